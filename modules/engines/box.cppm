// aabb3 against aabb3: intersects, contains, and covers(a, b, c): does a u b contain c?
// Semantics: closed boxes; touching faces, edges or corners intersect; a box contains itself.
// Method: coordinate comparisons, exact in binary64, so every tier returns the exact answer.
// covers: c is covered iff c lies in a, or the closure of c \ a (at most six slabs
// c n {x_i <= a.min_i}, c n {x_i >= a.max_i}) lies in b. A flat c (min == max on an axis) is
// handled the same way. Inverted (unchecked) boxes are empty sets for `covers`' c.
// Source: Ericson, Real-Time Collision Detection (2005), section 4.2 (AABB overlap).
//
// aabb3 against tetrahedron3 (closed box; closed solid tetrahedron, coplanar vertices give their
// hull), contains(box, tetrahedron) and contains(tetrahedron, box).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): the box's three face normals first (all four vertices beyond one box
// face: no; a vertex in the box: yes; coordinate comparisons), then a box corner inside the
// solid says yes, all eight strictly beyond one face plane say no (orient3d signs, degree 3);
// otherwise the box meets the tetrahedron iff it meets
// one of its four faces (the 13-axis aabb_triangle test), since it cannot then lie inside.
// contains: every vertex of the inner shape inside the outer one (coordinate comparisons for the
// box, orient3d signs for the tetrahedron).
// At run time the filter pass first tries the 25 separating axes (3 box normals, 4 face normals,
// 6 edges x 3 box axes) rounded, each widened by a proven error bound
// (box_triangle_detail::rounded_hull_axes_decide); the signs above decide what that leaves.
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Akenine-Moeller,
// "Fast 3D triangle-box overlap testing", JGT 6(1), 2001 for the face tests; Gottschalk, Lin and
// Manocha, "OBBTree", SIGGRAPH 1996, section 5 (the separating axis theorem).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_tetrahedron.cpp).
//
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
//
// aabb3 against line3 (closed box, the whole line; a zero direction is the point `origin`).
// Semantics: touching a face, an edge or a corner counts.
// Method (exact tiers): the slab method over all real t, its quotient comparisons rewritten as
// signs of products (see slabs in aabb_ray): degree 2 for each pair of axes.
// Source: Kay and Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (slabs).
// Approximate tier: the same slab test in plain double with reciprocal directions and no t >= 0
// bound. Error bound: for inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when
// some pairwise slab sign is within 2^-40 of its permanent (tests/query/aabb_line.cpp).
//
// aabb3 against segment3 (closed box, closed segment; a segment with equal end points is a point).
// Semantics: touching a face, an edge or a corner counts.
// Method (exact tiers): the slab method on t in [0, 1] with d = b - a taken exactly from the end
// points, its quotient comparisons rewritten as signs of products (see slabs in aabb_ray): degree
// 2 for each pair of axes, coordinate comparisons for the rest. Seen as a separating-axis test
// these are the six axes of the segment-box test (three box normals, three box axis x segment).
// Source: Kay and Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (slabs); Ericson, Real-Time
// Collision Detection (2005), section 5.3.3 (segment-box, the six axes).
// Approximate tier: the same slab test in plain double with reciprocal directions. Error bound:
// for inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when some pairwise slab
// sign or end-point comparison is within 2^-40 of its permanent (tests/query/aabb_segment.cpp).
module;
#include <optional>
export module incidence.detail:engines.box;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.tetrahedron;

