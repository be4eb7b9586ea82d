// Rays against boxes and balls: one ray against many, batch::intersects<Tier>(ray, boxes or balls,
// out), and many rays against one, batch::intersects<Tier>(rays, box or ball, out) (the
// bounding-volume hierarchy's node test for a packet of rays), each many as an array or a
// structure-of-arrays packet (boxes_soa, spheres_soa, rays_soa). out[i] is 1 where the pair i
// meets, else 0: the answer of the scalar intersects<Tier>(ray, box or ball), bit for bit, in every
// tier (tests/batch/ray_solids.cpp checks it on every SIMD target).
// Method (ray_solids_simd.cpp): the approximate tier runs the scalar approximate method in lanes
// (the slab method, Kay and Kajiya, SIGGRAPH 1986; the geometric ray-sphere method, Real-Time
// Rendering 4th ed., section 22.6.2); the filtered tiers run the scalar filter's first stage in
// lanes (the box: the slab parameters with their proven error; the ball: its three signs, degree 2
// to 4, against a block's static bound and the lanes' own) and ask the scalar query of the tier
// for a lane it leaves open.
// And the first hit of one ray among many boxes or balls: batch::intersection<Tier>(ray, many), the
// hit with the least entry parameter, ties to the least index (solid_hit below).
module;
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
export module incidence.batch:ray_solids;
import incidence.core;
import incidence.shapes;
import incidence.arith;
import incidence.query;
import incidence.scene;
import :lanes;
import :ray_triangles;
import :solids;

// The SIMD kernels (ray_solids_simd.cpp). ray: six fields (origin x, y, z, direction x, y, z), box
// six, ball four; `rays` true: the ray's fields are arrays of n and the solid's one value each,
// false: the other way. filter = false: the approximate tier (1 or 0); true: the filter's first
// stage, 2 where it leaves the lane to the scalar query.
extern "C++" {
namespace incidence::batch::simd {
void ray_boxes(const double* const* ray, bool rays, const double* const* box, std::size_t n, bool filter, std::uint8_t* out);
void ray_balls(const double* const* ray, bool rays, const double* const* ball, std::size_t n, bool filter, std::uint8_t* out);
} // namespace incidence::batch::simd
}

namespace incidence::batch::detail {

inline void arrays(const rays_soa& r, const double** p) {
    const double* v[6] = {r.ox.data(), r.oy.data(), r.oz.data(), r.dx.data(), r.dy.data(), r.dz.data()};
    for (int k = 0; k < 6; ++k) p[k] = v[k];
}

// n lanes: the kernel of the tier on the ray's fields and the solid's (one side arrays of n, the
// other one value each), then the scalar query where the filter left a lane open.
template <tier Tier, class Solid, class At>
std::size_t ray_solid_block(const double* const* ray, bool rays, const double* const* solid, std::size_t n, std::uint8_t* out,
                            const At& pair) {
    constexpr bool filter = !std::is_same_v<Tier, approximate>;
    if constexpr (std::is_same_v<Solid, aabb3>) simd::ray_boxes(ray, rays, solid, n, filter, out);
    else simd::ray_balls(ray, rays, solid, n, filter, out);
    return settle_open(out, n, [&](std::size_t i) {
        const auto [r, s] = pair(i);
        return incidence::intersects<Tier>(r, s);
    });
}
template <tier Tier, class Solid>
result<std::size_t> ray_many(const ray3& r, std::span<const Solid> many, std::span<std::uint8_t> out) {
    if (out.size() != many.size()) return error{errc::size_mismatch};
    const one_fields<ray3> ray(r);
    return by_blocks<fields_of<Solid>>(
        many, out.data(), [](const Solid& s, double* f) { unpack(s, f); },
        [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return ray_solid_block<Tier, Solid>(ray.p, false, coords, n, o, [&](std::size_t i) { return std::pair{r, many[start + i]}; });
        });
}
template <tier Tier, class Soa>
result<std::size_t> ray_many(const ray3& r, const Soa& many, std::span<std::uint8_t> out) {
    if (!many.consistent() || out.size() != many.size()) return error{errc::size_mismatch};
    using Solid = std::remove_cvref_t<decltype(many[0])>;
    const one_fields<ray3> ray(r);
    const double* p[6] = {};
    arrays(many, p);
    return ray_solid_block<Tier, Solid>(ray.p, false, p, many.size(), out.data(), [&](std::size_t i) { return std::pair{r, many[i]}; });
}
template <tier Tier, class Solid>
result<std::size_t> many_rays(std::span<const ray3> rays, const Solid& s, std::span<std::uint8_t> out) {
    if (out.size() != rays.size()) return error{errc::size_mismatch};
    const one_fields<Solid> solid(s);
    return by_blocks<6>(
        rays, out.data(), [](const ray3& r, double* f) { unpack(r, f); },
        [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return ray_solid_block<Tier, Solid>(coords, true, solid.p, n, o, [&](std::size_t i) { return std::pair{rays[start + i], s}; });
        });
}
template <tier Tier, class Solid>
result<std::size_t> many_rays(const rays_soa& rays, const Solid& s, std::span<std::uint8_t> out) {
    if (!rays.consistent() || out.size() != rays.size()) return error{errc::size_mismatch};
    const one_fields<Solid> solid(s);
    const double* p[6] = {};
    arrays(rays, p);
    return ray_solid_block<Tier, Solid>(p, true, solid.p, rays.size(), out.data(), [&](std::size_t i) { return std::pair{rays[i], s}; });
}

} // namespace incidence::batch::detail

