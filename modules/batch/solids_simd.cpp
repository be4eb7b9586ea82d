// Boxes and balls against one box or one ball, in SIMD lanes: the kernels behind
// batch::intersects(one, many) for one and many among aabb3 and sphere3 (modules/batch/solids.cppm
// declares them). Highway compiles this file once per target and dispatches at run time, as
// ray_triangles_simd.cpp.
//
// A kernel reads its shapes as fields (a box: min.x, min.y, min.z, max.x, max.y, max.z; a ball:
// centre x, y, z and radius), each either one value for every lane (the one shape) or an array of
// n (the many), and does in each lane what the scalar query does, operation for operation, so its
// answer is the scalar answer bit for bit:
// - box_box: the six comparisons of the scalar body (modules/query/intersects/box_pairs.cppm), in
//   every tier: comparisons decide it exactly.
// - box_ball / ball_ball: the sign of r r - |g|^2 (the scalar bodies of sphere_pairs.cppm: g the
//   gap from the centre to the box's nearest point, or the difference of the centres with
//   r = r_a + r_b), six operations. A box or ball with a non-finite field or an inverted box meets
//   nothing (box_ball only: the scalar ball_ball has no such test, so a NaN lane is left to it).
//   approximate: plain double, 1 unless negative; filter: 1 or 0 where proven, 2 where not, first
//   against the static bound of a block of 64 lanes (the permanent on its largest |r| and |g_k|),
//   then a vector it leaves open against each lane's own.
#include <cstddef>
#include <cstdint>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/batch/solids_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>
#include "modules/batch/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void box_box(const double* const* box, const double* const* boxes, std::size_t n, std::uint8_t* out) {
    const D d;
    fields f{{}, {}, 12};
    for (int k = 0; k < 6; ++k) f.p[k] = box[k], f.p[6 + k] = boxes[k], f.per_lane[6 + k] = true;
    over_fields(d, f, n, [&](const fields& g, std::size_t i, std::size_t lane, std::size_t count) {
        M meet = hn::FirstN(d, count);
        for (int k = 0; k < 3; ++k)
            meet = hn::And(meet, hn::And(hn::Le(g.at(d, k, i), g.at(d, 9 + k, i)), hn::Le(g.at(d, 6 + k, i), g.at(d, 3 + k, i))));
        store_answers(d, meet, out + lane, count);
    });
}

// One lane group's ball test: usable (the lanes whose shapes count), the radius r and the gaps g_k
// as values of the filter (r r - ((g_0 g_0 + g_1 g_1) + g_2 g_2), the scalar expression).
struct ball_inputs {
    M usable;
    fv r, g[3];
};
HWY_INLINE fv ball_value(const ball_inputs& x) { return x.r * x.r - (x.g[0] * x.g[0] + x.g[1] * x.g[1] + x.g[2] * x.g[2]); }
HWY_INLINE pv ball_value(pv r, const pv* g) { return r * r - (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]); }

// Fields 0..5 a box, 6..9 a ball: the gap from the centre to the box's nearest point on each axis
// (the scalar's hi - lo: min - c below the box, c - max above it, 0 - 0 within).
HWY_INLINE ball_inputs box_ball_inputs(D d, const fields& f, std::size_t i) {
    ball_inputs x;
    M usable = hn::IsFinite(f.at(d, 9, i));
    for (int k = 0; k < 3; ++k) {
        const V mn = f.at(d, k, i), mx = f.at(d, 3 + k, i), c = f.at(d, 6 + k, i);
        usable = hn::And(usable, hn::And(hn::And(hn::IsFinite(mn), hn::IsFinite(mx)), hn::And(hn::IsFinite(c), hn::Le(mn, mx))));
        const M below = hn::Lt(c, mn), above = hn::Gt(c, mx);
        const V lo = hn::IfThenElse(below, c, hn::IfThenElseZero(above, mx));
        const V hi = hn::IfThenElse(below, mn, hn::IfThenElseZero(above, c));
        x.g[k] = exact_difference(hi, lo);
    }
    x.usable = usable;
    const V r = f.at(d, 9, i);
    x.r = {r, hn::Abs(r)};
    return x;
}
// Fields 0..3 and 4..7 two balls: the difference of the centres, and r = |r_a| + |r_b| (one
// operation on inputs: its permanent is r; a negative radius acts as |r|, as in the scalar test).
HWY_INLINE ball_inputs ball_ball_inputs(D d, const fields& f, std::size_t i) {
    ball_inputs x;
    for (int k = 0; k < 3; ++k) x.g[k] = exact_difference(f.at(d, k, i), f.at(d, 4 + k, i));
    const V r = hn::Add(hn::Abs(f.at(d, 3, i)), hn::Abs(f.at(d, 7, i)));
    x.r = {r, hn::Abs(r)};
    x.usable = hn::Eq(hn::Zero(d), hn::Zero(d)); // every lane
    return x;
}

