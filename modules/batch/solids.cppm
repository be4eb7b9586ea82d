// Many boxes or balls against one box or one ball: batch::intersects<Tier>(one, many, out) for one
// and many among aabb3 and sphere3 (the broad phase's and the culling's tests), and many oriented
// boxes against one box or one ball, for many as an array of shapes or as a structure-of-arrays packet
// (boxes_soa, spheres_soa, obbs_soa). out[i] is 1 where many[i] meets the closed box or ball
// `one`, else 0: the answer of the scalar intersects<Tier>(one, many[i]), bit for bit, in every
// tier (tests/batch/solids.cpp checks it on every SIMD target).
// Method (solids_simd.cpp): box against box by the scalar body's six comparisons, exact in every
// tier; a ball against a box or a ball by the sign of r r - |g|^2 (degree 2; Ericson, Real-Time
// Collision Detection, 2005, sections 4.3.1 and 5.2.5: g the centre's gap to the box or the other
// centre), in plain double for the approximate tier, and in the filtered tiers in the semi-static
// filter against a static bound per block of 64 lanes, then each lane's own bound, then the
// scalar query for a lane still open.
// Oriented boxes against a box (box_obbs_simd.cpp): the scalar query's 15 separating axes
// (Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5; degree 4), in plain double
// for the approximate tier and against the scalar's static bounds per axis family, taken over a
// block of 64 lanes, in the filtered tiers; a lane they leave open (touching or flat boxes) goes
// to the scalar query.
// Oriented boxes against a ball (ball_obbs_simd.cpp): the scalar query's first look
// (ball_obb::first_look: slabs along the coordinate axes and the box's axes, the box's centre in
// the ball, the box's point of the ball centre's clamped coordinates in the ball, a slab along
// the direction from that point to the centre; degrees 2 to 6), in plain double for the
// approximate tier and in the filtered tiers against each lane's own bound, the scalar's; a lane it
// leaves open goes to the scalar query.
module;
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
export module incidence.batch:solids;
import incidence.core;
import incidence.shapes;
import incidence.arith;
import incidence.detail;
import incidence.query;
import :lanes;

// The SIMD kernels (solids_simd.cpp). A box is six fields (min.x, min.y, min.z, max.x, max.y,
// max.z), a ball four (centre x, y, z, radius): for the one shape each field points at one value,
// for the many at an array of n. box_balls: `boxes` says which side is the many. The filter
// (filter = true) writes 2 where it could not prove the sign.
extern "C++" {
namespace incidence::batch::simd {
void box_boxes(const double* const* box, const double* const* boxes, std::size_t n, std::uint8_t* out);
void box_balls(const double* const* box, const double* const* ball, bool boxes, std::size_t n, bool filter, std::uint8_t* out);
void ball_balls(const double* const* ball, const double* const* balls, std::size_t n, bool filter, std::uint8_t* out);
// obbs: fifteen arrays of n (centre x, y, z, axis 0 x, y, z, axis 1, axis 2, half extents 0, 1,
// 2); gammas: the scalar filter's five (box_obb_gammas), or null for the approximate tier.
void box_obbs(const double* const* box, const double* const* obbs, std::size_t n, const double* gammas, std::uint8_t* out);
// ball: four values (centre, radius); gammas: the scalar filter's six (ball_obb_gammas), or null.
void ball_obbs(const double* const* ball, const double* const* obbs, std::size_t n, const double* gammas, std::uint8_t* out);
} // namespace incidence::batch::simd
}

