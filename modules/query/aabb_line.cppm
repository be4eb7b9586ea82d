// aabb3 against line3 (closed box, the whole line; a zero direction is the point `origin`).
// Semantics: touching a face, an edge or a corner counts.
// Method (exact tiers): the slab method over all real t, its quotient comparisons rewritten as
// signs of products (see slabs in aabb_ray): degree 2 for each pair of axes.
// Source: Kay and Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (slabs).
// Approximate tier: the same slab test in plain double with reciprocal directions and no t >= 0
// bound. Error bound: for inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when
// some pairwise slab sign is within 2^-40 of its permanent (tests/query/aabb_line.cpp).
export module incidence.query:aabb_line;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const line3& l) {
    return slabs<slab_extent::line>(k, b, l.origin, l.direction, l.origin);
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
[[nodiscard]] constexpr bool intersects_approximate(const aabb3& b, const line3& l) { return aabb_line_slab(b, l); }

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const line3&);
} // namespace incidence::pair
