// Rays against boxes and balls, in SIMD lanes: the kernels behind batch::intersects(ray, boxes or
// balls) and batch::intersects(rays, box or ball) (modules/batch/ray_solids.cppm declares them).
// Highway compiles this file once per target and dispatches at run time, as
// ray_triangles_simd.cpp. Fields (lanes-inl.h): a ray is six (origin x, y, z, direction x, y, z),
// a box six (min x, y, z, max x, y, z), a ball four (centre x, y, z, radius); the one shape's
// broadcast, the many's arrays.
//
// Each lane does what the scalar query does, operation for operation, so its answer is the scalar
// answer bit for bit:
// - box_approximate: the classic slab method of the approximate tier (modules/engines/box.cppm's
//   aabb_ray_slab: Kay and Kajiya, SIGGRAPH 1986, with reciprocal directions). 1 hit, 0 miss.
// - box_filter: the filtered tiers' first stage, the slab parameters rounded and widened by their
//   proven error (box.cppm's slab_parameters_decide): 1 or 0 where it is clear, 2 where the scalar
//   goes on to the slab signs (a parameter too close to call, a direction component outside
//   [2^-1000, 2^1000]); its answer is the scalar filter pass's, so the tiers agree.
// - ball_approximate: the optimized geometric method of the approximate tier (sphere.cppm's
//   ray_sphere_geometric, Real-Time Rendering 4th ed., section 22.6.2), square root and quotient
//   correctly rounded in a lane as in a scalar register.
// - ball_filter: the scalar filter's three signs (sphere_pairs.cppm: the origin against the ball,
//   |m|^2 - r^2 of degree 2 and six operations; the direction against m, degree 2 and four; the
//   discriminant, degree 4 and eleven) against a block's static bound, then the lanes' own: 1 or 0
//   where every sign the scalar reads is proven, else 2.
#include <cstddef>
#include <cstdint>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/batch/ray_solids_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>
#include "modules/batch/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Fields 0..5 the ray, 6.. the solid (six for a box, four for a ball).
HWY_INLINE fields ray_solid_fields(const double* const* ray, bool rays, const double* const* solid, int count) {
    fields f{{}, {}, 6 + count};
    for (int k = 0; k < 6; ++k) f.p[k] = ray[k], f.per_lane[k] = rays;
    for (int k = 0; k < count; ++k) f.p[6 + k] = solid[k], f.per_lane[6 + k] = !rays;
    return f;
}

void box_approximate(const double* const* ray, bool rays, const double* const* box, std::size_t n, std::uint8_t* out) {
    const D d;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
    over_fields(d, ray_solid_fields(ray, rays, box, 6), n, [&](const fields& f, std::size_t i, std::size_t lane, std::size_t count) {
        V t0 = zero, t1 = hn::Set(d, __builtin_huge_val());
        M miss = hn::Lt(one, zero); // none
        for (int k = 0; k < 3; ++k) {
            const V o = f.at(d, k, i), dk = f.at(d, 3 + k, i), mn = f.at(d, 6 + k, i), mx = f.at(d, 9 + k, i);
            const M negative = hn::Lt(dk, zero), still = hn::Eq(dk, zero);
            const V near = hn::IfThenElse(negative, mx, mn), far = hn::IfThenElse(negative, mn, mx);
            // a zero component: the origin must lie in the slab; else the slab's parameters narrow [t0, t1]
            miss = hn::Or(miss, hn::AndNot(hn::And(hn::Le(near, o), hn::Le(o, far)), still));
            const V inv = hn::Div(one, dk);
            const V tn = hn::Mul(hn::Sub(near, o), inv), tf = hn::Mul(hn::Sub(far, o), inv);
            t0 = hn::IfThenElse(hn::AndNot(still, hn::Gt(tn, t0)), tn, t0);
            t1 = hn::IfThenElse(hn::AndNot(still, hn::Lt(tf, t1)), tf, t1);
            miss = hn::Or(miss, hn::AndNot(still, hn::Not(hn::Le(t0, t1))));
        }
        store_answers(d, hn::Not(miss), out + lane, count);
    });
}

