// Many points against one solid, in SIMD lanes: the kernels behind batch::intersects(box, points)
// and batch::intersects(sphere, points) (modules/batch/points.cppm declares them). Highway compiles
// this file once per target and dispatches at run time, as ray_triangles_simd.cpp.
//
// Each lane does what the scalar query does, operation for operation, so its answer is the scalar
// answer bit for bit:
// - box_points: the six comparisons min <= p <= max of the scalar body, in every tier (a NaN
//   compares false, as in the scalar code). 1 inside or on the boundary, 0 outside.
// - sphere_points_approximate: the sign of r r - |p - c|^2 in plain double, as the approximate
//   kernel computes it: 1 unless negative (a NaN is not negative, as sign_of_double's zero).
// - sphere_points_filter: the same value in the semi-static filter (modules/arith/filtered.cppm,
//   six operations, bound gamma_6 p): 1 or 0 where proven, 2 where not. A block of 64 lanes is
//   first tried against a static bound, the permanent r r + |p - c|^2 on the block's largest
//   |p_k - c_k| (rounding is monotone, so what it proves the lane's own bound proves; a NaN makes
//   the block's bound infinite), then a vector it leaves open against each lane's own.
// - tetrahedron_points: the scalar point_in_closed (modules/engines/tetrahedron.cppm): a point
//   beyond the tetrahedron's bounding box is outside (comparisons: a non-finite point is beyond
//   it), else the four volumes with the point in place of one vertex, as triple products around
//   the cross products c = d0 x d1 and e = d2 x d3 (d_i = v_i - p): c.d2, -(c.d3), d0.e, -(d1.e).
//   Two of opposite nonzero signs: outside; nonzero ones of one sign: inside; all four zero (a
//   flat tetrahedron): 2, for the scalar query. Plain double in the approximate tier; in the
//   filter (eight operations per sign) a vector's lanes are decided where the signs the scalar
//   filter reads are proven (c.d2 and c.d3 opposite, or all four), against one static bound (the
//   tetrahedron's box bounds every |d_i| of a point in it: computed once per call) and then the
//   lanes' own; else 2.
#include <cstddef>
#include <cstdint>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/batch/points_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>
#include "modules/batch/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Where the n points are: three coordinate arrays (xyz == nullptr), or one array of x, y, z
// interleaved (point after point, as an array of point3 copied into doubles).
struct points_at {
    const double* c[3];
    const double* xyz;
    points_at from(std::size_t start) const {
        return xyz != nullptr ? points_at{{}, xyz + 3 * start} : points_at{{c[0] + start, c[1] + start, c[2] + start}, nullptr};
    }
};

// Runs body(x, y, z, lane, count) over the n points: whole vectors in place, the tail from a
// zero-padded copy.
template <class Body>
HWY_INLINE void over_points(D d, const points_at& at, std::size_t n, const Body& body) {
    const std::size_t N = hn::Lanes(d);
    std::size_t i = 0;
    for (; i + N <= n; i += N) {
        if (at.xyz != nullptr) {
            V x, y, z;
            hn::LoadInterleaved3(d, at.xyz + 3 * i, x, y, z);
            body(x, y, z, i, N);
        } else {
            body(hn::LoadU(d, at.c[0] + i), hn::LoadU(d, at.c[1] + i), hn::LoadU(d, at.c[2] + i), i, N);
        }
    }
    if (i == n) return;
    HWY_ALIGN double tail[3][HWY_MAX_BYTES / sizeof(double)] = {};
    for (std::size_t j = i; j < n; ++j)
        for (int k = 0; k < 3; ++k) tail[k][j - i] = at.xyz != nullptr ? at.xyz[3 * j + k] : at.c[k][j];
    body(hn::Load(d, tail[0]), hn::Load(d, tail[1]), hn::Load(d, tail[2]), i, n - i);
}

void box_points(const double* box, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out) {
    const D d;
    const points_at at{{coords[0], coords[1], coords[2]}, xyz};
    const V lo[3] = {hn::Set(d, box[0]), hn::Set(d, box[1]), hn::Set(d, box[2])};
    const V hi[3] = {hn::Set(d, box[3]), hn::Set(d, box[4]), hn::Set(d, box[5])};
    over_points(d, at, n, [&](V x, V y, V z, std::size_t lane, std::size_t count) {
        const M in = hn::And(hn::And(hn::And(hn::Le(lo[0], x), hn::Le(x, hi[0])), hn::And(hn::Le(lo[1], y), hn::Le(y, hi[1]))),
                             hn::And(hn::Le(lo[2], z), hn::Le(z, hi[2])));
        store_answers(d, in, out + lane, count);
    });
}