export namespace incidence::batch {

// Boxes kept as structure of arrays: six arrays of one length, box i being
// {{min_x[i], min_y[i], min_z[i]}, {max_x[i], max_y[i], max_z[i]}}.
struct boxes_soa {
    std::span<const double> min_x, min_y, min_z, max_x, max_y, max_z;
    [[nodiscard]] constexpr std::size_t size() const { return min_x.size(); }
    [[nodiscard]] constexpr bool consistent() const {
        const std::size_t n = min_x.size();
        return min_y.size() == n && min_z.size() == n && max_x.size() == n && max_y.size() == n && max_z.size() == n;
    }
    [[nodiscard]] constexpr aabb3 operator[](std::size_t i) const {
        return {{min_x[i], min_y[i], min_z[i]}, {max_x[i], max_y[i], max_z[i]}};
    }
};
// Balls kept as structure of arrays: ball i has centre {x[i], y[i], z[i]} and radius radius[i].
struct spheres_soa {
    std::span<const double> x, y, z, radius;
    [[nodiscard]] constexpr std::size_t size() const { return x.size(); }
    [[nodiscard]] constexpr bool consistent() const { return y.size() == x.size() && z.size() == x.size() && radius.size() == x.size(); }
    [[nodiscard]] constexpr sphere3 operator[](std::size_t i) const { return {{x[i], y[i], z[i]}, radius[i]}; }
};
// Oriented boxes kept as structure of arrays: fifteen arrays of one length, box i having centre
// {cx[i], cy[i], cz[i]}, axes {ux[i], uy[i], uz[i]}, {vx[i], ...}, {wx[i], ...} and half extents
// {hu[i], hv[i], hw[i]} along them (read exactly as given, as obb3 reads them).
struct obbs_soa {
    std::span<const double> cx, cy, cz, ux, uy, uz, vx, vy, vz, wx, wy, wz, hu, hv, hw;
    [[nodiscard]] constexpr std::size_t size() const { return cx.size(); }
    [[nodiscard]] constexpr bool consistent() const {
        const std::size_t n = cx.size();
        for (const auto& a : {cy, cz, ux, uy, uz, vx, vy, vz, wx, wy, wz, hu, hv, hw})
            if (a.size() != n) return false;
        return true;
    }
    [[nodiscard]] constexpr obb3 operator[](std::size_t i) const {
        return {{cx[i], cy[i], cz[i]},
                {vec3{ux[i], uy[i], uz[i]}, vec3{vx[i], vy[i], vz[i]}, vec3{wx[i], wy[i], wz[i]}},
                {hu[i], hv[i], hw[i]}};
    }
};

} // namespace incidence::batch

