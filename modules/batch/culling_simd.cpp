// Boxes against one frustum (or any six half-spaces), in SIMD lanes: the kernel behind
// batch::intersects(frustum, boxes) (modules/batch/culling.cppm declares it). Highway compiles this
// file once per target and dispatches at run time, as ray_triangles_simd.cpp.
//
// A lane does the three stages of the scalar query (halfspaces::box_meets in
// modules/engines/halfspace_lp.cppm) that come before its linear program, operation for
// operation, so that what it decides is the scalar answer bit for bit:
// 1. for each plane in order, c - n . q with q the box corner least along n: negative says no;
// 2. then, with every plane passed, c - n . m at the box's clamped middle m: positive at every
//    plane says yes; so does the same at the box corner least along n_i, for a plane i the middle
//    is not inside;
// 3. then, for each plane that two of the six imply along an edge-edge axis (the caller's list,
//    halfspaces::edge_planes, computed once for the batch in the tier's kernel as the scalar
//    query computes it per box), alpha (c_i - n_i . q) + beta (c_j - n_j . q) at the box corner
//    q the list names: negative says no.
// A lane no stage decides is left to the scalar query (its linear program): the boxes near the
// frustum's edges and corners. approximate: plain double. The filtered tiers: each sign of the
// scalar filter (degree 2, gamma_4; stage 3 degree 3, gamma_6), stages 1 and 2 against a static
// bound per plane and block of 64 lanes and then, where that leaves a lane undecided, the lane's
// own permanent, stage 3 against the lane's own; a lane whose plane sign is unproven before a
// negative one is left open too, as the scalar filter pass fails there. A box with a non-finite
// bound or an inverted box meets nothing. The caller passes finite planes only (a frustum with a
// non-finite number is no set: the scalar query's answer).
#include <cstddef>
#include <cstdint>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/batch/culling_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>
#include "modules/batch/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// c 1 - ((n_x x + n_y y) + n_z z), the scalar expression, for one plane (n, c) broadcast and a
// point of the lanes: in the filter, with its permanent.
HWY_INLINE fv plane_value(D d, const double* plane, const V* x) {
    auto in = [&](double v) { return fv{hn::Set(d, v), hn::Set(d, v < 0 ? -v : v)}; };
    auto lane = [&](V v) { return fv{v, hn::Abs(v)}; };
    const fv one = in(1.0);
    return in(plane[3]) * one - (in(plane[0]) * lane(x[0]) + in(plane[1]) * lane(x[1]) + in(plane[2]) * lane(x[2]));
}
HWY_INLINE V plane_value_alone(D d, const double* plane, const V* x) {
    const pv one{hn::Set(d, 1.0)};
    return (pv{hn::Set(d, plane[3])} * one -
            (pv{hn::Set(d, plane[0])} * pv{x[0]} + pv{hn::Set(d, plane[1])} * pv{x[1]} + pv{hn::Set(d, plane[2])} * pv{x[2]}))
        .v;
}

// A sign's two masks: proven positive, proven negative (approximate: the signs of plain double).
struct sign_masks {
    M pos, neg;
};