// r r - ((dx dx + dy dy) + dz dz), the scalar expression's order.
HWY_INLINE V power(V r, V dx, V dy, V dz) {
    return hn::Sub(hn::Mul(r, r), hn::Add(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)), hn::Mul(dz, dz)));
}

void sphere_points_approximate(const double* center, double radius, const double* const* coords, const double* xyz, std::size_t n,
                               std::uint8_t* out) {
    const D d;
    const points_at at{{coords[0], coords[1], coords[2]}, xyz};
    const V c[3] = {hn::Set(d, center[0]), hn::Set(d, center[1]), hn::Set(d, center[2])};
    const V r = hn::Set(d, radius);
    over_points(d, at, n, [&](V x, V y, V z, std::size_t lane, std::size_t count) {
        const V v = power(r, hn::Sub(x, c[0]), hn::Sub(y, c[1]), hn::Sub(z, c[2]));
        store_answers(d, hn::Not(hn::Lt(v, hn::Zero(d))), out + lane, count);
    });
}

void sphere_points_filter(const double* center, double radius, const double* const* coords, const double* xyz, std::size_t n,
                          std::uint8_t* out) {
    const D d;
    const points_at all{{coords[0], coords[1], coords[2]}, xyz};
    // gamma_6 with filtered.cppm's (1 + 2^-20) margin: r r (one operation), the differences (one),
    // their squares, two sums, and the final difference.
    constexpr double ku = 6 * (1.0 / 9007199254740992.0);
    constexpr double gamma = ku / (1.0 - ku) * (1.0 + 0x1p-20);
    constexpr double c_min = 0x1p-1020; // each product's permanent carries it (filtered.cppm)
    const V g = hn::Set(d, gamma), trusted = hn::Set(d, 0x1p-900), tiny = hn::Set(d, c_min);
    const V c[3] = {hn::Set(d, center[0]), hn::Set(d, center[1]), hn::Set(d, center[2])};
    const V r = hn::Set(d, radius);
    const double abs_r = radius < 0 ? -radius : radius;
    const double p_rr = abs_r * abs_r + c_min;
    const V p_r2 = hn::Set(d, p_rr);
    constexpr std::size_t block = 64;
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const points_at at = all.from(start);
        // the block's largest |p_k - c_k| (a NaN counts as infinite)
        V most[3] = {hn::Zero(d), hn::Zero(d), hn::Zero(d)};
        over_points(d, at, m, [&](V x, V y, V z, std::size_t, std::size_t) {
            const V a[3] = {hn::Abs(hn::Sub(x, c[0])), hn::Abs(hn::Sub(y, c[1])), hn::Abs(hn::Sub(z, c[2]))};
            for (int k = 0; k < 3; ++k) most[k] = max_counting_nan(d, most[k], a[k]);
        });
        double m3[3];
        for (int k = 0; k < 3; ++k) m3[k] = hn::GetLane(hn::MaxOfLanes(d, most[k]));
        const double p_dot = ((m3[0] * m3[0] + c_min) + (m3[1] * m3[1] + c_min)) + (m3[2] * m3[2] + c_min);
        const double b = gamma * (p_rr + p_dot);
        const V bound = hn::Set(d, b < 0x1p-900 ? 0x1p-900 : b); // NaN stays NaN: nothing passes it
        over_points(d, at, m, [&](V x, V y, V z, std::size_t lane, std::size_t count) {
            const V dx = hn::Sub(x, c[0]), dy = hn::Sub(y, c[1]), dz = hn::Sub(z, c[2]);
            const V v = power(r, dx, dy, dz);
            const M up = hn::Gt(v, bound), down = hn::Lt(v, hn::Neg(bound));
            if (hn::AllTrue(d, hn::Or(hn::Or(up, down), hn::Not(hn::FirstN(d, count))))) {
                store_answers(d, up, out + start + lane, count);
                return;
            }
            // each lane's own bound: the permanent as filtered.cppm's operations build it
            auto sq = [&](V a) { return hn::Add(hn::Mul(hn::Abs(a), hn::Abs(a)), tiny); };
            const V p = hn::Add(p_r2, hn::Add(hn::Add(sq(dx), sq(dy)), sq(dz)));
            const V own = hn::Mul(g, p);
            const M ok = hn::Ge(p, trusted);
            const M pos = hn::And(ok, hn::Gt(v, own)), neg = hn::And(ok, hn::Lt(v, hn::Neg(own)));
            store_answers(d, pos, hn::Not(hn::Or(pos, neg)), out + start + lane, count);
        });
    }
}

