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
export module incidence.query:aabb_sphere;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

namespace ball {
[[nodiscard]] constexpr bool usable(const aabb3& b) {
    return finite(b.min) && finite(b.max) && b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z;
}
[[nodiscard]] constexpr bool usable(const sphere3& s) { return finite(s.center) && finite(s.radius); }
[[nodiscard]] constexpr double magnitude(double r) { return r < 0.0 ? -r : r; }
} // namespace ball

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const sphere3& s) {
    if (!ball::usable(b) || !ball::usable(s)) return false;
    const double c[3] = {s.center.x, s.center.y, s.center.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    // the nearest point's gap on each axis: from the centre up to min, from max up to the centre, or none
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
        if (c[i] < mn[i]) lo[i] = c[i], hi[i] = mn[i];
        else if (c[i] > mx[i]) lo[i] = mx[i], hi[i] = c[i];
        else lo[i] = hi[i] = 0.0;
    }
    const double r = s.radius;
    return k.sgn([=](auto L) {
        auto g = [&](int i) { return L(hi[i]) - L(lo[i]); };
        const auto g0 = g(0), g1 = g(1), g2 = g(2);
        return L(r) * L(r) - (g0 * g0 + g1 * g1 + g2 * g2);
    }) != sign::negative;
}

// Is the ball inside the box?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const sphere3& s) {
    if (!ball::usable(b) || !ball::usable(s)) return false;
    const double r = ball::magnitude(s.radius);
    const double c[3] = {s.center.x, s.center.y, s.center.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    for (int i = 0; i < 3; ++i) {
        const double ci = c[i], lo = mn[i], hi = mx[i];
        if (k.sgn([=](auto L) { return L(ci) - L(r) - L(lo); }) == sign::negative) return false;
        if (k.sgn([=](auto L) { return L(hi) - L(ci) - L(r); }) == sign::negative) return false;
    }
    return true;
}

// Is the box inside the ball?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const aabb3& b) {
    if (!ball::usable(b) || !ball::usable(s)) return false;
    const double c[3] = {s.center.x, s.center.y, s.center.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    double far[3];
    for (int i = 0; i < 3; ++i) {
        const double ci = c[i], lo = mn[i], hi = mx[i];
        // min is at least as far from c as max iff c - min >= max - c
        far[i] = k.sgn([=](auto L) { return (L(ci) + L(ci)) - (L(lo) + L(hi)); }) != sign::negative ? lo : hi;
    }
    const double r = s.radius;
    return k.sgn([=](auto L) {
        auto g = [&](int i) { return L(far[i]) - L(c[i]); };
        const auto g0 = g(0), g1 = g(1), g2 = g(2);
        return L(r) * L(r) - (g0 * g0 + g1 * g1 + g2 * g2);
    }) != sign::negative;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const sphere3&);
extern template bool contains(arith::exact_kernel&, const aabb3&, const sphere3&);
extern template bool contains(arith::exact_kernel&, const sphere3&, const aabb3&);
} // namespace incidence::pair