export namespace incidence::batch {

// The first contact of a ray with one of many boxes or balls: that shape's span_hit (entry and exit
// parameters, the point at entry; t_enter = 0 where the ray starts inside) and its index.
template <class V = double>
struct solid_hit {
    V t_enter;
    V t_exit;
    point_of<V> point;
    std::size_t index;
    certainty exists = certainty::yes;
};

} // namespace incidence::batch

namespace incidence::batch::detail {

// sign(t_enter(r, a) - t_enter(r, b)), exactly, for two boxes the ray meets. The entry is
// max(0, (near_k - o_k) / d_k over the axes with d_k != 0), near_k the slab's bound the ray comes
// from (the slab method, Kay and Kajiya, SIGGRAPH 1986): each candidate is a ratio of a difference
// of inputs and an input, compared by the sign of a cross product (degree 2).
struct slab_entry {
    double near, o, d; // (near - o) / d; 0 is {0, 0, 1}
};
[[nodiscard]] inline sign compare_entries(const slab_entry& x, const slab_entry& y) {
    arith::exact_kernel k;
    const sign s = k.sgn([=](auto L) { return (L(x.near) - L(x.o)) * L(y.d) - (L(y.near) - L(y.o)) * L(x.d); });
    return (x.d < 0) != (y.d < 0) ? -s : s;
}
[[nodiscard]] inline slab_entry box_entry(const ray3& r, const aabb3& b) {
    const double o[3] = {r.origin.x, r.origin.y, r.origin.z}, d[3] = {r.direction.x, r.direction.y, r.direction.z};
    const double lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
    slab_entry best{0, 0, 1};
    for (int k = 0; k < 3; ++k)
        if (d[k] != 0)
            if (const slab_entry e{d[k] > 0 ? lo[k] : hi[k], o[k], d[k]}; compare_entries(e, best) == sign::positive) best = e;
    return best;
}
[[nodiscard]] inline sign compare_first(const ray3& r, const aabb3& a, const aabb3& b) {
    return compare_entries(box_entry(r, a), box_entry(r, b));
}

// The same for two balls the ray meets. o + t d is in the ball at t where f(t) = a t^2 + 2 b t + c
// <= 0 (a = d . d, b = m . d, c = m . m - r^2, m = o - centre); the entry is max(0, t1), t1 the
// smaller root, and t1 > 0 exactly where c > 0 and b < 0. Both positive: the two quadratics share a,
// so f1(t2) = f1(t2) - f2(t2) = 2 (b1 - b2) t2 + (c1 - c2), whose sign is that of b1 - b2 times
// sign(t2 - y), y = (c2 - c1) / (2 (b1 - b2)), and the vertex test a t2 + b1 is a (t2 - (-b1 / a)):
// both are t2 against a rational (arith::exact_root_side, degree 6), and with them
// arith::root_side places t1 against t2.
[[nodiscard]] inline sign compare_first(const ray3& r, const sphere3& s1, const sphere3& s2) {
    arith::exact_kernel k;
    auto quadratic_of = [&](const sphere3& s) {
        return [o = r.origin, d = r.direction, c = s.center, rad = s.radius](auto L) {
            const auto m = arith::lift(L, o) - arith::lift(L, c);
            const auto D = arith::lift(L, d);
            return arith::quadratic{arith::dot(D, D), arith::dot(m, D), arith::dot(m, m) - L(rad) * L(rad)};
        };
    };
    const auto f1 = quadratic_of(s1), f2 = quadratic_of(s2);
    auto enters_later = [&](const auto& f) {
        return k.sgn([=](auto L) { return f(L).c; }) == sign::positive && k.sgn([=](auto L) { return f(L).b; }) == sign::negative;
    };
    const bool later1 = enters_later(f1), later2 = enters_later(f2);
    if (!later1 || !later2) return later1 ? sign::positive : later2 ? sign::negative : sign::zero;
    const sign db = k.sgn([=](auto L) { return f1(L).b - f2(L).b; });
    sign f_at = k.sgn([=](auto L) { return f1(L).c - f2(L).c; }); // b1 = b2: f1 - f2 is the constant c1 - c2
    if (db != sign::zero) {
        const bool up = db == sign::positive; // y = p / q with q > 0
        const sign side = arith::exact_root_side(
            f2, arith::root::smaller,
            [=](auto L) {
                const auto e1 = f1(L), e2 = f2(L);
                return up ? e2.c - e1.c : e1.c - e2.c;
            },
            [=](auto L) {
                const auto e1 = f1(L), e2 = f2(L);
                return up ? (e1.b - e2.b) + (e1.b - e2.b) : (e2.b - e1.b) + (e2.b - e1.b);
            });
        f_at = db * side;
    }
    const sign v_at =
        arith::exact_root_side(f2, arith::root::smaller, [=](auto L) { return L(0.0) - f1(L).b; }, [=](auto L) { return f1(L).a; });
    return *arith::root_side(arith::root::smaller, f_at, v_at);
}

// A block of many (an array's part or a packet's part) from `start`, `n` long.
template <class Solid>
std::span<const Solid> part(std::span<const Solid> many, std::size_t start, std::size_t n) {
    return many.subspan(start, n);
}
inline boxes_soa part(const boxes_soa& b, std::size_t start, std::size_t n) {
    return {b.min_x.subspan(start, n), b.min_y.subspan(start, n), b.min_z.subspan(start, n),
            b.max_x.subspan(start, n), b.max_y.subspan(start, n), b.max_z.subspan(start, n)};
}
inline spheres_soa part(const spheres_soa& s, std::size_t start, std::size_t n) {
    return {s.x.subspan(start, n), s.y.subspan(start, n), s.z.subspan(start, n), s.radius.subspan(start, n)};
}

// The first hit: the batch's exact answers say which shapes the ray meets (approximate: its plain
// double answers), 64 at a time; each hit's entry is enclosed by the conservative tier's values,
// a hit whose enclosure lies wholly beyond the best one's is passed over, one wholly before it
// replaces it, and overlapping enclosures are ordered exactly (compare_first). Scanning in index
// order and replacing only on "strictly before" leaves ties to the least index. The values are then
// the chosen shape's scalar intersection in the tier: exact correctly rounded; conservative and
// aggressive the conservative enclosures (every comparison was exact, so exists is yes);
// approximate the least plain-double entry among its plain-double hits (exists uncertain).
template <tier Tier, class Many>
result<std::optional<solid_hit<scene_value_t<Tier>>>> first_solid(const ray3& r, const Many& many) {
    using Solid = std::remove_cvref_t<decltype(many[0])>;
    using V = scene_value_t<Tier>;
    constexpr bool plain = std::is_same_v<Tier, approximate>;
    using Hit = std::conditional_t<plain, span_hit<double>, span_hit<interval>>;
    std::optional<Hit> best;
    std::size_t best_index = 0;
    std::uint8_t met[block];
    for (std::size_t start = 0; start < many.size(); start += block) {
        const std::size_t n = many.size() - start < block ? many.size() - start : block;
        const auto hits = ray_many<std::conditional_t<plain, approximate, exact>>(r, part(many, start, n), std::span<std::uint8_t>(met, n));
        if (!hits) return hits.error();
        if (hits.value() == 0) continue;
        for (std::size_t i = 0; i < n; ++i) {
            if (met[i] == 0) continue;
            const Solid s = many[start + i];
            const auto h = incidence::intersection<std::conditional_t<plain, approximate, conservative>>(r, s);
            if (!h) continue; // approximate only: its values' method may disagree with its yes/no
            bool before = !best;
            if (!before) {
                if constexpr (plain) before = h->t_enter < best->t_enter;
                else if (h->t_enter.hi < best->t_enter.lo) before = true;
                else if (h->t_enter.lo <= best->t_enter.hi) before = compare_first(r, s, many[best_index]) == sign::negative;
            }
            if (before) best = *h, best_index = start + i;
        }
    }
    if (!best) return std::optional<solid_hit<V>>{};
    if constexpr (plain) {
        return std::optional<solid_hit<V>>{solid_hit<V>{best->t_enter, best->t_exit, best->point, best_index, certainty::uncertain}};
    } else if constexpr (std::is_same_v<Tier, exact>) {
        const auto h = incidence::intersection<exact>(r, many[best_index]);
        return std::optional<solid_hit<V>>{solid_hit<V>{h->t_enter, h->t_exit, h->point, best_index, certainty::yes}};
    } else {
        return std::optional<solid_hit<V>>{solid_hit<V>{best->t_enter, best->t_exit, best->point, best_index, certainty::yes}};
    }
}

} // namespace incidence::batch::detail