// The four volumes' values (w3 = c.d2, w2 = c.d3, w1 = d0.e, w0 = d1.e; the signs v3 = sgn w3,
// v2 = -sgn w2, v1 = sgn w1, v0 = -sgn w0) over any number type, from d_i = v_i - p.
template <class T>
struct four {
    T w3, w2, w1, w0;
};
template <class T>
HWY_INLINE four<T> volumes(const vec<T>* dv) {
    const vec<T> c = cross(dv[0], dv[1]), e = cross(dv[2], dv[3]);
    return {dot(c, dv[2]), dot(c, dv[3]), dot(dv[0], e), dot(dv[1], e)};
}
// Whether the point is inside from the four signs' masks (positive / negative: proven or plain
// signs of w_k): decided where c.d2 and -(c.d3) are opposite nonzero (outside), or where all four
// are nonzero (`known`); the answer where decided.
struct verdict {
    M decided, inside;
};
template <class Pos, class Neg>
HWY_INLINE verdict from_volumes(const Pos& pos, const Neg& neg, M known) {
    // v_k positive / negative: w3 and w1 as they are, w2 and w0 negated
    const M up[4] = {neg(0), pos(1), neg(2), pos(3)}, down[4] = {pos(0), neg(1), pos(2), neg(3)};
    const M early = hn::Or(hn::And(up[3], down[2]), hn::And(down[3], up[2]));
    const M all_up = hn::And(hn::And(up[0], up[1]), hn::And(up[2], up[3]));
    const M all_down = hn::And(hn::And(down[0], down[1]), hn::And(down[2], down[3]));
    return {hn::Or(early, known), hn::And(hn::Not(early), hn::Or(all_up, all_down))};
}
HWY_INLINE M within(D d, const V* lo, const V* hi, V x, V y, V z) {
    (void)d;
    return hn::And(hn::And(hn::And(hn::Le(lo[0], x), hn::Le(x, hi[0])), hn::And(hn::Le(lo[1], y), hn::Le(y, hi[1]))),
                   hn::And(hn::Le(lo[2], z), hn::Le(z, hi[2])));
}
// The tetrahedron's vertices t[3 i + k] and its bounding box, broadcast.
struct tetrahedron_lanes {
    V v[4][3], lo[3], hi[3];
    tetrahedron_lanes(D d, const double* t) {
        for (int k = 0; k < 3; ++k) {
            double a = t[k], b = t[k];
            for (int i = 0; i < 4; ++i) {
                v[i][k] = hn::Set(d, t[3 * i + k]);
                a = t[3 * i + k] < a ? t[3 * i + k] : a;
                b = t[3 * i + k] > b ? t[3 * i + k] : b;
            }
            lo[k] = hn::Set(d, a), hi[k] = hn::Set(d, b);
        }
    }
    // d_i = v_i - p, differences of inputs
    void differences(V x, V y, V z, vec<fv>* dv) const {
        for (int i = 0; i < 4; ++i) dv[i] = {exact_difference(v[i][0], x), exact_difference(v[i][1], y), exact_difference(v[i][2], z)};
    }
};

void tetrahedron_points_approximate(const double* t, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out) {
    const D d;
    const points_at at{{coords[0], coords[1], coords[2]}, xyz};
    const tetrahedron_lanes tl(d, t);
    const V zero = hn::Zero(d);
    over_points(d, at, n, [&](V x, V y, V z, std::size_t lane, std::size_t count) {
        const M in_box = within(d, tl.lo, tl.hi, x, y, z);
        vec<fv> df[4];
        tl.differences(x, y, z, df);
        const vec<pv> dv[4] = {values(df[0]), values(df[1]), values(df[2]), values(df[3])};
        const four<pv> w = volumes(dv);
        const V ws[4] = {w.w0.v, w.w1.v, w.w2.v, w.w3.v};
        auto pos = [&](int k) { return hn::Gt(ws[k], zero); };
        auto neg = [&](int k) { return hn::Lt(ws[k], zero); };
        // the scalar reads the signs as they are, zeros skipped: some nonzero one decides
        const M some =
            hn::Or(hn::Or(hn::Or(pos(0), neg(0)), hn::Or(pos(1), neg(1))), hn::Or(hn::Or(pos(2), neg(2)), hn::Or(pos(3), neg(3))));
        const M up_seen = hn::Or(hn::Or(neg(0), pos(1)), hn::Or(neg(2), pos(3)));
        const M down_seen = hn::Or(hn::Or(pos(0), neg(1)), hn::Or(pos(2), neg(3)));
        const M inside = hn::And(hn::And(in_box, some), hn::Not(hn::And(up_seen, down_seen)));
        store_answers(d, inside, hn::AndNot(some, in_box), out + lane, count);
    });
}

