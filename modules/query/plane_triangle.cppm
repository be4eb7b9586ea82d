// plane3 against triangle3 (the plane n . p = offset; a closed triangle, a collinear one is its
// hull). Semantics: a vertex on the plane counts.
// Method (exact tiers): the signs of n . v - offset at the three vertices (degree 2); the
// triangle meets the plane iff they are not all strictly positive or all strictly negative.
// Source: Moeller, "A fast triangle-triangle intersection test", JGT 2(2), 1997, section 2 (the
// plane-rejection step: signed distances of the vertices), as signs.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a sign is within 2^-48 of its permanent
// (tests/query/plane_triangle.cpp).
export module incidence.query:plane_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_plane;
import :segment_segment;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const triangle3& t) {
    // An early yes leaves vertices unread: a NaN or infinite one makes no triangle.
    const sign sa = plane_side(k, pl, t.a);
    if (sa == sign::zero) return finite(t.b) && finite(t.c);
    const sign sb = plane_side(k, pl, t.b);
    if (sb != sa) return finite(t.c);
    return plane_side(k, pl, t.c) != sa;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const plane3&, const triangle3&);
} // namespace incidence::pair
