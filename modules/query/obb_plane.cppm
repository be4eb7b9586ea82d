// obb3 against plane3 (closed box read as the parallelepiped its axes span; the plane
// n . p = offset, a zero normal is everything when the offset is 0 and nothing otherwise).
// Semantics: a plane touching a corner, an edge or a face counts.
// Method (exact tiers): the plane meets the box iff |n . 2c - 2 offset| <= sum 2 h_i |n . a_i|,
// one sign of degree 3 (a lifted 1.0 balances the degrees; no rounded centre or radius).
// Source: Ericson, Real-Time Collision Detection (2005), section 5.2.3 (testing box against plane).
// Approximate tier: the same sign in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when the sign is within 2^-48 of its permanent;
// tests/query/obb_plane.cpp checks it.
export module incidence.query:obb_plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& b, const plane3& pl) {
    if (!sat::well_formed(b)) return false;
    const sat::zonotope z = sat::of(b);
    const vec3 n = pl.normal;
    const double d = pl.offset;
    return k.sgn([=](auto L) {
               const auto w = arith::lift(L, n);
               return L(1.0) * sat::magnitude(arith::dot(w, sat::centre2(L, z)) - L(1.0) * (L(d) + L(d))) - sat::radius2(L, z, w);
           }) != sign::positive;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const plane3&);
} // namespace incidence::pair
