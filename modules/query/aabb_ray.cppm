// aabb3 against ray3: intersects, and intersection = the parameter interval [t_enter, t_exit]
// of the ray inside the box (t_enter >= 0).
// Semantics: closed box; a ray grazing a face, an edge or a corner hits; a ray lying in a face
// plane hits when it meets the face; a zero direction is the point `origin`.
// Method (exact tiers): the slab method with its comparisons of quotients rewritten as signs
// of products. Per axis i with d_i != 0 the ray is in the slab for t in [L_i/d_i, U_i/d_i]
// (L, U the near and far plane minus o_i); with d_i == 0 the origin must lie in the slab.
// The ray hits iff every U_j/d_j >= 0 and every L_i/d_i <= U_j/d_j, i.e.
//   sign(U_j d_i - L_i d_j) * sign(d_i d_j) >= 0,
// a homogeneous degree-2 sign per ordered pair of axes. Before any sign, the classic slab
// parameters rounded, each widened by a rigorous error bound, decide every case where they are
// clear (slab_parameters_decide). t_enter/t_exit of the exact tier are
// the max/min of correctly rounded quotients (rounding is monotone, so max of rounded = rounded
// max): correctly rounded.
// Approximate tier: the classic slab method with reciprocal directions (Kay and Kajiya,
// SIGGRAPH 1986; robust form of Williams et al., JGT 10(1), 2005). Woo's method
// (Graphics Gems, 1990, "Fast Ray-Box Intersection") is kept as method::aabb_ray_woo.
// Error bound (approximate slab): for inputs whose nonzero magnitudes lie in [2^-500, 2^500],
// wrong only when some pairwise slab sign U_j d_i - L_i d_j is within 2^-40 of its permanent
// (the ray grazes the box). Woo's method is weaker: it compares a rounded hit point with the
// face bounds, so it can also fail when the ray enters through an edge or corner and then
// runs deep inside; its bound adds the ray's relative distance 2^-40 to each edge line
// (tests/query/aabb_ray.cpp measures both).
module;
#include <optional>
export module incidence.query:aabb_ray;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence {

struct aabb_ray_hit {
    double t_enter; // >= 0: the first parameter inside the box
    double t_exit;  // the last parameter inside the box (may be +infinity only for d == 0)
};

} // namespace incidence

