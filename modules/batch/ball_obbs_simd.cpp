// Oriented boxes against one ball, in SIMD lanes: the kernel behind batch::intersects(sphere3, obbs)
// (modules/batch/solids.cppm declares it). Highway compiles this file once per target and
// dispatches at run time, as ray_triangles_simd.cpp.
//
// A lane evaluates the scalar query's first look (ball_obb::first_look in
// modules/engines/ball_obb.cppm; Ericson, Real-Time Collision Detection, 2005, section 5.2.1)
// operation for operation, with the box's centre o, axes a_j and half extents h_j, and the ball's
// centre c and radius r:
//   coordinate slab m: |c_m - o_m| 1 - ((h_0 |a_0m| + h_1 |a_1m|) + h_2 |a_2m|) - |r| 1 > 0: no;
//   centre:            r r - |o - c|^2 > 0: yes;
//   box-axis slab j:   |a_j . (c - o)| 1 - ((h_0 |a_j . a_0| + h_1 |a_j . a_1|) + h_2 |a_j . a_2|)
//                      - (|r| ((|a_jx| + |a_jy|) + |a_jz|)) 1 > 0: no;
//   point of the box:  r r (1 1) - |(c - o) 1 - sum a_j t_j|^2 > 0, t_j c's coordinate along a_j
//                      clamped to +-h_j (ball_obb::clamped, the same doubles): yes;
//   slab along d:      d = c - o - sum a_j t_j in plain double, the gap (d . (c - o)) 1 - ((h_0
//                      |d . a_0| + h_1 |d . a_1|) + h_2 |d . a_2|) > 0 and gap gap - r r (d . d)
//                      (1 1) > 0: no.
// approximate: the same doubles, and the scalar's order (a coordinate slab, then the centre, then a
// box-axis slab, then the point, then the slab along d) where plain double's signs contradict each
// other. The filtered tiers: each value with its permanent (fv: filtered.cppm's arithmetic, the
// same operations on the same doubles) against the lane's own bound, with the gamma of each value's operation count read off the
// scalar's expressions by the caller: the bound the scalar's filter computes, so a lane decides
// exactly where the scalar's first look proves a sign, and the same way. Any other lane (the first
// look proves nothing; a non-finite number, a negative or NaN extent) is left to the scalar query
// (2), which then runs its box coordinates.
#include <cstddef>
#include <cstdint>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/batch/ball_obbs_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>
#include "modules/batch/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The value alone (approximate) or with its permanent (the filter): an input, its magnitude, and
// whether the value is positive (the filter: proven positive against gamma).
HWY_INLINE pv input_of(pv, V x) { return {x}; }
HWY_INLINE fv input_of(fv, V x) { return {x, hn::Abs(x)}; }
HWY_INLINE pv difference_of(pv, V a, V b) { return {hn::Sub(a, b)}; }
HWY_INLINE fv difference_of(fv, V a, V b) { return exact_difference(a, b); }
HWY_INLINE pv magnitude(pv x) { return {hn::Abs(x.v)}; }
HWY_INLINE fv magnitude(fv x) { return {hn::Abs(x.v), x.p}; }
HWY_INLINE M positive(D d, double, pv x) { return hn::Gt(x.v, hn::Zero(d)); }
HWY_INLINE M positive(D d, double gamma, fv x) { return own_positive(d, gamma, x); }