void box_filter(const double* const* ray, bool rays, const double* const* box, std::size_t n, std::uint8_t* out) {
    const D d;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), inf = hn::Set(d, __builtin_huge_val());
    const V tiny = hn::Set(d, 0x1p-1000), huge = hn::Set(d, 0x1p1000), rel = hn::Set(d, 0x1p-50), abs_e = hn::Set(d, 0x1p-1060);
    over_fields(d, ray_solid_fields(ray, rays, box, 6), n, [&](const fields& f, std::size_t i, std::size_t lane, std::size_t count) {
        V near_lo = zero, near_hi = zero, far_lo = inf, far_hi = inf;
        M done = hn::Lt(one, zero), no = done, uncertain = done, ordered = hn::Not(done);
        for (int k = 0; k < 3; ++k) {
            const V o = f.at(d, k, i), dk = f.at(d, 3 + k, i), mn = f.at(d, 6 + k, i), mx = f.at(d, 9 + k, i);
            const V ad = hn::Abs(dk);
            const M out_of_range = hn::AndNot(done, hn::Not(hn::And(hn::Ge(ad, tiny), hn::Le(ad, huge))));
            uncertain = hn::Or(uncertain, out_of_range);
            done = hn::Or(done, out_of_range);
            const V inv = hn::Div(one, dk);
            const V t1 = hn::Mul(hn::Sub(mn, o), inv), t2 = hn::Mul(hn::Sub(mx, o), inv);
            const M positive = hn::Gt(dk, zero);
            const V tn = hn::IfThenElse(positive, t1, t2), tf = hn::IfThenElse(positive, t2, t1);
            const V en = hn::Add(hn::Mul(rel, hn::Abs(tn)), abs_e), ef = hn::Add(hn::Mul(rel, hn::Abs(tf)), abs_e);
            const V nl = hn::Sub(tn, en), nh = hn::Add(tn, en), fl = hn::Sub(tf, ef), fh = hn::Add(tf, ef);
            // (a NaN test as Not(Eq): Highway's Ne is unordered on SSE4 and ordered on AVX2 and AVX-512)
            near_lo = hn::IfThenElse(hn::Gt(nl, near_lo), nl, near_lo);
            near_hi = hn::IfThenElse(hn::Or(hn::Gt(nh, near_hi), hn::Not(hn::Eq(nh, nh))), nh, near_hi);
            far_lo = hn::IfThenElse(hn::Or(hn::Lt(fl, far_lo), hn::Not(hn::Eq(fl, fl))), fl, far_lo);
            far_hi = hn::IfThenElse(hn::Lt(fh, far_hi), fh, far_hi);
            ordered = hn::And(ordered, hn::Le(mn, mx));
            const M apart = hn::AndNot(done, hn::Gt(near_lo, far_hi)); // the slabs so far have no common t
            no = hn::Or(no, apart);
            done = hn::Or(done, apart);
        }
        const M yes = hn::AndNot(done, hn::And(ordered, hn::Le(near_hi, far_lo)));
        store_answers(d, yes, hn::Or(uncertain, hn::Not(hn::Or(no, yes))), out + lane, count);
    });
}

void ball_approximate(const double* const* ray, bool rays, const double* const* ball, std::size_t n, std::uint8_t* out) {
    const D d;
    const V zero = hn::Zero(d);
    over_fields(d, ray_solid_fields(ray, rays, ball, 4), n, [&](const fields& f, std::size_t i, std::size_t lane, std::size_t count) {
        V l[3], dir[3];
        for (int k = 0; k < 3; ++k) l[k] = hn::Sub(f.at(d, 6 + k, i), f.at(d, k, i)), dir[k] = f.at(d, 3 + k, i);
        const V r = f.at(d, 9, i);
        auto dot3 = [](const V* a, const V* b) { return hn::Add(hn::Add(hn::Mul(a[0], b[0]), hn::Mul(a[1], b[1])), hn::Mul(a[2], b[2])); };
        const V r2 = hn::Mul(r, r), l2 = dot3(l, l), a = dot3(dir, dir);
        const M inside = hn::Le(l2, r2), moving = hn::Gt(a, zero);
        const V len = hn::Sqrt(a);
        const V sproj = hn::Div(dot3(l, dir), len);
        const V m2 = hn::Sub(l2, hn::Mul(sproj, sproj));
        const M away = hn::AndNot(inside, hn::Lt(sproj, zero));
        const M hit_moving = hn::Not(hn::Or(away, hn::Gt(m2, r2)));
        store_answers(d, hn::Or(hn::And(moving, hit_moving), hn::AndNot(moving, inside)), out + lane, count);
    });
}

// The three signs' values over a number type: c = m.m - r r (m = o - centre), b = m.d, and the
// discriminant b b - d.d c (the scalar expressions, operation for operation).
template <class T>
struct ball_signs {
    T c, b, disc;
};
template <class T>
HWY_INLINE ball_signs<T> ray_ball_signs(const vec<T>& m, const vec<T>& dir, T r) {
    const T c = dot(m, m) - r * r;
    const T b = dot(m, dir);
    return {c, b, b * b - dot(dir, dir) * (dot(m, m) - r * r)};
}
struct ray_ball_inputs {
    vec<fv> m, dir;
    fv r;
};
HWY_INLINE ray_ball_inputs ray_ball_at(D d, const fields& f, std::size_t i) {
    ray_ball_inputs x;
    auto input = [&](int k) {
        const V v = f.at(d, k, i);
        return fv{v, hn::Abs(v)};
    };
    x.m = {exact_difference(f.at(d, 0, i), f.at(d, 6, i)), exact_difference(f.at(d, 1, i), f.at(d, 7, i)),
           exact_difference(f.at(d, 2, i), f.at(d, 8, i))};
    x.dir = {input(3), input(4), input(5)};
    x.r = input(9);
    return x;
}
// The answer where the signs the scalar reads are proven: the origin in the ball (c < 0): a hit
// iff the direction is finite; outside (c > 0): b > 0 misses, b < 0 hits iff disc >= 0.
template <class Pos, class Neg>
HWY_INLINE void ray_ball_answer(D d, const Pos& pos, const Neg& neg, M finite_direction, std::uint8_t* out, std::size_t count) {
    const M in = neg(0), outside = pos(0);
    const M away = hn::And(outside, pos(1)), toward = hn::And(outside, neg(1));
    const M decided = hn::Or(hn::Or(in, away), hn::And(toward, hn::Or(pos(2), neg(2))));
    const M yes = hn::Or(hn::And(in, finite_direction), hn::And(toward, pos(2)));
    store_answers(d, hn::And(decided, yes), hn::Not(decided), out, count);
}