export namespace incidence::batch {

// Does the ray meet each box (ball)? out[i] for many[i] (out as long as many); the number met.
// Tiers as the scalar intersects(ray, box or ball): the same answer, lane by lane.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, std::span<const aabb3> boxes, std::span<std::uint8_t> out) {
    return detail::ray_many<Tier>(r, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, const boxes_soa& boxes, std::span<std::uint8_t> out) {
    return detail::ray_many<Tier>(r, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, std::span<const sphere3> balls, std::span<std::uint8_t> out) {
    return detail::ray_many<Tier>(r, balls, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, const spheres_soa& balls, std::span<std::uint8_t> out) {
    return detail::ray_many<Tier>(r, balls, out);
}
// The first hit of the ray among the boxes (balls): the least entry parameter, ties to the least
// index, with that shape's values as intersection<Tier>(ray, shape) gives them (exact correctly
// rounded; conservative and aggressive enclosures, exists yes; approximate plain double, exists
// uncertain) and its index; nothing when the ray meets none.
template <tier Tier = exact>
[[nodiscard]] result<std::optional<solid_hit<scene_value_t<Tier>>>> intersection(const ray3& r, std::span<const aabb3> boxes) {
    return detail::first_solid<Tier>(r, boxes);
}
template <tier Tier = exact>
[[nodiscard]] result<std::optional<solid_hit<scene_value_t<Tier>>>> intersection(const ray3& r, const boxes_soa& boxes) {
    if (!boxes.consistent()) return error{errc::size_mismatch};
    return detail::first_solid<Tier>(r, boxes);
}
template <tier Tier = exact>
[[nodiscard]] result<std::optional<solid_hit<scene_value_t<Tier>>>> intersection(const ray3& r, std::span<const sphere3> balls) {
    return detail::first_solid<Tier>(r, balls);
}
template <tier Tier = exact>
[[nodiscard]] result<std::optional<solid_hit<scene_value_t<Tier>>>> intersection(const ray3& r, const spheres_soa& balls) {
    if (!balls.consistent()) return error{errc::size_mismatch};
    return detail::first_solid<Tier>(r, balls);
}
// Does each ray meet the box (ball)? out[i] for rays[i]; the number of rays that meet it.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(std::span<const ray3> rays, const aabb3& b, std::span<std::uint8_t> out) {
    return detail::many_rays<Tier>(rays, b, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const rays_soa& rays, const aabb3& b, std::span<std::uint8_t> out) {
    return detail::many_rays<Tier>(rays, b, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(std::span<const ray3> rays, const sphere3& s, std::span<std::uint8_t> out) {
    return detail::many_rays<Tier>(rays, s, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const rays_soa& rays, const sphere3& s, std::span<std::uint8_t> out) {
    return detail::many_rays<Tier>(rays, s, out);
}

} // namespace incidence::batch