export namespace incidence::pair {

struct slab_axis {
    double o, d, near_plane, far_plane;
};
[[nodiscard]] constexpr slab_axis slab_of(const aabb3& b, const ray3& r, int i) {
    const double o = i == 0 ? r.origin.x : (i == 1 ? r.origin.y : r.origin.z);
    const double d = i == 0 ? r.direction.x : (i == 1 ? r.direction.y : r.direction.z);
    const double mn = i == 0 ? b.min.x : (i == 1 ? b.min.y : b.min.z);
    const double mx = i == 0 ? b.max.x : (i == 1 ? b.max.y : b.max.z);
    return d < 0.0 ? slab_axis{o, d, mx, mn} : slab_axis{o, d, mn, mx};
}

// The slab test as signs, shared by the box's linear pairs (aabb_ray, aabb_segment, aabb_line). The
// parameter runs over t >= 0 (ray), [0, 1] (segment, direction e - o taken exactly from its end
// points) or all reals (line). Per axis with d_i != 0 the object is inside the slab for t between
// L_i/d_i and U_i/d_i; the sets meet iff every near bound is <= every far bound, the far bounds
// are >= 0 (ray, segment) and the near bounds are <= 1 (segment): as signs, degree 2 for the
// pairs of axes, comparisons of coordinates for the rest. Non-finite input: no.
enum class slab_extent { ray, segment, line };

// The slab test on rounded slab parameters where its answer is clear, before any sign: 1 the sets
// meet, 0 they do not, -1 too close to call (or a direction component outside [2^-1000, 2^1000]).
// Per axis t = (P - o) * (1 / d) is Kay and Kajiya's slab parameter (SIGGRAPH 1986); rounded it is
// within 4u|t| + 2^-1074 of the exact value (d = e - o rounded for a segment, its reciprocal, P - o
// and the product: four roundings, the last one possibly subnormal), and the interval
// t -+ (2^-50 |t| + 2^-1060) also covers the rounding of its own end points. The sets meet iff
// max(near t) <= min(far t), with 0 <= min(far t) for a ray or segment and max(near t) <= 1 for a
// segment; a miss is known as soon as the slabs of the axes so far are disjoint in t (as in the
// classic method's early exit). A non-finite input gives an infinite or NaN t: an infinite t has
// one NaN end point, a NaN coordinate makes its axis's interval empty, and NaN compares false, so
// such an input is never called a hit (a miss is its right answer). An inverted box is never
// called a hit. Run time only: constant evaluation refuses the NaN an overflow can make.
template <slab_extent X>
[[nodiscard]] constexpr int slab_parameters_decide(const aabb3& b, point3 o, vec3 dv, point3 e) {
    const double oc[3] = {o.x, o.y, o.z}, dc[3] = {dv.x, dv.y, dv.z}, ec[3] = {e.x, e.y, e.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    double near_lo = X == slab_extent::line ? -__builtin_huge_val() : 0.0, near_hi = near_lo;
    double far_lo = X == slab_extent::segment ? 1.0 : __builtin_huge_val(), far_hi = far_lo;
    bool ordered = true;
    for (int i = 0; i < 3; ++i) {
        const double d = X == slab_extent::segment ? ec[i] - oc[i] : dc[i];
        const double ad = arith::abs(d);
        if (!(ad >= 0x1p-1000 && ad <= 0x1p1000)) return -1;
        const double inv = 1.0 / d;
        const double t1 = (mn[i] - oc[i]) * inv, t2 = (mx[i] - oc[i]) * inv;
        const double tn = d > 0.0 ? t1 : t2, tf = d > 0.0 ? t2 : t1;
        const double en = 0x1p-50 * arith::abs(tn) + 0x1p-1060, ef = 0x1p-50 * arith::abs(tf) + 0x1p-1060;
        const double nl = tn - en, nh = tn + en, fl = tf - ef, fh = tf + ef;
        // a NaN lower end of near t or upper end of far t is left out (the bound stays valid without
        // it); a NaN upper end of near t or lower end of far t is kept, so no hit is claimed
        near_lo = nl > near_lo ? nl : near_lo;
        near_hi = nh > near_hi || nh != nh ? nh : near_hi;
        far_lo = fl < far_lo || fl != fl ? fl : far_lo;
        far_hi = fh < far_hi ? fh : far_hi;
        ordered = ordered && mn[i] <= mx[i];
        if (near_lo > far_hi) return 0; // the slabs so far have no common t: most misses end here
    }
    return ordered && near_hi <= far_lo ? 1 : -1;
}

template <slab_extent X, class K>
[[nodiscard]] constexpr bool slab_signs(K& k, const aabb3& b, point3 o, vec3 dv, point3 e) {
    if (!is_finite(b.min) || !is_finite(b.max) || !is_finite(o) || !is_finite(dv) || !is_finite(e)) return false;
    const double oc[3] = {o.x, o.y, o.z}, dc[3] = {dv.x, dv.y, dv.z}, ec[3] = {e.x, e.y, e.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    sign s[3];
    double near[3], far[3];
    for (int i = 0; i < 3; ++i) {
        if (!(mn[i] <= mx[i])) return false; // inverted box
        s[i] = X == slab_extent::segment ? arith::compare(k, ec[i], oc[i]) : arith::compare(k, dc[i], 0.0);
        near[i] = s[i] == sign::negative ? mx[i] : mn[i];
        far[i] = s[i] == sign::negative ? mn[i] : mx[i];
        if (s[i] == sign::zero) { // parallel to the slab: the origin must lie in it
            if (arith::compare(k, oc[i], mn[i]) == sign::negative || arith::compare(k, oc[i], mx[i]) == sign::positive) return false;
            continue;
        }
        if constexpr (X != slab_extent::line) // U_i / d_i >= 0: the slab is not behind the origin
            if (arith::compare(k, far[i], oc[i]) == -s[i]) return false;
        if constexpr (X == slab_extent::segment) // L_i / d_i <= 1: the end point reaches the slab
            if (arith::compare(k, near[i], ec[i]) == s[i]) return false;
    }
    for (int i = 0; i < 3; ++i) {
        if (s[i] == sign::zero) continue;
        for (int j = 0; j < 3; ++j) {
            if (j == i || s[j] == sign::zero) continue;
            // L_i/d_i <= U_j/d_j  <=>  sign(U_j d_i - L_i d_j) * sign(d_i) * sign(d_j) >= 0
            const double oi = oc[i], oj = oc[j], ni = near[i], fj = far[j];
            sign v;
            if constexpr (X == slab_extent::segment) {
                const double ai = oc[i], bi = ec[i], aj = oc[j], bj = ec[j];
                v = k.sgn([=](auto L) { return (L(fj) - L(oj)) * (L(bi) - L(ai)) - (L(ni) - L(oi)) * (L(bj) - L(aj)); });
            } else {
                const double di = dc[i], dj = dc[j];
                v = k.sgn([=](auto L) { return (L(fj) - L(oj)) * L(di) - (L(ni) - L(oi)) * L(dj); });
            }
            if (v * s[i] * s[j] == sign::negative) return false;
        }
    }
    return true;
}

// The slab test: the rounded slab parameters first in a filter pass (arith::rounded_stage_applies),
// inline; the signs only where they were too close to call.
template <slab_extent X, class K>
[[nodiscard, gnu::always_inline]] constexpr bool slabs(K& k, const aabb3& b, point3 o, vec3 dv, point3 e) {
    if (arith::rounded_stage_applies<K>())
        if (const int r = slab_parameters_decide<X>(b, o, dv, e); r >= 0) return r == 1;
    return slab_signs<X>(k, b, o, dv, e);
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const ray3& r) {
    return slabs<slab_extent::ray>(k, b, r.origin, r.direction, r.origin);
}

// Classic slab method in plain double (approximate tier).
[[nodiscard]] constexpr std::optional<aabb_ray_hit> aabb_ray_slab(const aabb3& b, const ray3& r) {
    double t0 = 0.0, t1 = __builtin_huge_val();
    for (int i = 0; i < 3; ++i) {
        const slab_axis a = slab_of(b, r, i);
        if (a.d == 0.0) {
            if (!(a.near_plane <= a.o && a.o <= a.far_plane)) return std::nullopt;
            continue;
        }
        const double inv = 1.0 / a.d;
        const double tn = (a.near_plane - a.o) * inv;
        const double tf = (a.far_plane - a.o) * inv;
        if (tn > t0) t0 = tn;
        if (tf < t1) t1 = tf;
        if (!(t0 <= t1)) return std::nullopt; // also rejects NaN
    }
    return aabb_ray_hit{t0, t1};
}

// Woo's method: pick the candidate plane per axis from the origin's position, take the
// farthest candidate hit, then check the hit point against the other two slabs.
[[nodiscard]] constexpr bool aabb_ray_woo(const aabb3& b, const ray3& r) {
    const double o[3] = {r.origin.x, r.origin.y, r.origin.z};
    const double d[3] = {r.direction.x, r.direction.y, r.direction.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z};
    const double mx[3] = {b.max.x, b.max.y, b.max.z};
    bool inside = true;
    double cand[3] = {0, 0, 0};
    bool middle[3] = {true, true, true};
    for (int i = 0; i < 3; ++i) {
        if (o[i] < mn[i]) { cand[i] = mn[i]; middle[i] = false; inside = false; }
        else if (o[i] > mx[i]) { cand[i] = mx[i]; middle[i] = false; inside = false; }
    }
    if (inside) return true;
    double tmax[3] = {-1.0, -1.0, -1.0};
    for (int i = 0; i < 3; ++i)
        if (!middle[i] && d[i] != 0.0) tmax[i] = (cand[i] - o[i]) / d[i];
    int plane = 0;
    for (int i = 1; i < 3; ++i)
        if (tmax[i] > tmax[plane]) plane = i;
    if (!(tmax[plane] >= 0.0)) return false;
    for (int i = 0; i < 3; ++i) {
        if (i == plane) continue;
        const double p = o[i] + tmax[plane] * d[i];
        if (p < mn[i] || p > mx[i]) return false;
    }
    return true;
}

// Correctly rounded (num_a - num_b) / d.
[[nodiscard]] constexpr double rounded_quotient(double num_a, double num_b, double d) {
    const auto diff = arith::two_diff(num_a, num_b);
    if (diff.lo == 0.0 && is_finite(diff.hi)) return diff.hi / d; // IEEE division is correctly rounded
    return arith::quotient(arith::to_dyadic(num_a) - arith::to_dyadic(num_b), arith::to_dyadic(d));
}

[[nodiscard]] constexpr std::optional<aabb_ray_hit> aabb_ray_exact(const aabb3& b, const ray3& r) {
    // Called without a filter pass before it: the rounded slab parameters first here too.
    int fast = -1;
    if (!__builtin_is_constant_evaluated()) fast = slab_parameters_decide<slab_extent::ray>(b, r.origin, r.direction, r.origin);
    if (fast == 0) return std::nullopt;
    if (fast < 0) {
        arith::exact_kernel k;
        if (!intersects(k, b, r) || !k.valid) return std::nullopt;
    }
    double t0 = 0.0, t1 = __builtin_huge_val();
    for (int i = 0; i < 3; ++i) {
        const slab_axis a = slab_of(b, r, i);
        if (a.d == 0.0) continue;
        const double tn = rounded_quotient(a.near_plane, a.o, a.d);
        const double tf = rounded_quotient(a.far_plane, a.o, a.d);
        if (tn > t0) t0 = tn;
        if (tf < t1) t1 = tf;
    }
    return aabb_ray_hit{t0, t1};
}

} // namespace incidence::pair

export namespace incidence::pair {
// The approximate tier of intersects(aabb3, ray3) is the classic slab method.
[[nodiscard]] constexpr bool intersects_approximate(const aabb3& b, const ray3& r) { return aabb_ray_slab(b, r).has_value(); }
} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const ray3&);
} // namespace incidence::pair
