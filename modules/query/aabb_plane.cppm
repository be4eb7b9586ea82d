// aabb3 against plane3 (closed box; the plane n . p = offset; a zero normal is everything when
// the offset is 0 and nothing otherwise).
// Semantics: a plane touching a corner, an edge or a face counts.
// Method (exact tiers): the box corners extreme along n are picked by the signs of n's components;
// the plane meets the box iff n . lo <= offset <= n . hi, two signs of degree 2.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.2.3 (testing box against plane,
// with the extreme corners instead of the centre-radius form, so no rounded centre is compared).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a sign is within 2^-48 of its permanent
// (tests/query/aabb_plane.cpp).
export module incidence.query:aabb_plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::pair {

// sign(n . p - offset), degree 2.
template <class K>
[[nodiscard]] constexpr sign plane_side(K& k, const plane3& pl, point3 p) {
    const vec3 n = pl.normal;
    const double d = pl.offset;
    return k.sgn([=](auto L) { return arith::dot(arith::lift(L, n), arith::lift(L, p)) - L(d); });
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const plane3& pl) {
    if (!(b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z)) return false; // inverted or NaN box
    const vec3 n = pl.normal;
    const point3 lo{n.x >= 0.0 ? b.min.x : b.max.x, n.y >= 0.0 ? b.min.y : b.max.y, n.z >= 0.0 ? b.min.z : b.max.z};
    const point3 hi{n.x >= 0.0 ? b.max.x : b.min.x, n.y >= 0.0 ? b.max.y : b.min.y, n.z >= 0.0 ? b.max.z : b.min.z};
    return plane_side(k, pl, lo) != sign::positive && plane_side(k, pl, hi) != sign::negative;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const plane3&);
} // namespace incidence::pair
