// obb3 against ray3 (closed box read as the parallelepiped its axes span; the ray o + t d, t >= 0).
// Semantics: a ray starting inside, on the boundary, or grazing an edge counts.
// Method (exact tiers): generalised slabs as separating axes: the three face normals and the three
// box axes crossed with d. Along an axis w the ray projects to a half-line, so the sign of w . d
// picks which end of the box's interval its origin must pass; each test is one sign of degree 4,
// with no division (the slab method's entry and exit t are never formed).
// Source: Kay and Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (slabs); Ericson, Real-Time
// Collision Detection (2005), section 5.3.3 (the axes of the segment-box test, one side open).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is within 2^-40 of its
// permanent (the sets touch or nearly touch); tests/query/obb_ray.cpp checks it.
export module incidence.query:obb_ray;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const ray3& b) {
    return sat::well_formed(a) && sat::zonotopes_intersect(k, sat::of(a), sat::of(b));
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const ray3&);
} // namespace incidence::pair
