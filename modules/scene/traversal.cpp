// The traversals of a scene3: a line, a ray or a segment against it (linear_scene.cppm), a solid
// against it and every triangle a shape meets (solid_scene.cppm), a scene against a scene
// (scene_scene.cppm); see those for the semantics, the methods and their sources.
module;
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>
module incidence.scene;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.query;
import incidence.detail;

namespace incidence::detail {

namespace {

// The filter's signs; a sign it cannot prove is decided at once by the exact stages
// (filter_kernel::decided_sgn) instead of failing the pass. A traversal visits many triangles, and
// one open sign would otherwise send the whole traversal to the exact kernel.
struct deciding_kernel : arith::filter_kernel {
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign sgn(const F& f) {
        return decided_sgn(f);
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr bool zero(const F& f) {
        return decided_sgn(f) == sign::zero;
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign settled_sgn(const F& f) {
        return decided_sgn(f);
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign structural_sgn(const F& f) {
        return decided_sgn(f);
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr bool structural_zero(const F& f) {
        return decided_sgn(f) == sign::zero;
    }
};

constexpr double inf = __builtin_huge_val();
constexpr double moderate_limit = 0x1p400, small_direction = 0x1p-400;

double coordinate(point3 p, int i) { return i == 0 ? p.x : (i == 1 ? p.y : p.z); }

// The slab test of a linear object against node boxes, never missing a box the object meets.
template <class S>
class node_slabs {
public:
    static constexpr double missed = inf; // entry()'s answer for a box the object surely misses

    node_slabs(const S& x, const linear3& s, const scene3& scene) : x_(x) {
        const vec3 d = s.kind == extent::segment ? s.q - s.o : s.d;
        const double dv[3] = {d.x, d.y, d.z};
        lo_ = s.kind == extent::line ? -inf : 0.0;
        hi_ = s.kind == extent::segment ? 1.0 : inf;
        fast_ = scene.moderate();
        for (int i = 0; i < 3; ++i) {
            o_[i] = coordinate(s.o, i);
            const double m = std::fabs(dv[i]);
            if (!(std::fabs(o_[i]) <= moderate_limit) || !(std::fabs(coordinate(s.q, i)) <= moderate_limit)) fast_ = false;
            if (m != 0.0 && !(m >= small_direction && m <= moderate_limit)) fast_ = false;
            inv_[i] = 1.0 / dv[i]; // +-infinity for a zero component
            negative_[i] = std::signbit(dv[i]);
        }
    }
    // Whether the widened slab test applies (every coordinate within 2^400, directions in range).
    [[nodiscard]] bool fast() const { return fast_; }
    // A lower bound of the parameter where the object enters the box, at most `limit`; `missed`
    // where it surely does not meet the box up to `limit`.
    template <bool Fast>
    [[nodiscard, gnu::always_inline]] double entry(const aabb3& b, double limit) const {
        if constexpr (!Fast) {
            return incidence::intersects<conservative>(x_, b) ? lo_ : missed;
        } else {
            // Per axis the slab's parameters (bound - o) / d as (bound - o) (1 / d); a zero direction
            // gives 1 / d = +-infinity, so a slab the origin lies outside gives an empty range, one it
            // lies inside an unbounded one, and one it lies on NaN, which max and min below ignore.
            // Then the widening, once: the largest entry's and the least exit's own error bounds.
            double lo = lo_, hi = std::min(hi_, limit);
            const double bmin[3] = {b.min.x, b.min.y, b.min.z}, bmax[3] = {b.max.x, b.max.y, b.max.z};
            for (int i = 0; i < 3; ++i) {
                const double a = ((negative_[i] ? bmax[i] : bmin[i]) - o_[i]) * inv_[i];
                const double c = ((negative_[i] ? bmin[i] : bmax[i]) - o_[i]) * inv_[i];
                lo = std::max(lo, a);
                hi = std::min(hi, c);
            }
            lo -= std::fabs(lo) * 0x1p-49 + 0x1p-1070;
            hi += std::fabs(hi) * 0x1p-49 + 0x1p-1070;
            return lo <= hi ? lo : missed;
        }
    }

private:
    const S& x_;
    double o_[3], inv_[3];
    bool negative_[3];
    double lo_, hi_;
    bool fast_;
};

// Visits the leaves' triangles the object may meet, depth first, the child it enters first first;
// visit(i) returns false to stop; limit() bounds the parameters still of interest.
template <bool Fast, class S, class Visit, class Limit>
void traverse_with(const scene3& scene, const node_slabs<S>& sl, Visit&& visit, Limit&& limit) {
    const auto nodes = scene.nodes();
    struct pending {
        std::uint32_t node;
        double entry;
    };
    pending stack[2 * scene3::max_depth + 4];
    int top = 0;
    constexpr double missed = node_slabs<S>::missed;
    if (const double t = sl.template entry<Fast>(nodes[0].box, limit()); t != missed) stack[top++] = {0, t};
    while (top > 0) {
        const pending p = stack[--top];
        if (p.entry > limit()) continue; // begins beyond what is still of interest
        const scene3::node& n = nodes[p.node];
        if (n.leaf()) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
                if (!visit(i)) return;
            continue;
        }
        const double l = limit();
        const double ta = sl.template entry<Fast>(nodes[n.first].box, l), tb = sl.template entry<Fast>(nodes[n.first + 1].box, l);
        const bool a = ta != missed, b = tb != missed;
        if (a && b) {
            const bool a_first = ta <= tb;
            stack[top++] = a_first ? pending{n.first + 1, tb} : pending{n.first, ta};
            stack[top++] = a_first ? pending{n.first, ta} : pending{n.first + 1, tb};
        } else if (a) {
            stack[top++] = {n.first, ta};
        } else if (b) {
            stack[top++] = {n.first + 1, tb};
        }
    }
}
template <class S, class Visit, class Limit>
void traverse(const scene3& scene, const node_slabs<S>& sl, Visit&& visit, Limit&& limit) {
    if (sl.fast()) traverse_with<true>(scene, sl, visit, limit);
    else traverse_with<false>(scene, sl, visit, limit);
}

// An upper bound of an end's parameter (infinity where its enclosure is not finite).
double upper_bound(const contact_end& e, const linear3& s) {
    if (e.kind == end_kind::domain) return e.bound;
    const double hi = with_ratio(e, s, [](const auto& t) { return arith::enclosed_value(t); }).hi;
    return hi == hi ? hi : inf;
}

// The search for the first contact in kernel K: consider(source, t) weighs triangle t (its
// caller's index `source`); the least end wins, ties to the least source index.
template <class K>
struct contact_search {
    K& k;
    linear3 s;
    aabb3 xb;
    std::optional<contact_end> first{};
    std::size_t best = 0;
    triangle3 best_triangle{};
    double limit = inf; // an upper bound of the best end's parameter
    void consider(std::size_t source, const triangle3& t) {
        if (!boxes_meet(xb, bounds(t))) return; // the scalar pair's first step (comparisons)
        if (const auto r = triangle_span(k, s, t)) {
            const sign c = first ? compare_ends(k, r->enter, *first, s) : sign::negative;
            if (c == sign::negative || (c == sign::zero && source < best)) {
                first = r->enter;
                best = source;
                best_triangle = t;
                limit = upper_bound(*first, s);
            }
        }
    }
    [[nodiscard]] std::optional<scene_hit<arith::value_t<K>>> hit() const {
        if (!first) return std::nullopt;
        const auto h = triangle_values(k, *first, s, best_triangle);
        return scene_hit<arith::value_t<K>>{h.t, h.point, h.normal, h.u, h.v, h.w, best};
    }
};

// The first contact in kernel K over the scene's triangles, through the hierarchy.
template <class K, class S>
std::optional<scene_hit<arith::value_t<K>>> first_contact(K& k, const S& x, const scene3& scene) {
    const linear3 s = as_linear(x);
    const node_slabs<S> sl(x, s, scene);
    const auto triangles = scene.triangles();
    contact_search<K> search{k, s, bounds(x)};
    traverse(
        scene, sl,
        [&](std::uint32_t i) {
            search.consider(scene.source(i), triangles[i]);
            return true;
        },
        [&] { return search.limit; });
    return search.hit();
}

// A first hit in each tier's contract, from contact(k): the search in kernel k.
//   approximate   plain double, exists uncertain;
//   exact, conservative, aggressive: the filter with the exact sign in place where it cannot
//                 decide (deciding_kernel; exact values correctly rounded); were a sign left open
//                 (not reached for finite inputs): the exact kernel, the conservative tier's
//                 enclosing uncertain hit over the object's range, the aggressive tier's none.
template <class Tier, class S, class Contact>
std::optional<scene_hit<scene_value_t<Tier>>> first_hit_in_tier(const S& x, const Contact& contact) {
    if constexpr (std::is_same_v<Tier, approximate>) {
        arith::approx_kernel k;
        auto h = contact(k);
        if (h) h->exists = certainty::uncertain;
        return h;
    } else {
        std::conditional_t<std::is_same_v<Tier, exact>, arith::rounding_kernel<deciding_kernel>, deciding_kernel> k;
        const auto h = contact(k);
        if (!k.failed()) return h;
        if constexpr (std::is_same_v<Tier, exact>) {
            arith::exact_kernel e;
            const auto he = contact(e);
            return e.valid ? he : std::nullopt;
        } else if constexpr (std::is_same_v<Tier, conservative>) {
            constexpr interval unit{0.0, 1.0};
            return scene_hit<interval>{range_of(as_linear(x)),       everywhere,          everywhere, unit, unit, unit,
                                       static_cast<std::size_t>(-1), certainty::uncertain};
        } else {
            return std::nullopt;
        }
    }
}

} // namespace

template <class Tier, class S>
bool scene_any_hit(const S& x, const scene3& scene) {
    if (scene.empty() || !finite(x)) return false;
    const node_slabs<S> sl(x, as_linear(x), scene);
    const auto triangles = scene.triangles();
    bool met = false;
    traverse(
        scene, sl,
        [&](std::uint32_t i) {
            met = incidence::intersects<Tier>(x, triangles[i]);
            return !met;
        },
        [] { return inf; });
    return met;
}

template <class Tier, class S>
std::optional<scene_hit<scene_value_t<Tier>>> scene_first_hit(const S& x, const scene3& scene) {
    if (scene.empty() || !finite(x)) return std::nullopt;
    return first_hit_in_tier<Tier>(x, [&](auto& k) { return first_contact(k, x, scene); });
}

template <class Tier>
std::optional<scene_hit<scene_value_t<Tier>>> triangles_first_hit(const ray3& r, std::size_t count, candidates_fn fill,
                                                                  const void* context) {
    if (count == 0 || !finite(r)) return std::nullopt;
    return first_hit_in_tier<Tier>(r, [&](auto& k) {
        contact_search<std::remove_reference_t<decltype(k)>> search{k, as_linear(r), bounds(r)};
        std::uint8_t candidate[candidate_block];
        triangle3 block[candidate_block];
        for (std::size_t start = 0; start < count; start += candidate_block) {
            const std::size_t n = count - start < candidate_block ? count - start : candidate_block;
            fill(context, start, n, candidate, block);
            for (std::size_t i = 0; i < n; ++i)
                if (candidate[i] != 0) search.consider(start + i, block[i]);
        }
        return search.hit();
    });
}

namespace {

// s's box: exact for the shapes with vertices, rounded outward for the oriented box.
aabb3 box_around(const aabb3& b) { return b; }
aabb3 box_around(const triangle3& t) { return bounds(t); }
aabb3 box_around(const tetrahedron3& t) { return bounds(t); }
aabb3 box_around(const obb3& s) {
    const interval3 r = reach_of(s);
    return {{r.x.lo, r.y.lo, r.z.lo}, {r.x.hi, r.y.hi, r.z.hi}};
}

template <class S>
bool finite_shape(const S& s) {
    if constexpr (std::is_same_v<S, aabb3>) return finite(s.min) && finite(s.max);
    else if constexpr (std::is_same_v<S, obb3>)
        return finite(s.center) && finite(s.axes[0]) && finite(s.axes[1]) && finite(s.axes[2]) && finite(s.half_extents[0]) &&
               finite(s.half_extents[1]) && finite(s.half_extents[2]);
    else if constexpr (std::is_same_v<S, frustum3>) {
        for (const plane3& p : s.planes)
            if (!finite(p.normal) || !finite(p.offset)) return false;
        return true;
    } else return finite(s);
}

// Visits the triangles of the leaves whose boxes may meet s (by its box, or for a frustum by the
// frustum-box pair's conservative tier); visit(i) returns false to stop.
template <class S, class Visit>
void overlapping(const scene3& scene, const S& s, Visit&& visit) {
    aabb3 box{};
    if constexpr (!std::is_same_v<S, frustum3>) box = box_around(s);
    auto may_meet = [&](const aabb3& b) {
        if constexpr (std::is_same_v<S, frustum3>) return incidence::intersects<conservative>(s, b);
        else return boxes_meet(b, box);
    };
    const auto nodes = scene.nodes();
    std::uint32_t stack[2 * scene3::max_depth + 4];
    int top = 0;
    if (may_meet(nodes[0].box)) stack[top++] = 0;
    while (top > 0) {
        const scene3::node& n = nodes[stack[--top]];
        if (n.leaf()) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
                if (!visit(i)) return;
            continue;
        }
        if (may_meet(nodes[n.first + 1].box)) stack[top++] = n.first + 1;
        if (may_meet(nodes[n.first].box)) stack[top++] = n.first;
    }
}

} // namespace

template <class Tier, class S>
bool scene_solid_any(const S& s, const scene3& scene) {
    if (scene.empty() || !finite_shape(s)) return false;
    const auto triangles = scene.triangles();
    bool met = false;
    overlapping(scene, s, [&](std::uint32_t i) {
        met = incidence::intersects<Tier>(s, triangles[i]);
        return !met;
    });
    return met;
}

template <class Tier, class S>
std::size_t scene_every_hit(const S& s, const scene3& scene, std::vector<std::size_t>& out) {
    if (scene.empty() || !finite_shape(s)) return 0;
    const auto triangles = scene.triangles();
    std::size_t met = 0;
    auto visit = [&](std::uint32_t i) {
        if (incidence::intersects<Tier>(s, triangles[i])) out.push_back(scene.source(i)), ++met;
        return true;
    };
    if constexpr (scene_linear<S>) {
        const node_slabs<S> sl(s, as_linear(s), scene);
        traverse(scene, sl, visit, [] { return inf; });
    } else {
        overlapping(scene, s, visit);
    }
    return met;
}

// Every pair of triangles whose leaves' boxes meet: out == nullptr stops at the first pair met.
template <class Tier>
bool scene_pairs(const scene3& a, const scene3& b, std::vector<std::pair<std::size_t, std::size_t>>* out, std::size_t& met) {
    met = 0;
    if (a.empty() || b.empty()) return false;
    const auto na = a.nodes(), nb = b.nodes();
    const auto ta = a.triangles(), tb = b.triangles();
    auto size = [](const aabb3& x) { return (x.max.x / 2 - x.min.x / 2) + (x.max.y / 2 - x.min.y / 2) + (x.max.z / 2 - x.min.z / 2); };
    std::pair<std::uint32_t, std::uint32_t> stack[4 * scene3::max_depth + 8];
    int top = 0;
    if (boxes_meet(na[0].box, nb[0].box)) stack[top++] = {0, 0};
    while (top > 0) {
        const auto [i, j] = stack[--top];
        const scene3::node &x = na[i], &y = nb[j];
        if (x.leaf() && y.leaf()) {
            for (std::uint32_t p = x.first; p < x.first + x.count; ++p)
                for (std::uint32_t q = y.first; q < y.first + y.count; ++q) {
                    if (!boxes_meet(bounds(ta[p]), bounds(tb[q])) || !incidence::intersects<Tier>(ta[p], tb[q])) continue;
                    ++met;
                    if (out == nullptr) return true;
                    out->push_back({a.source(p), b.source(q)});
                }
            continue;
        }
        if (!x.leaf() && (y.leaf() || size(x.box) >= size(y.box))) { // descend a
            for (std::uint32_t c = x.first + 2; c-- > x.first;)
                if (boxes_meet(na[c].box, y.box)) stack[top++] = {c, j};
        } else { // descend b
            for (std::uint32_t c = y.first + 2; c-- > y.first;)
                if (boxes_meet(x.box, nb[c].box)) stack[top++] = {i, c};
        }
    }
    return met > 0;
}

// The instances the front doors (linear_scene.cppm, solid_scene.cppm) declare: every tier, every shape.
#define INCIDENCE_SCENE_LINEAR(TIER, S)                                                                                                    \
    template bool scene_any_hit<TIER, S>(const S&, const scene3&);                                                                         \
    template std::optional<scene_hit<scene_value_t<TIER>>> scene_first_hit<TIER, S>(const S&, const scene3&);                              \
    template std::size_t scene_every_hit<TIER, S>(const S&, const scene3&, std::vector<std::size_t>&);
#define INCIDENCE_SCENE_SOLID(TIER, S)                                                                                                     \
    template bool scene_solid_any<TIER, S>(const S&, const scene3&);                                                                       \
    template std::size_t scene_every_hit<TIER, S>(const S&, const scene3&, std::vector<std::size_t>&);
#define INCIDENCE_SCENE_TIER(TIER)                                                                                                         \
    template bool scene_pairs<TIER>(const scene3&, const scene3&, std::vector<std::pair<std::size_t, std::size_t>>*, std::size_t&);        \
    INCIDENCE_SCENE_LINEAR(TIER, ray3)                                                                                                     \
    INCIDENCE_SCENE_LINEAR(TIER, segment3)                                                                                                 \
    INCIDENCE_SCENE_LINEAR(TIER, line3)                                                                                                    \
    INCIDENCE_SCENE_SOLID(TIER, aabb3)                                                                                                     \
    INCIDENCE_SCENE_SOLID(TIER, obb3)                                                                                                      \
    INCIDENCE_SCENE_SOLID(TIER, triangle3)                                                                                                 \
    INCIDENCE_SCENE_SOLID(TIER, tetrahedron3)                                                                                              \
    INCIDENCE_SCENE_SOLID(TIER, frustum3)
template std::optional<scene_hit<scene_value_t<exact>>> triangles_first_hit<exact>(const ray3&, std::size_t, candidates_fn, const void*);
template std::optional<scene_hit<scene_value_t<conservative>>> triangles_first_hit<conservative>(const ray3&, std::size_t, candidates_fn,
                                                                                                 const void*);
template std::optional<scene_hit<scene_value_t<aggressive>>> triangles_first_hit<aggressive>(const ray3&, std::size_t, candidates_fn,
                                                                                             const void*);
template std::optional<scene_hit<scene_value_t<approximate>>> triangles_first_hit<approximate>(const ray3&, std::size_t, candidates_fn,
                                                                                               const void*);
INCIDENCE_SCENE_TIER(exact)
INCIDENCE_SCENE_TIER(conservative)
INCIDENCE_SCENE_TIER(aggressive)
INCIDENCE_SCENE_TIER(approximate)
#undef INCIDENCE_SCENE_TIER
#undef INCIDENCE_SCENE_SOLID
#undef INCIDENCE_SCENE_LINEAR

} // namespace incidence::detail