export namespace incidence::detail {

[[nodiscard]] constexpr bool box_inside(const double (&lo)[3], const double (&hi)[3], const aabb3& b) {
    return b.min.x <= lo[0] && hi[0] <= b.max.x && b.min.y <= lo[1] && hi[1] <= b.max.y && b.min.z <= lo[2] && hi[2] <= b.max.z;
}

[[nodiscard]] constexpr bool covers(const aabb3& a, const aabb3& b, const aabb3& c) {
    const double cmin[3] = {c.min.x, c.min.y, c.min.z};
    const double cmax[3] = {c.max.x, c.max.y, c.max.z};
    const double amin[3] = {a.min.x, a.min.y, a.min.z};
    const double amax[3] = {a.max.x, a.max.y, a.max.z};
    for (int i = 0; i < 3; ++i)
        if (!(cmin[i] <= cmax[i])) return true; // c is empty (or NaN): trivially covered
    for (int i = 0; i < 3; ++i) {
        // below a on axis i: c n {x_i <= a.min_i}, nonempty part only if c.min_i < a.min_i
        if (cmin[i] < amin[i]) {
            double lo[3] = {cmin[0], cmin[1], cmin[2]};
            double hi[3] = {cmax[0], cmax[1], cmax[2]};
            if (amin[i] < hi[i]) hi[i] = amin[i];
            if (!box_inside(lo, hi, b)) return false;
        }
        // above a on axis i: c n {x_i >= a.max_i}
        if (cmax[i] > amax[i]) {
            double lo[3] = {cmin[0], cmin[1], cmin[2]};
            double hi[3] = {cmax[0], cmax[1], cmax[2]};
            if (amax[i] > lo[i]) lo[i] = amax[i];
            if (!box_inside(lo, hi, b)) return false;
        }
    }
    return true;
}

// A box is a set when its bounds are ordered finite numbers (an inverted box is empty).
[[nodiscard]] constexpr bool well_formed_finite(const aabb3& b) {
    return b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z && finite(b.min) && finite(b.max);
}
struct box_corners {
    point3 p[8];
    constexpr explicit box_corners(const aabb3& b) : p{} {
        for (int i = 0; i < 8; ++i) p[i] = point3{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
    }
};
// A point of the box near its middle: each coordinate (min + max) / 2 rounded, clamped into
// [min, max] (the rounding of a tiny or huge bound may leave it), so exactly a point of the box.
[[nodiscard]] constexpr point3 middle_in(const aabb3& b) {
    auto mid = [](double lo, double hi) {
        const double c = 0.5 * lo + 0.5 * hi;
        return c < lo ? lo : (c > hi ? hi : c);
    };
    return {mid(b.min.x, b.max.x), mid(b.min.y, b.max.y), mid(b.min.z, b.max.z)};
}
// The box corner least along n (where a component of n is zero, either bound would do).
[[nodiscard]] constexpr point3 least_corner(const aabb3& b, const vec3& n) {
    return {n.x > 0 ? b.min.x : b.max.x, n.y > 0 ? b.min.y : b.max.y, n.z > 0 ? b.min.z : b.max.z};
}

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

// The slab test on rounded slab parameters where its answer is clear, before any sign: yes the sets
// meet, no they do not, uncertain too close to call (or a direction component outside [2^-1000, 2^1000]).
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
[[nodiscard]] constexpr certainty slab_parameters_decide(const aabb3& b, point3 o, vec3 dv, point3 e) {
    const double oc[3] = {o.x, o.y, o.z}, dc[3] = {dv.x, dv.y, dv.z}, ec[3] = {e.x, e.y, e.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    double near_lo = X == slab_extent::line ? -__builtin_huge_val() : 0.0, near_hi = near_lo;
    double far_lo = X == slab_extent::segment ? 1.0 : __builtin_huge_val(), far_hi = far_lo;
    bool ordered = true;
    for (int i = 0; i < 3; ++i) {
        const double d = X == slab_extent::segment ? ec[i] - oc[i] : dc[i];
        const double ad = arith::abs(d);
        if (!(ad >= 0x1p-1000 && ad <= 0x1p1000)) return certainty::uncertain;
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
        if (near_lo > far_hi) return certainty::no; // the slabs so far have no common t: most misses end here
    }
    return ordered && near_hi <= far_lo ? certainty::yes : certainty::uncertain;
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
        if (const certainty r = slab_parameters_decide<X>(b, o, dv, e); r != certainty::uncertain) return r == certainty::yes;
    return slab_signs<X>(k, b, o, dv, e);
}

// Classic slab method in plain double (approximate tier).
[[nodiscard]] constexpr std::optional<span_hit<double>> aabb_ray_slab(const aabb3& b, const ray3& r) {
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
    return span_hit<double>{t0, t1, r.at(t0), certainty::uncertain};
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
        if (o[i] < mn[i]) {
            cand[i] = mn[i];
            middle[i] = false;
            inside = false;
        } else if (o[i] > mx[i]) {
            cand[i] = mx[i];
            middle[i] = false;
            inside = false;
        }
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

// The slab method in plain double over all t (approximate tier).
[[nodiscard]] constexpr bool aabb_line_slab(const aabb3& b, const line3& l) {
    double t0 = -__builtin_huge_val(), t1 = __builtin_huge_val();
    for (int i = 0; i < 3; ++i) {
        const slab_axis a = slab_of(b, ray3{l.origin, l.direction}, i);
        if (a.d == 0.0) {
            if (!(a.near_plane <= a.o && a.o <= a.far_plane)) return false;
            continue;
        }
        const double inv = 1.0 / a.d;
        const double tn = (a.near_plane - a.o) * inv, tf = (a.far_plane - a.o) * inv;
        if (tn > t0) t0 = tn;
        if (tf < t1) t1 = tf;
        if (!(t0 <= t1)) return false;
    }
    return true;
}

// The slab method in plain double on [0, 1] (approximate tier).
[[nodiscard]] constexpr bool aabb_segment_slab(const aabb3& b, const segment3& s) {
    const auto h = aabb_ray_slab(b, ray3{s.a, s.b - s.a});
    return h.has_value() && h->t_enter <= 1.0;
}

} // namespace incidence::detail