namespace incidence::batch::detail {

inline void arrays(const boxes_soa& b, const double** p) {
    const double* v[6] = {b.min_x.data(), b.min_y.data(), b.min_z.data(), b.max_x.data(), b.max_y.data(), b.max_z.data()};
    for (int k = 0; k < 6; ++k) p[k] = v[k];
}
inline void arrays(const spheres_soa& s, const double** p) {
    const double* v[4] = {s.x.data(), s.y.data(), s.z.data(), s.radius.data()};
    for (int k = 0; k < 4; ++k) p[k] = v[k];
}
inline void arrays(const obbs_soa& b, const double** p) {
    const double* v[15] = {b.cx.data(), b.cy.data(), b.cz.data(), b.ux.data(), b.uy.data(), b.uz.data(), b.vx.data(), b.vy.data(),
                           b.vz.data(), b.wx.data(), b.wy.data(), b.wz.data(), b.hu.data(), b.hv.data(), b.hw.data()};
    for (int k = 0; k < 15; ++k) p[k] = v[k];
}

// The scalar filter's gamma for each of sat::box_box_pass's five sign families (by
// sat::box_axis_kind), read off its own value types, so that the kernel's static bounds are the
// scalar's bounds for the same magnitudes.
inline constexpr std::array<double, 5> box_obb_gammas = [] {
    namespace sat = incidence::detail::sat;
    std::array<double, 5> g{};
    const sat::zonotope a = sat::zonotope_of(aabb3{{0, 0, 0}, {1, 1, 1}});
    const obb3 b{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    (void)sat::box_box_pass(arith::lift_filter{}, a, b, [&]<int N>(const arith::filtered<N>&, sat::box_axis_kind kind) {
        g[kind] = arith::error_bound(arith::filtered<N>{0.0, 1.0});
        return -1; // every axis and both determinants visited
    });
    return g;
}();

// The scalar filter's gamma for ball_obb::first_look's six values (the coordinate slabs, the box's
// centre in the ball, the box-axis slabs, the box's clamped point in the ball, the gap along the
// direction from that point to c and its square against the radius's), read off the expressions'
// own operation counts.
inline constexpr std::array<double, 6> ball_obb_gammas = [] {
    namespace ball_obb = incidence::detail::ball_obb;
    const ball_obb::frame f{{0, 0, 0}, {0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}, 1};
    const arith::lift_filter l{};
    auto gamma = []<int N>(const arith::filtered<N>&) { return arith::error_bound(arith::filtered<N>{0.0, 1.0}); };
    const vec3 d{1, 1, 1};
    return std::array<double, 6>{gamma(ball_obb::look_coordinate(l, f, 0)), gamma(ball_obb::look_centre(l, f)),
                                 gamma(ball_obb::look_box_axis(l, f, 0)),   gamma(ball_obb::look_clamped(l, f, {1, 1, 1})),
                                 gamma(ball_obb::look_apart_gap(l, f, d)),  gamma(ball_obb::look_apart(l, f, d))};
}();

// n lanes of `Many` (its fields' arrays) against `one`: the kernel of the tier, then the scalar
// query where the filter left a lane open. The number of lanes met.
template <tier Tier, class One, class Many, class At>
std::size_t solids_block(const One& one, const double* const* many, std::size_t n, std::uint8_t* out, const At& at) {
    const one_fields<One> fields(one);
    constexpr bool filter = !std::is_same_v<Tier, approximate>;
    if constexpr (std::is_same_v<One, aabb3> && std::is_same_v<Many, aabb3>) simd::box_boxes(fields.p, many, n, out);
    else if constexpr (std::is_same_v<One, aabb3> && std::is_same_v<Many, obb3>)
        simd::box_obbs(fields.p, many, n, filter ? box_obb_gammas.data() : nullptr, out);
    else if constexpr (std::is_same_v<Many, obb3>) simd::ball_obbs(fields.p, many, n, filter ? ball_obb_gammas.data() : nullptr, out);
    else if constexpr (std::is_same_v<One, aabb3>) simd::box_balls(fields.p, many, false, n, filter, out);
    else if constexpr (std::is_same_v<Many, aabb3>) simd::box_balls(many, fields.p, true, n, filter, out);
    else simd::ball_balls(fields.p, many, n, filter, out);
    return settle_open(out, n, [&](std::size_t i) { return incidence::intersects<Tier>(one, at(i)); });
}

template <tier Tier, class One, class Many>
result<std::size_t> solids(const One& one, std::span<const Many> many, std::span<std::uint8_t> out) {
    if (out.size() != many.size()) return error{errc::size_mismatch};
    if constexpr (std::is_same_v<One, aabb3> && std::is_same_v<Many, aabb3>) {
        // six comparisons read in place: transposing an array of boxes into lanes measured slower
        // than the comparisons themselves (bench/NOTES.md, "Batches"); the packet entry runs in lanes
        std::size_t met = 0;
        for (std::size_t i = 0; i < many.size(); ++i) met += out[i] = incidence::intersects<Tier>(one, many[i]) ? 1 : 0;
        return met;
    }
    return by_blocks<fields_of<Many>>(
        many, out.data(), [](const Many& s, double* f) { unpack(s, f); },
        [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return solids_block<Tier, One, Many>(one, coords, n, o, [&](std::size_t i) { return many[start + i]; });
        });
}
template <tier Tier, class One, class Soa>
result<std::size_t> solids(const One& one, const Soa& many, std::span<std::uint8_t> out) {
    if (!many.consistent() || out.size() != many.size()) return error{errc::size_mismatch};
    const double* p[15] = {};
    arrays(many, p);
    using Many = std::remove_cvref_t<decltype(many[0])>;
    return solids_block<Tier, One, Many>(one, p, many.size(), out.data(), [&](std::size_t i) { return many[i]; });
}

} // namespace incidence::batch::detail

export namespace incidence::batch {

// Does each box (or ball) of `many` meet `one`? out[i] for many[i] (out as long as many); the
// number met. Tiers as the scalar intersects: the same answer, lane by lane.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const aabb3& one, std::span<const aabb3> many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const aabb3& one, std::span<const sphere3> many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const sphere3& one, std::span<const aabb3> many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const sphere3& one, std::span<const sphere3> many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const aabb3& one, std::span<const obb3> many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const sphere3& one, std::span<const obb3> many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const aabb3& one, const boxes_soa& many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const aabb3& one, const spheres_soa& many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const aabb3& one, const obbs_soa& many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const sphere3& one, const boxes_soa& many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const sphere3& one, const spheres_soa& many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const sphere3& one, const obbs_soa& many, std::span<std::uint8_t> out) {
    return detail::solids<Tier>(one, many, out);
}

} // namespace incidence::batch
