// aabb3 against sphere3 (closed box, closed ball): intersects, contains(aabb3, sphere3) and
// contains(sphere3, aabb3).
// Semantics: touching counts; a box contains a ball it touches from inside. Unchecked negative
// radii act as |r| (as in point_sphere); inverted, infinite or NaN input meets and holds nothing.
// Method (exact tiers): intersects: the box's point nearest the centre, chosen per axis by
// coordinate comparisons, then the sign of r^2 - sum of the squared gaps (degree 2). The ball in
// the box: c_i - |r| >= min_i and c_i + |r| <= max_i (six signs of degree 1). The box in the ball:
// the corner farthest from the centre, chosen per axis by the sign of 2 c_i - min_i - max_i, then
// the sign of r^2 - |corner - c|^2 (degree 2).
// Source: Arvo, "A simple method for box-sphere intersection testing", Graphics Gems (1990);
// Ericson, Real-Time Collision Detection (2005), section 5.2.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_sphere.cpp).
//
// ray3 against sphere3 (closed ball): intersects, and intersection = the first point with t >= 0.
// Semantics: a ray that starts inside or on the ball hits at t = 0; a ray tangent to the sphere
// hits at the tangent point; a zero direction is the point `origin`.
// Method (exact tiers): with m = o - c, a = d.d, b = m.d, c' = m.m - r^2:
//   c' <= 0            -> hit at t = 0 (origin in the ball)
//   b >= 0             -> miss (outside, not approaching)
//   b^2 - a c' >= 0    -> hit at t1 = (-b - sqrt(b^2 - a c')) / a
// signs of homogeneous polynomials of degree 2, 2 and 4. The exact tier's t and point are
// correctly rounded by bracketing t1 between midpoints with exact comparisons:
//   t1 <= p/q (q > 0)  <=>  a p + b q >= 0  or  a p^2 + 2 b p q + c' q^2 <= 0.
// Approximate tier: the optimized geometric method with early rejections, Akenine-Moller et al.,
// Real-Time Rendering 4th ed. (2018), section 22.6.2; the algebraic quadratic is kept as
// method::ray_sphere_algebraic (Ericson, Real-Time Collision Detection, section 5.3.2).
// Error bound (approximate), nonzero input magnitudes in [2^-500, 2^500]: wrong only when one
// of the three signs above is within 2^-40 of its permanent, i.e. the ray passes within that
// relative distance of the silhouette or starts that close to the sphere (checked by tests).
module;
#include <optional>
export module incidence.detail:engines.sphere;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;

export namespace incidence::detail {

namespace ball {
[[nodiscard]] constexpr bool usable(const aabb3& b) {
    return finite(b.min) && finite(b.max) && b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z;
}
[[nodiscard]] constexpr bool usable(const sphere3& s) { return finite(s.center) && finite(s.radius); }
[[nodiscard]] constexpr double magnitude(double r) { return r < 0.0 ? -r : r; }
} // namespace ball

// Optimized geometric method (RTR4 22.6.2) in plain double; the direction is normalised.
[[nodiscard]] constexpr std::optional<span_hit<double>> ray_sphere_geometric(const ray3& r, const sphere3& s) {
    const vec3 l = s.center - r.origin;
    const double r2 = s.radius * s.radius;
    const double l2 = dot(l, l);
    const double a = dot(r.direction, r.direction);
    const bool inside = l2 <= r2;
    if (!(a > 0.0))
        return inside ? std::optional{span_hit<double>{0.0, __builtin_huge_val(), r.origin, certainty::uncertain}} : std::nullopt;
    const double len = arith::sqrt(a);
    const double sproj = dot(l, r.direction) / len;
    if (!inside && sproj < 0.0) return std::nullopt; // outside and pointing away
    const double m2 = l2 - sproj * sproj;
    if (m2 > r2) return std::nullopt; // passes beside the sphere
    const double q = arith::sqrt(r2 - m2);
    const double t = inside ? 0.0 : (sproj - q) / len;
    return span_hit<double>{t, (sproj + q) / len, r.at(t), certainty::uncertain};
}

// Algebraic method: solve a t^2 + 2 b t + c = 0 with the numerically stable root formula.
[[nodiscard]] constexpr std::optional<span_hit<double>> ray_sphere_algebraic(const ray3& r, const sphere3& s) {
    const vec3 m = r.origin - s.center;
    const double c = dot(m, m) - s.radius * s.radius;
    const double b = dot(m, r.direction);
    const double a = dot(r.direction, r.direction);
    if (c <= 0.0) { // inside: enters at 0, leaves at the larger root
        const double disc = b * b - a * c;
        const double exit = a > 0.0 ? (b < 0.0 ? (-b + arith::sqrt(disc)) / a : c / (-b - arith::sqrt(disc))) : __builtin_huge_val();
        return span_hit<double>{0.0, exit, r.origin, certainty::uncertain};
    }
    if (b >= 0.0) return std::nullopt;
    const double disc = b * b - a * c;
    if (disc < 0.0) return std::nullopt;
    const double root = arith::sqrt(disc);
    const double t = c / (-b + root);
    return span_hit<double>{t, (-b + root) / a, r.at(t), certainty::uncertain};
}

} // namespace incidence::detail
