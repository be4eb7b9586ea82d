// triangle3 against triangle3 (closed triangles; a collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge, or coplanar overlap counts.
// Method (exact tiers): bounding boxes apart reject (comparisons, exact; Ericson, Real-Time
// Collision Detection (2005), section 4.2.1). Then the orient3d signs of each triangle's vertices
// against the other's plane; all three strictly on one side rejects. When all six signs are nonzero, each triangle
// strictly straddles the other's plane (so neither is degenerate and the planes cross in a line
// L): after a circular permutation puts the vertex alone on its side first, and a swap of the
// other triangle's last two vertices makes that vertex's sign positive, the triangles meet iff
// orient3d(p1, q1, p2, q2) <= 0 and orient3d(p1, r1, r2, p2) <= 0 (the two intervals on L
// overlap). Source: Guigue and Devillers, "Fast and robust triangle-triangle overlap test using
// orientation predicates", JGT 8(1), 2003, sections 2-3. Otherwise (a vertex in the other's
// plane, coplanar or degenerate triangles) two closed convex sets in R^3 whose intersection is
// nonempty meet at a point of one's boundary that lies in the other (the intersection of two
// triangles is a convex set whose extreme points lie on an edge of one of them), so T1 and T2
// meet iff one of the six edges meets the other triangle, each by the segment_triangle sign
// algorithm. Every sign is of a polynomial of degree <= 3 in the inputs.
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
import :segment_segment;
import :ray_triangle;

export namespace incidence::pair {

// Canonical order for the one-type pair (segment_segment.cppm's before): the lexicographically
// smaller triangle first, so that every tier, plain double included, gives (p, q) and (q, p) the
// same answer (the last two orient3d signs are not symmetric in p and q).
[[nodiscard]] constexpr bool before(const triangle3& p, const triangle3& q) {
    const double x[9] = {p.a.x, p.a.y, p.a.z, p.b.x, p.b.y, p.b.z, p.c.x, p.c.y, p.c.z};
    const double y[9] = {q.a.x, q.a.y, q.a.z, q.b.x, q.b.y, q.b.z, q.c.x, q.c.y, q.c.z};
    return lex_compare(x, y, 9) < 0;
}

template <class K>
[[nodiscard]] constexpr bool triangles_meet(K& k, const triangle3& p, const triangle3& q) {
    auto orient = [&](point3 a, point3 b, point3 c, point3 d) {
        return k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, d); });
    };
    const point3 P[3] = {p.a, p.b, p.c}, Q[3] = {q.a, q.b, q.c};
    // The signs of t's vertices against u's plane, into s: 0 when all three lie strictly on one
    // side, 1 when none is zero (t straddles), 2 at the first zero (the remaining signs unset).
    auto sides = [&](const point3* t, const point3* u, sign* s) {
        for (int i = 0; i < 3; ++i)
            if ((s[i] = orient(u[0], u[1], u[2], t[i])) == sign::zero) return 2;
        return s[0] == s[1] && s[1] == s[2] ? 0 : 1;
    };
    sign sp[3] = {}, sq[3] = {};
    const int from_p = sides(P, Q, sp);
    if (from_p == 0) return false;
    const int from_q = sides(Q, P, sq);
    if (from_q == 0) return false;
    if (from_p == 1 && from_q == 1) {
        // Guigue and Devillers: the lone vertex first, on the positive side of the other plane.
        auto lone = [](const sign* s) { return s[0] == s[1] ? 2 : s[0] == s[2] ? 1 : 0; };
        const int i = lone(sp), j = lone(sq);
        const int fa = sq[j] == sign::negative, fb = sp[i] == sign::negative; // swap the last two
        const point3 a0 = P[i], a1 = P[(i + 1 + fa) % 3], a2 = P[(i + 2 - fa) % 3];
        const point3 b0 = Q[j], b1 = Q[(j + 1 + fb) % 3], b2 = Q[(j + 2 - fb) % 3];
        return orient(a0, a1, b0, b1) != sign::positive && orient(a0, a2, b2, b0) != sign::positive;
    }
    auto edge = [&](point3 x, point3 y, const triangle3& t) {
        return linear_triangle(k, linear3{x, vec3{0, 0, 0}, y, extent::segment}, t);
    };
    return edge(p.a, p.b, q) || edge(p.b, p.c, q) || edge(p.c, p.a, q) || edge(q.a, q.b, p) || edge(q.b, q.c, p) ||
           edge(q.c, q.a, p);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const triangle3& p, const triangle3& q) {
    if (boxes_apart(k, p, q)) return false; // exact, and cheap on the commonest no
    return before(q, p) ? triangles_meet(k, q, p) : triangles_meet(k, p, q);
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