void ball_filter(const double* const* ray, bool rays, const double* const* ball, std::size_t n, std::uint8_t* out) {
    const D d;
    const double gamma[3] = {gamma_of(6), gamma_of(4), gamma_of(11)};
    const fields all = ray_solid_fields(ray, rays, ball, 4);
    constexpr std::size_t block = 64;
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const fields f = from(all, start);
        // the block's largest |m_k|, |d_k| and |r| (a NaN counts as infinite)
        V most[7];
        for (V& x : most) x = hn::Zero(d);
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t, std::size_t) {
            const ray_ball_inputs x = ray_ball_at(d, g, i);
            const fv* v[7] = {&x.m.x, &x.m.y, &x.m.z, &x.dir.x, &x.dir.y, &x.dir.z, &x.r};
            for (int k = 0; k < 7; ++k) most[k] = max_counting_nan(d, most[k], v[k]->p);
        });
        pp largest[7];
        for (int k = 0; k < 7; ++k) largest[k] = {hn::GetLane(hn::MaxOfLanes(d, most[k]))};
        const ball_signs<pp> p =
            ray_ball_signs(vec<pp>{largest[0], largest[1], largest[2]}, vec<pp>{largest[3], largest[4], largest[5]}, largest[6]);
        const V bound[3] = {static_bound(d, gamma[0], p.c.p), static_bound(d, gamma[1], p.b.p), static_bound(d, gamma[2], p.disc.p)};
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t lane, std::size_t count) {
            const ray_ball_inputs x = ray_ball_at(d, g, i);
            const M finite_direction = hn::And(hn::And(hn::IsFinite(x.dir.x.v), hn::IsFinite(x.dir.y.v)), hn::IsFinite(x.dir.z.v));
            const ball_signs<pv> v = ray_ball_signs(values(x.m), values(x.dir), pv{x.r.v});
            const V vs[3] = {v.c.v, v.b.v, v.disc.v};
            auto pos = [&](int k) { return hn::Gt(vs[k], bound[k]); };
            auto neg = [&](int k) { return hn::Lt(vs[k], hn::Neg(bound[k])); };
            // every lane proven by the static bound (the three signs; the scalar may need fewer)
            M proven = hn::Or(pos(0), neg(0));
            proven = hn::And(proven, hn::Or(neg(0), hn::Or(pos(1), hn::And(neg(1), hn::Or(pos(2), neg(2))))));
            if (hn::AllTrue(d, hn::Or(proven, hn::Not(hn::FirstN(d, count))))) {
                ray_ball_answer(d, pos, neg, finite_direction, out + start + lane, count);
                return;
            }
            const ball_signs<fv> own = ray_ball_signs(x.m, x.dir, x.r);
            const fv os[3] = {own.c, own.b, own.disc};
            ray_ball_answer(
                d, [&](int k) { return own_positive(d, gamma[k], os[k]); }, [&](int k) { return own_negative(d, gamma[k], os[k]); },
                finite_direction, out + start + lane, count);
        });
    }
}

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(box_approximate);
HWY_EXPORT(box_filter);
HWY_EXPORT(ball_approximate);
HWY_EXPORT(ball_filter);

// The entry points (declared extern "C++" in modules/batch/ray_solids.cppm).
void ray_boxes(const double* const* ray, bool rays, const double* const* box, std::size_t n, bool filter, std::uint8_t* out) {
    if (filter) HWY_DYNAMIC_DISPATCH(box_filter)(ray, rays, box, n, out);
    else HWY_DYNAMIC_DISPATCH(box_approximate)(ray, rays, box, n, out);
}
void ray_balls(const double* const* ray, bool rays, const double* const* ball, std::size_t n, bool filter, std::uint8_t* out) {
    if (filter) HWY_DYNAMIC_DISPATCH(ball_filter)(ray, rays, ball, n, out);
    else HWY_DYNAMIC_DISPATCH(ball_approximate)(ray, rays, ball, n, out);
}
} // namespace incidence::batch::simd
#endif
