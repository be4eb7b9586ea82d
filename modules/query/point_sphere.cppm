// point3 against sphere3 (the closed ball).
// Semantics: the point intersects the ball iff |p - c| <= r (on the sphere counts).
// Method: sign of r^2 - |p - c|^2, a homogeneous degree-2 polynomial: one filtered evaluation,
// exact fallback through the kernel. Unchecked negative radii act as |r| (r enters squared);
// make() refuses them.
// Source: Ericson, Real-Time Collision Detection (2005), section 4.3 (sphere tests).
export module incidence.query:point_sphere;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const sphere3& s) {
    return k.sgn([=](auto L) {
        const auto d = arith::lift(L, p) - arith::lift(L, s.center);
        const auto r = L(s.radius);
        return r * r - arith::dot(d, d);
    }) != sign::negative;
}

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const point3& p) {
    return intersects(k, p, s);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const point3&, const sphere3&);
extern template bool contains(arith::exact_kernel&, const sphere3&, const point3&);
} // namespace incidence::pair
