// contains(obb3, sphere3) and contains(sphere3, obb3): a closed box (the parallelepiped its axes
// span, read exactly as given) and a closed ball.
// Semantics: a ball touching the box's faces from inside lies in it; a box whose corners touch the
// sphere from inside lies in the ball. Unchecked negative radii act as |r|; NaN, infinite or
// negative extents hold nothing and lie in nothing.
// Method (exact tiers): the ball in the box: with the face normals n_i = a_j x a_k and
// det = n_i . a_i, the centre's distance to the two faces of slab i is (h_i |det| - |n_i . (c - o)|)
// / |n_i|, so each slab asks A_i = h_i |det| - |n_i . (c - o)| >= 0 (degree 4) and
// A_i^2 >= r^2 |n_i|^2 (degree 8); dependent axes (det = 0) hold a ball only of radius 0, a point.
// The box in the ball: its eight corners o + sum +-h_j a_j, each |corner - c|^2 <= r^2 (degree 4).
// Source: Ericson, Real-Time Collision Detection (2005), sections 4.4 and 5.2.5 (the distance to
// a box face; sphere containment by its centre's distance), here squared so that nothing is a root.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500] and whose signs' permanents stay within [2^-900, 2^900] (the
// degree-8 sign overflows past coordinates of about 2^110), wrong only when a deciding sign is
// within 2^-40 of its permanent (tests/query/obb_sphere.cpp).
export module incidence.query:obb_sphere;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :separating_axes;
import :obb_point;
import :obb_tetrahedron;
import :aabb_sphere;

export namespace incidence::pair {

// Is the ball inside the box?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& b, const sphere3& s) {
    if (!sat::well_formed(b) || !finite(b) || !ball::usable(s)) return false;
    if (s.radius == 0.0) return contains(k, b, s.center);
    const vec3 a[3] = {b.axes[0], b.axes[1], b.axes[2]};
    if (arith::is_zero(k, [=](auto L) { return arith::det3(arith::lift(L, a[0]), arith::lift(L, a[1]), arith::lift(L, a[2])); }))
        return false; // a flat box
    const point3 o = b.center, c = s.center;
    const double r = s.radius;
    for (unsigned i = 0; i < 3; ++i) {
        const vec3 ai = a[i], aj = a[(i + 1) % 3], ak = a[(i + 2) % 3];
        const double h = b.half_extents[i];
        auto room = [=](auto L) { // A_i = h_i |det| - |n_i . (c - o)|
            const auto n = arith::cross(arith::lift(L, aj), arith::lift(L, ak));
            return L(h) * sat::magnitude(arith::dot(n, arith::lift(L, ai))) - L(1.0) * sat::magnitude(arith::dot(n, arith::lift(L, c) - arith::lift(L, o)));
        };
        if (k.sgn(room) == sign::negative) return false;
        if (k.sgn([=](auto L) {
                const auto n = arith::cross(arith::lift(L, aj), arith::lift(L, ak));
                const auto A = room(L);
                const auto one = L(1.0);
                return A * A - L(r) * L(r) * (one * one) * arith::dot(n, n);
            }) == sign::negative)
            return false;
    }
    return true;
}

// Is the box inside the ball?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const obb3& b) {
    if (!sat::well_formed(b) || !finite(b) || !ball::usable(s)) return false;
    const point3 o = b.center, c = s.center;
    const double r = s.radius;
    for (int m = 0; m < 8; ++m) {
        double f[3]; // the corner's signed extents
        for (unsigned j = 0; j < 3; ++j) f[j] = (m >> j & 1) ? b.half_extents[j] : -b.half_extents[j];
        const vec3 a0 = b.axes[0], a1 = b.axes[1], a2 = b.axes[2];
        if (k.sgn([=](auto L) {
                const auto one = L(1.0);
                const auto d = arith::lift(L, o) - arith::lift(L, c);
                const auto x = one * d.x + L(f[0]) * L(a0.x) + L(f[1]) * L(a1.x) + L(f[2]) * L(a2.x);
                const auto y = one * d.y + L(f[0]) * L(a0.y) + L(f[1]) * L(a1.y) + L(f[2]) * L(a2.y);
                const auto z = one * d.z + L(f[0]) * L(a0.z) + L(f[1]) * L(a1.z) + L(f[2]) * L(a2.z);
                return L(r) * L(r) * (one * one) - (x * x + y * y + z * z);
            }) == sign::negative)
            return false;
    }
    return true;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool contains(arith::exact_kernel&, const obb3&, const sphere3&);
extern template bool contains(arith::exact_kernel&, const sphere3&, const obb3&);
} // namespace incidence::pair