void tetrahedron_points_filter(const double* t, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out) {
    const D d;
    const points_at all{{coords[0], coords[1], coords[2]}, xyz};
    const tetrahedron_lanes tl(d, t);
    constexpr double gamma = gamma_of(8); // d_i: one operation; a product adds its operands' counts and one, a sum one
    // One static bound for every point the signs are evaluated for, those in the tetrahedron's box
    // [lo, hi]: there |v_ik - p_k| <= max(v_ik - lo_k, hi_k - v_ik), so (rounding being monotone)
    // each lane's |d_ik| is at most that maximum rounded, and so are its permanents and bounds.
    vec<pp> largest[4];
    for (int i = 0; i < 4; ++i) {
        double e[3];
        for (int k = 0; k < 3; ++k) {
            double lo = t[k], hi = t[k];
            for (int j = 1; j < 4; ++j) lo = t[3 * j + k] < lo ? t[3 * j + k] : lo, hi = t[3 * j + k] > hi ? t[3 * j + k] : hi;
            const double below = t[3 * i + k] - lo, above = hi - t[3 * i + k];
            e[k] = below > above ? below : above;
        }
        largest[i] = {{e[0]}, {e[1]}, {e[2]}};
    }
    const four<pp> permanent = volumes(largest);
    const V bound[4] = {static_bound(d, gamma, permanent.w0.p), static_bound(d, gamma, permanent.w1.p),
                        static_bound(d, gamma, permanent.w2.p), static_bound(d, gamma, permanent.w3.p)};
    over_points(d, all, n, [&](V x, V y, V z, std::size_t lane, std::size_t count) {
        const M in_box = within(d, tl.lo, tl.hi, x, y, z);
        const M counted = hn::And(in_box, hn::FirstN(d, count));
        vec<fv> df[4];
        tl.differences(x, y, z, df);
        const vec<pv> dv[4] = {values(df[0]), values(df[1]), values(df[2]), values(df[3])};
        const four<pv> w = volumes(dv);
        const V ws[4] = {w.w0.v, w.w1.v, w.w2.v, w.w3.v};
        auto pos = [&](int k) { return hn::Gt(ws[k], bound[k]); };
        auto neg = [&](int k) { return hn::Lt(ws[k], hn::Neg(bound[k])); };
        auto proven = [&](int k) { return hn::Or(pos(k), neg(k)); };
        const M known = hn::And(hn::And(proven(0), proven(1)), hn::And(proven(2), proven(3)));
        verdict v = from_volumes(pos, neg, known);
        if (!hn::AllTrue(d, hn::Or(v.decided, hn::Not(counted)))) { // the lanes' own bounds
            const four<fv> f = volumes(df);
            const fv fs[4] = {f.w0, f.w1, f.w2, f.w3};
            auto own_pos = [&](int k) { return own_positive(d, gamma, fs[k]); };
            auto own_neg = [&](int k) { return own_negative(d, gamma, fs[k]); };
            auto own_proven = [&](int k) { return hn::Or(own_pos(k), own_neg(k)); };
            v = from_volumes(own_pos, own_neg, hn::And(hn::And(own_proven(0), own_proven(1)), hn::And(own_proven(2), own_proven(3))));
        }
        // beyond the box: 0; in it: the verdict, or 2 where undecided
        store_answers(d, hn::And(in_box, v.inside), hn::AndNot(v.decided, in_box), out + lane, count);
    });
}

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(box_points);
HWY_EXPORT(sphere_points_approximate);
HWY_EXPORT(sphere_points_filter);
HWY_EXPORT(tetrahedron_points_approximate);
HWY_EXPORT(tetrahedron_points_filter);

// The entry points (declared extern "C++" in modules/batch/points.cppm).
void box_points(const double* box, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(box_points)(box, coords, xyz, n, out);
}
void sphere_points_approximate(const double* center, double radius, const double* const* coords, const double* xyz, std::size_t n,
                               std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(sphere_points_approximate)(center, radius, coords, xyz, n, out);
}
void sphere_points_filter(const double* center, double radius, const double* const* coords, const double* xyz, std::size_t n,
                          std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(sphere_points_filter)(center, radius, coords, xyz, n, out);
}
void tetrahedron_points_approximate(const double* t, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(tetrahedron_points_approximate)(t, coords, xyz, n, out);
}
void tetrahedron_points_filter(const double* t, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(tetrahedron_points_filter)(t, coords, xyz, n, out);
}
} // namespace incidence::batch::simd
#endif