// The first look in one vector of lanes: `no` and `yes` where it decides.
template <class T>
HWY_INLINE void first_look(D d, const lanes_obb& b, M usable, const V* c, V r, const double* gammas, M& no, M& yes) {
    const T proto{};
    const T one = input_of(proto, hn::Set(d, 1.0));
    const T radius = input_of(proto, hn::Abs(r));
    M slab = hn::Not(hn::Eq(hn::Zero(d), hn::Zero(d)));
    for (int m = 0; m < 3; ++m) {
        const T reach = (input_of(proto, b.h[0]) * input_of(proto, hn::Abs(b.a[0][m])) +
                         input_of(proto, b.h[1]) * input_of(proto, hn::Abs(b.a[1][m]))) +
                        input_of(proto, b.h[2]) * input_of(proto, hn::Abs(b.a[2][m]));
        const T v = magnitude(difference_of(proto, c[m], b.c[m])) * one - reach - radius * one;
        slab = hn::Or(slab, positive(d, gammas[0], v));
    }
    const T g[3] = {difference_of(proto, b.c[0], c[0]), difference_of(proto, b.c[1], c[1]), difference_of(proto, b.c[2], c[2])};
    const T rr = input_of(proto, r) * input_of(proto, r);
    yes = hn::AndNot(slab, positive(d, gammas[1], rr - (g[0] * g[0] + g[1] * g[1] + g[2] * g[2])));
    no = slab;
    if (hn::AllTrue(d, hn::Or(hn::Or(slab, yes), hn::Not(usable)))) return;
    const vec<T> axis[3] = {{input_of(proto, b.a[0][0]), input_of(proto, b.a[0][1]), input_of(proto, b.a[0][2])},
                            {input_of(proto, b.a[1][0]), input_of(proto, b.a[1][1]), input_of(proto, b.a[1][2])},
                            {input_of(proto, b.a[2][0]), input_of(proto, b.a[2][1]), input_of(proto, b.a[2][2])}};
    const vec<T> e{difference_of(proto, c[0], b.c[0]), difference_of(proto, c[1], b.c[1]), difference_of(proto, c[2], b.c[2])};
    for (int j = 0; j < 3; ++j) {
        const vec<T>& aj = axis[j];
        const T reach = (input_of(proto, b.h[0]) * magnitude(dot(aj, axis[0])) + input_of(proto, b.h[1]) * magnitude(dot(aj, axis[1]))) +
                        input_of(proto, b.h[2]) * magnitude(dot(aj, axis[2]));
        const T norm1 = (input_of(proto, hn::Abs(b.a[j][0])) + input_of(proto, hn::Abs(b.a[j][1]))) + input_of(proto, hn::Abs(b.a[j][2]));
        const T v = magnitude(dot(aj, e)) * one - reach - radius * norm1 * one;
        no = hn::Or(no, hn::AndNot(yes, positive(d, gammas[2], v)));
    }
    if (hn::AllTrue(d, hn::Or(hn::Or(no, yes), hn::Not(usable)))) return;
    // the box's point of c's clamped coordinates t_j (ball_obb::clamped, in the same doubles)
    const V ed[3] = {hn::Sub(c[0], b.c[0]), hn::Sub(c[1], b.c[1]), hn::Sub(c[2], b.c[2])};
    T t[3];
    for (int j = 0; j < 3; ++j) {
        const V* a = b.a[j];
        const V aa = hn::Add(hn::Add(hn::Mul(a[0], a[0]), hn::Mul(a[1], a[1])), hn::Mul(a[2], a[2]));
        const V ae = hn::Add(hn::Add(hn::Mul(a[0], ed[0]), hn::Mul(a[1], ed[1])), hn::Mul(a[2], ed[2]));
        const V s = hn::IfThenElseZero(hn::Gt(aa, hn::Zero(d)), hn::Div(ae, aa));
        const V h = b.h[j], low = hn::Neg(h);
        t[j] = input_of(proto, hn::IfThenElse(hn::Ge(s, h), h, hn::IfThenElse(hn::Le(s, low), low, hn::IfThenElseZero(hn::Eq(s, s), s))));
    }
    const auto part = [](const vec<T>& v, int k) { return k == 0 ? v.x : (k == 1 ? v.y : v.z); };
    T w[3];
    for (int k = 0; k < 3; ++k) w[k] = ((part(e, k) * one - part(axis[0], k) * t[0]) - part(axis[1], k) * t[1]) - part(axis[2], k) * t[2];
    const vec<T> wv{w[0], w[1], w[2]};
    yes = hn::Or(yes, hn::AndNot(no, positive(d, gammas[3], rr * (one * one) - dot(wv, wv))));
    if (hn::AllTrue(d, hn::Or(hn::Or(no, yes), hn::Not(usable)))) return;
    // the slab along that point to c (ball_obb::apart_direction, the same doubles)
    V dir[3];
    for (int k = 0; k < 3; ++k)
        dir[k] = hn::Sub(hn::Sub(hn::Sub(ed[k], hn::Mul(t[0].v, b.a[0][k])), hn::Mul(t[1].v, b.a[1][k])), hn::Mul(t[2].v, b.a[2][k]));
    const vec<T> dv{input_of(proto, dir[0]), input_of(proto, dir[1]), input_of(proto, dir[2])};
    const T gap = dot(dv, e) * one -
                  ((input_of(proto, b.h[0]) * magnitude(dot(dv, axis[0])) + input_of(proto, b.h[1]) * magnitude(dot(dv, axis[1]))) +
                   input_of(proto, b.h[2]) * magnitude(dot(dv, axis[2])));
    const M apart = hn::And(positive(d, gammas[4], gap), positive(d, gammas[5], gap * gap - rr * dot(dv, dv) * (one * one)));
    no = hn::Or(no, hn::AndNot(yes, apart));
}

// ball: four values (centre x, y, z, radius); obbs: fifteen arrays of n (centre, axes, half
// extents); gammas: the scalar filter's gamma for the coordinate slabs, the centre, the box-axis
// slabs, the clamped point, and the gap and the square along d, or null for the approximate tier.
void ball_obb(const double* const* ball, const double* const* obbs, std::size_t n, const double* gammas, std::uint8_t* out) {
    const D d;
    const double cb[3] = {*ball[0], *ball[1], *ball[2]}, rb = *ball[3];
    // a ball with a non-finite number is the scalar query's to answer
    if (!(cb[0] - cb[0] == 0.0 && cb[1] - cb[1] == 0.0 && cb[2] - cb[2] == 0.0 && rb - rb == 0.0)) {
        std::memset(out, 2, n);
        return;
    }
    const V c[3] = {hn::Set(d, cb[0]), hn::Set(d, cb[1]), hn::Set(d, cb[2])};
    const V r = hn::Set(d, rb);
    fields all{{}, {}, 15};
    for (int k = 0; k < 15; ++k) all.p[k] = obbs[k], all.per_lane[k] = true;
    over_fields(d, all, n, [&](const fields& g, std::size_t i, std::size_t lane, std::size_t count) {
        lanes_obb b;
        const M usable = load_obb(d, g, i, count, b, [](V x) { return hn::IsFinite(x); });
        M no, yes;
        constexpr double unused[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}; // plain double's signs need no gamma
        if (gammas != nullptr) first_look<fv>(d, b, usable, c, r, gammas, no, yes);
        else first_look<pv>(d, b, usable, c, r, unused, no, yes);
        const M decided = hn::And(usable, hn::Or(no, yes));
        store_answers(d, hn::And(yes, decided), hn::Not(decided), out + lane, count);
    });
}

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(ball_obb);

// The entry point (declared extern "C++" in modules/batch/solids.cppm).
void ball_obbs(const double* const* ball, const double* const* obbs, std::size_t n, const double* gammas, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(ball_obb)(ball, obbs, n, gammas, out);
}
} // namespace incidence::batch::simd
#endif
