// sphere3 against sphere3 (closed balls).
// Semantics: intersects iff |c1 - c2| <= r1 + r2 (tangent balls intersect);
// contains(a, b) iff ball b lies inside ball a: r_a >= r_b and |ca - cb| <= r_a - r_b
// (internally tangent counts; equal balls contain each other).
// Method: signs of (r1 + r2)^2 - |c1 - c2|^2 and of r_a - r_b, (r_a - r_b)^2 - |ca - cb|^2,
// homogeneous of degree 2. Unchecked negative radii: the formulas are evaluated as written.
// Source: Ericson, Real-Time Collision Detection (2005), section 4.3.1.
export module incidence.query:sphere_sphere;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const sphere3& a, const sphere3& b) {
    return k.sgn([=](auto L) {
        const auto d = arith::lift(L, a.center) - arith::lift(L, b.center);
        const auto r = L(a.radius) + L(b.radius);
        return r * r - arith::dot(d, d);
    }) != sign::negative;
}

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& a, const sphere3& b) {
    if (k.sgn([=](auto L) { return L(a.radius) - L(b.radius); }) == sign::negative) return false;
    return k.sgn([=](auto L) {
        const auto d = arith::lift(L, a.center) - arith::lift(L, b.center);
        const auto r = L(a.radius) - L(b.radius);
        return r * r - arith::dot(d, d);
    }) != sign::negative;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const sphere3&, const sphere3&);
extern template bool contains(arith::exact_kernel&, const sphere3&, const sphere3&);
} // namespace incidence::pair
