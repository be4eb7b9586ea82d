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
export module incidence.query:ray_sphere;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence {

struct ray_sphere_hit {
    double t;     // ray parameter of the first point with t >= 0
    point3 point; // origin + t * direction
};

} // namespace incidence

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const sphere3& s) {
    const auto m_of = [=](auto L) { return arith::lift(L, r.origin) - arith::lift(L, s.center); };
    const sign c = k.sgn([=](auto L) {
        const auto m = m_of(L);
        const auto rr = L(s.radius);
        return arith::dot(m, m) - rr * rr;
    });
    if (c != sign::positive) return true;
    const sign b = k.sgn([=](auto L) { return arith::dot(m_of(L), arith::lift(L, r.direction)); });
    if (b != sign::negative) return false;
    return k.sgn([=](auto L) {
               const auto m = m_of(L);
               const auto d = arith::lift(L, r.direction);
               const auto rr = L(s.radius);
               const auto bb = arith::dot(m, d);
               return bb * bb - arith::dot(d, d) * (arith::dot(m, m) - rr * rr);
           }) != sign::negative;
}

// Optimized geometric method (RTR4 22.6.2) in plain double; the direction is normalised.
[[nodiscard]] constexpr std::optional<ray_sphere_hit> ray_sphere_geometric(const ray3& r, const sphere3& s) {
    const vec3 l = s.center - r.origin;
    const double r2 = s.radius * s.radius;
    const double l2 = dot(l, l);
    const double a = dot(r.direction, r.direction);
    if (l2 <= r2) return ray_sphere_hit{0.0, r.origin};
    if (!(a > 0.0)) return std::nullopt;
    const double len = arith::sqrt(a);
    const double sproj = dot(l, r.direction) / len;
    if (sproj < 0.0) return std::nullopt; // outside and pointing away
    const double m2 = l2 - sproj * sproj;
    if (m2 > r2) return std::nullopt; // passes beside the sphere
    const double q = arith::sqrt(r2 - m2);
    const double t = (sproj - q) / len;
    return ray_sphere_hit{t, r.at(t)};
}

// Algebraic method: solve a t^2 + 2 b t + c = 0 with the numerically stable root formula.
[[nodiscard]] constexpr std::optional<ray_sphere_hit> ray_sphere_algebraic(const ray3& r, const sphere3& s) {
    const vec3 m = r.origin - s.center;
    const double c = dot(m, m) - s.radius * s.radius;
    if (c <= 0.0) return ray_sphere_hit{0.0, r.origin};
    const double b = dot(m, r.direction);
    if (b >= 0.0) return std::nullopt;
    const double a = dot(r.direction, r.direction);
    const double disc = b * b - a * c;
    if (disc < 0.0) return std::nullopt;
    const double t = c / (-b + arith::sqrt(disc));
    return ray_sphere_hit{t, r.at(t)};
}

// Exact first hit: t and the point correctly rounded.
[[nodiscard]] constexpr std::optional<ray_sphere_hit> ray_sphere_exact(const ray3& r, const sphere3& s) {
    arith::exact_kernel k;
    if (!intersects(k, r, s) || !k.valid) return std::nullopt;
    using arith::dyadic;
    using arith::to_dyadic;
    const dyadic ox = to_dyadic(r.origin.x), oy = to_dyadic(r.origin.y), oz = to_dyadic(r.origin.z);
    const dyadic mx = ox - to_dyadic(s.center.x), my = oy - to_dyadic(s.center.y),
                 mz = oz - to_dyadic(s.center.z);
    const dyadic dx = to_dyadic(r.direction.x), dy = to_dyadic(r.direction.y), dz = to_dyadic(r.direction.z);
    const dyadic rr = to_dyadic(s.radius);
    const dyadic c = mx * mx + my * my + mz * mz - rr * rr;
    if (arith::sign_of(c) <= 0) return ray_sphere_hit{0.0, r.origin};
    const dyadic a = dx * dx + dy * dy + dz * dz;
    const dyadic b = mx * dx + my * dy + mz * dz;
    // t1 <= p/q, q > 0
    auto le_rat = [&](const dyadic& p, const dyadic& q) {
        if (arith::sign_of(a * p + b * q) >= 0) return true;
        return arith::sign_of(a * p * p + b * p * q + b * p * q + c * q * q) <= 0;
    };
    auto lt_rat = [&](const dyadic& p, const dyadic& q) {
        if (arith::sign_of(a * p + b * q) > 0) return true;
        return arith::sign_of(a * p * p + b * p * q + b * p * q + c * q * q) < 0;
    };
    const dyadic one = to_dyadic(1.0);
    const auto approx = ray_sphere_algebraic(r, s);
    const double guess_t = approx ? approx->t : 0.0;
    const double t = arith::correctly_round([&](const dyadic& y) { return le_rat(y, one); },
                                            [&](const dyadic& y) { return lt_rat(y, one); }, guess_t);
    // Coordinate i of the point: X = o_i + t1 d_i, monotone in t1.
    auto coord = [&](const dyadic& o, const dyadic& d, double od, double guess) {
        const int sd = arith::sign_of(d);
        if (sd == 0) return od;
        auto le = [&](const dyadic& y) { // o + t1 d <= y
            return sd > 0 ? le_rat(y - o, d) : !lt_rat(o - y, -d);
        };
        auto lt = [&](const dyadic& y) { return sd > 0 ? lt_rat(y - o, d) : !le_rat(o - y, -d); };
        return arith::correctly_round(le, lt, guess);
    };
    const point3 g = r.at(t);
    const point3 p{coord(ox, dx, r.origin.x, g.x), coord(oy, dy, r.origin.y, g.y), coord(oz, dz, r.origin.z, g.z)};
    return ray_sphere_hit{t, p};
}

} // namespace incidence::pair

export namespace incidence::pair {
// The approximate tier of intersects(ray3, sphere3) is the optimized geometric method.
[[nodiscard]] constexpr bool intersects_approximate(const ray3& r, const sphere3& s) {
    return ray_sphere_geometric(r, s).has_value();
}
} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const ray3&, const sphere3&);
} // namespace incidence::pair