// planes: six planes as (n_x, n_y, n_z, c); edges: `edge_count` implied planes as (i, j, alpha,
// beta, upper_x, upper_y, upper_z); boxes: min x, y, z, max x, y, z, arrays of n.
void frustum_box(const double* planes, const double* edges, int edge_count, const double* const* boxes, std::size_t n, bool filter,
                 std::uint8_t* out) {
    const D d;
    constexpr double gamma = gamma_of(4);         // c 1: one operation; each n_k q_k one, two sums, the difference
    constexpr double gamma_implied = gamma_of(6); // alpha times that, and the sum of two
    constexpr std::size_t block = 64;
    const M none = hn::Not(hn::Eq(hn::Zero(d), hn::Zero(d)));
    fields all{{}, {}, 6};
    for (int k = 0; k < 6; ++k) all.p[k] = boxes[k], all.per_lane[k] = true;
    auto load = [&](const fields& g, std::size_t i, std::size_t count, V* mn, V* mx) {
        M usable = hn::FirstN(d, count);
        for (int k = 0; k < 3; ++k) {
            mn[k] = g.at(d, k, i), mx[k] = g.at(d, 3 + k, i);
            usable = hn::And(usable, hn::And(hn::And(hn::IsFinite(mn[k]), hn::IsFinite(mx[k])), hn::Le(mn[k], mx[k])));
        }
        return usable;
    };
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const fields f = from(all, start);
        // the filter's static bound per plane, from the block's largest |coordinate| on each axis
        // (any point of a box, and so every point a stage tries, is within it)
        V bound[6];
        if (filter) {
            V most[3] = {hn::Zero(d), hn::Zero(d), hn::Zero(d)};
            over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t, std::size_t count) {
                V mn[3], mx[3];
                const M usable = load(g, i, count, mn, mx);
                for (int k = 0; k < 3; ++k) most[k] = hn::Max(most[k], hn::IfThenElseZero(usable, hn::Max(hn::Abs(mn[k]), hn::Abs(mx[k]))));
            });
            pp big[3];
            for (int k = 0; k < 3; ++k) big[k] = {hn::GetLane(hn::MaxOfLanes(d, most[k]))};
            for (int p = 0; p < 6; ++p) {
                const double* h = planes + 4 * p;
                auto in = [](double v) { return pp{v < 0 ? -v : v}; };
                bound[p] = static_bound(d, gamma, (in(h[3]) * pp{1.0} - (in(h[0]) * big[0] + in(h[1]) * big[1] + in(h[2]) * big[2])).p);
            }
        }
        // plane p's sign at x for the lanes in `care`: the static bound, then each lane's own
        // the box corner least along plane p's normal (halfspaces' least_corner: min where n_k > 0)
        auto least_corner = [&](int p, const V* mn, const V* mx, V* q) {
            for (int k = 0; k < 3; ++k) q[k] = planes[4 * p + k] > 0 ? mn[k] : mx[k];
        };
        auto test = [&](int p, const V* x, M care) {
            const double* plane = planes + 4 * p;
            const V v = plane_value_alone(d, plane, x);
            if (!filter) return sign_masks{hn::Gt(v, hn::Zero(d)), hn::Lt(v, hn::Zero(d))};
            sign_masks s{hn::Gt(v, bound[p]), hn::Lt(v, hn::Neg(bound[p]))};
            if (!hn::AllFalse(d, hn::AndNot(hn::Or(s.pos, s.neg), care))) {
                const fv own = plane_value(d, plane, x);
                s = {own_positive(d, gamma, own), own_negative(d, gamma, own)};
            }
            return s;
        };
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t lane, std::size_t count) {
            V mn[3], mx[3];
            const M usable = load(g, i, count, mn, mx);
            // stage 1: alive, the lanes every plane so far has proven short of the box's far side
            M alive = usable, open = none;
            for (int p = 0; p < 6 && !hn::AllFalse(d, alive); ++p) {
                V q[3];
                least_corner(p, mn, mx, q);
                const sign_masks s = test(p, q, alive);
                if (filter) open = hn::Or(open, hn::AndNot(hn::Or(s.pos, s.neg), alive));
                alive = filter ? hn::And(alive, s.pos) : hn::AndNot(s.neg, alive);
            }
            // stage 2: the box's middle strictly inside every plane, or for a plane it is not
            // inside, the box corner least along that plane's normal
            M yes = alive;
            if (!hn::AllFalse(d, alive)) {
                V c[3];
                for (int k = 0; k < 3; ++k) {
                    const V mid = hn::Add(hn::Mul(hn::Set(d, 0.5), mn[k]), hn::Mul(hn::Set(d, 0.5), mx[k]));
                    c[k] = hn::Min(hn::Max(mid, mn[k]), mx[k]);
                }
                M middle_outside[6];
                for (int p = 0; p < 6; ++p) {
                    middle_outside[p] = hn::Not(test(p, c, alive).pos);
                    yes = hn::AndNot(middle_outside[p], yes);
                }
                M corner_inside = none;
                for (int p = 0; p < 6; ++p) {
                    const M tried = hn::AndNot(yes, hn::And(alive, middle_outside[p]));
                    if (hn::AllFalse(d, hn::AndNot(corner_inside, tried))) continue;
                    V q[3];
                    least_corner(p, mn, mx, q);
                    M inside = tried;
                    for (int j = 0; j < 6; ++j) inside = hn::And(inside, test(j, q, tried).pos);
                    corner_inside = hn::Or(corner_inside, inside);
                }
                yes = hn::Or(yes, corner_inside);
                // stage 3: the lanes alive and not accepted, beyond an implied plane
                const M rest = hn::AndNot(yes, alive);
                M beyond = none;
                for (int e = 0; e < edge_count && !hn::AllFalse(d, hn::AndNot(beyond, rest)); ++e) {
                    const double* x = edges + 7 * e;
                    const double* pi = planes + 4 * static_cast<int>(x[0]);
                    const double* pj = planes + 4 * static_cast<int>(x[1]);
                    V q[3];
                    for (int k = 0; k < 3; ++k) q[k] = x[4 + k] != 0 ? mx[k] : mn[k];
                    if (filter) {
                        const fv alpha{hn::Set(d, x[2]), hn::Set(d, x[2])}, beta{hn::Set(d, x[3]), hn::Set(d, x[3])};
                        beyond =
                            hn::Or(beyond, own_negative(d, gamma_implied, alpha * plane_value(d, pi, q) + beta * plane_value(d, pj, q)));
                    } else {
                        const V v = (pv{hn::Set(d, x[2])} * pv{plane_value_alone(d, pi, q)} +
                                     pv{hn::Set(d, x[3])} * pv{plane_value_alone(d, pj, q)})
                                        .v;
                        beyond = hn::Or(beyond, hn::Lt(v, hn::Zero(d)));
                    }
                }
                open = hn::Or(open, hn::AndNot(beyond, rest));
            }
            store_answers(d, yes, open, out + start + lane, count);
        });
    }
}

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(frustum_box);

// The entry point (declared extern "C++" in modules/batch/culling.cppm).
void frustum_boxes(const double* planes, const double* edges, int edge_count, const double* const* boxes, std::size_t n, bool filter,
                   std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(frustum_box)(planes, edges, edge_count, boxes, n, filter, out);
}
} // namespace incidence::batch::simd
#endif