template <class Inputs>
HWY_INLINE void balls_approximate(D d, const fields& f, std::size_t n, std::uint8_t* out, const Inputs& inputs) {
    over_fields(d, f, n, [&](const fields& g, std::size_t i, std::size_t lane, std::size_t count) {
        const ball_inputs x = inputs(d, g, i);
        const pv gv[3] = {{x.g[0].v}, {x.g[1].v}, {x.g[2].v}};
        const V v = ball_value(pv{x.r.v}, gv).v;
        store_answers(d, hn::AndNot(hn::Lt(v, hn::Zero(d)), x.usable), out + lane, count);
    });
}

template <class Inputs>
HWY_INLINE void balls_filter(D d, const fields& all, std::size_t n, std::uint8_t* out, const Inputs& inputs) {
    constexpr double gamma = gamma_of(6); // r r: one operation; g_k g_k three; two sums and the difference
    constexpr std::size_t block = 64;
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const fields f = from(all, start);
        // the block's largest |r| and |g_k| over its usable lanes (a NaN counts as infinite)
        V most[4] = {hn::Zero(d), hn::Zero(d), hn::Zero(d), hn::Zero(d)};
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t, std::size_t) {
            const ball_inputs x = inputs(d, g, i);
            most[0] = max_counting_nan(d, most[0], hn::IfThenElseZero(x.usable, x.r.p));
            for (int k = 0; k < 3; ++k) most[1 + k] = max_counting_nan(d, most[1 + k], hn::IfThenElseZero(x.usable, x.g[k].p));
        });
        pp largest[4];
        for (int k = 0; k < 4; ++k) largest[k] = {hn::GetLane(hn::MaxOfLanes(d, most[k]))};
        const V bound = static_bound(
            d, gamma, (largest[0] * largest[0] - (largest[1] * largest[1] + largest[2] * largest[2] + largest[3] * largest[3])).p);
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t lane, std::size_t count) {
            const ball_inputs x = inputs(d, g, i);
            const pv gv[3] = {{x.g[0].v}, {x.g[1].v}, {x.g[2].v}};
            const V v = ball_value(pv{x.r.v}, gv).v;
            M up = hn::Gt(v, bound), down = hn::Lt(v, hn::Neg(bound));
            const M counted = hn::And(x.usable, hn::FirstN(d, count));
            if (!hn::AllTrue(d, hn::Or(hn::Or(up, down), hn::Not(counted)))) { // the lanes' own bounds
                const fv own = ball_value(x);
                up = own_positive(d, gamma, own), down = own_negative(d, gamma, own);
            }
            store_answers(d, hn::And(x.usable, up), hn::AndNot(hn::Or(up, down), x.usable), out + start + lane, count);
        });
    }
}

HWY_INLINE fields box_ball_fields(const double* const* box, bool boxes, const double* const* ball, bool balls) {
    fields f{{}, {}, 10};
    for (int k = 0; k < 6; ++k) f.p[k] = box[k], f.per_lane[k] = boxes;
    for (int k = 0; k < 4; ++k) f.p[6 + k] = ball[k], f.per_lane[6 + k] = balls;
    return f;
}
// boxes: the box fields are arrays of n (else one box), and the ball's are one ball (else arrays).
void box_ball(const double* const* box, const double* const* ball, bool boxes, std::size_t n, bool filter, std::uint8_t* out) {
    const D d;
    const fields f = box_ball_fields(box, boxes, ball, !boxes);
    if (filter) balls_filter(d, f, n, out, box_ball_inputs);
    else balls_approximate(d, f, n, out, box_ball_inputs);
}
// One ball (fields of one value) against n balls (arrays of n).
void ball_ball(const double* const* ball, const double* const* balls, std::size_t n, bool filter, std::uint8_t* out) {
    const D d;
    fields f{{}, {}, 8};
    for (int k = 0; k < 4; ++k) f.p[k] = ball[k], f.p[4 + k] = balls[k], f.per_lane[4 + k] = true;
    if (filter) balls_filter(d, f, n, out, ball_ball_inputs);
    else balls_approximate(d, f, n, out, ball_ball_inputs);
}

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(box_box);
HWY_EXPORT(box_ball);
HWY_EXPORT(ball_ball);

// The entry points (declared extern "C++" in modules/batch/solids.cppm).
void box_boxes(const double* const* box, const double* const* boxes, std::size_t n, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(box_box)(box, boxes, n, out);
}
void box_balls(const double* const* box, const double* const* ball, bool boxes, std::size_t n, bool filter, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(box_ball)(box, ball, boxes, n, filter, out);
}
void ball_balls(const double* const* ball, const double* const* balls, std::size_t n, bool filter, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(ball_ball)(ball, balls, n, filter, out);
}
} // namespace incidence::batch::simd
#endif
