// triangle3 against triangle3 (closed triangles; a collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge, or coplanar overlap counts.
// Method (exact tiers): two closed convex sets in R^3 whose intersection is nonempty meet at a
// point of one's boundary that lies in the other (the intersection of two triangles is a convex
// set whose extreme points lie on an edge of one of them), so T1 and T2 meet iff one of the six
// edges meets the other triangle. Each edge test is the segment_triangle sign algorithm; a
// strict one-side rejection by the three orient3d signs of each triangle's vertices against the
// other's plane comes first (Guigue and Devillers, "Fast and robust triangle-triangle overlap
// test using orientation predicates", JGT 8(1), 2003, section 2 uses the same first step).
// Every sign is of a polynomial of degree <= 3 in the inputs.
// Approximate tier: the same sign algorithm in plain double. Error bound, for inputs whose
// nonzero magnitudes lie in [2^-500, 2^500]: wrong only when some sign's value is within 2^-36 of
// its permanent (checked by tests/query/triangle_triangle.cpp). method::triangle_triangle_sat is
// the separating-axis test in plain double (two normals, nine edge-edge cross products, six
// in-plane edge normals for the coplanar case; Akenine-Moeller, Real-Time Rendering 4th ed.,
// section 22.12), kept for comparison.
export module incidence.query:triangle_triangle;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :ray_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const triangle3& p, const triangle3& q) {
    // All three vertices of `t` strictly on one side of the plane of `u`.
    auto one_side = [&](const triangle3& t, const triangle3& u) {
        const point3 a = u.a, b = u.b, c = u.c;
        const sign s0 = k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, t.a); });
        if (s0 == sign::zero) return false;
        const sign s1 = k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, t.b); });
        if (s1 != s0) return false;
        const sign s2 = k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, t.c); });
        return s2 == s0;
    };
    if (one_side(p, q) || one_side(q, p)) return false;
    auto edge = [&](point3 x, point3 y, const triangle3& t) {
        return linear_triangle(k, linear3{x, vec3{0, 0, 0}, y, extent::segment}, t);
    };
    return edge(p.a, p.b, q) || edge(p.b, p.c, q) || edge(p.c, p.a, q) || edge(q.a, q.b, p) || edge(q.b, q.c, p) ||
           edge(q.c, q.a, p);
}

// Separating-axis test in plain double (see the top comment); closed triangles, touching counts.
[[nodiscard]] constexpr bool triangle_triangle_sat(const triangle3& p, const triangle3& q) {
    const point3 P[3] = {p.a, p.b, p.c}, Q[3] = {q.a, q.b, q.c};
    const vec3 ep[3] = {p.b - p.a, p.c - p.b, p.a - p.c}, eq[3] = {q.b - q.a, q.c - q.b, q.a - q.c};
    auto separated = [&](vec3 axis) {
        if (axis.x == 0.0 && axis.y == 0.0 && axis.z == 0.0) return false;
        double pmin = dot(axis, P[0] - point3{0, 0, 0}), pmax = pmin;
        double qmin = dot(axis, Q[0] - point3{0, 0, 0}), qmax = qmin;
        for (int i = 1; i < 3; ++i) {
            const double x = dot(axis, P[i] - point3{0, 0, 0}), y = dot(axis, Q[i] - point3{0, 0, 0});
            pmin = x < pmin ? x : pmin; pmax = x > pmax ? x : pmax;
            qmin = y < qmin ? y : qmin; qmax = y > qmax ? y : qmax;
        }
        return pmax < qmin || qmax < pmin;
    };
    const vec3 np = cross(ep[0], ep[1]), nq = cross(eq[0], eq[1]);
    if (separated(np) || separated(nq)) return false;
    for (const vec3& a : ep)
        for (const vec3& b : eq)
            if (separated(cross(a, b))) return false;
    for (int i = 0; i < 3; ++i)
        if (separated(cross(np, ep[i])) || separated(cross(nq, eq[i]))) return false;
    return true;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const triangle3&, const triangle3&);
} // namespace incidence::pair
