// ray3 against triangle3: intersects, and intersection (t, point, normal, barycentrics).
// Semantics: closed triangle, so hits on edges and vertices count; a ray lying in the
// triangle's plane hits when it meets the triangle (2D test); a collinear (degenerate)
// triangle is its convex hull, a segment or a point; a zero direction is the point `origin`.
// Method (exact tiers): bounding boxes apart reject (comparisons, exact; Ericson, Real-Time
// Collision Detection (2005), section 4.2.1; a ray's box is unbounded where it moves). Then
// signs only, as in CGAL's Ray_3/Triangle_3 do_intersect. With
// n.d = det(b-a, c-a, d), the Pluecker edge values w_a = det(d, b-o, c-o), w_b = det(d, c-o, a-o),
// w_c = det(d, a-o, b-o) (summing to n.d) and num = det(b-a, c-a, a-o):
//   n.d != 0: hit iff w_a, w_b, w_c all have the sign of n.d or are zero, and num * n.d >= 0
//   n.d == 0, n != 0: coplanar iff num == 0, then a 2D test in the plane projected along an
//                     axis where n is nonzero (origin inside, or a crossing of an edge)
//   n == 0: the triangle is a segment or a point: test its three edges.
// Every sign is of a homogeneous polynomial of degree <= 3 (expansion length <= 192).
// The exact tier's t = num / n.d and barycentrics w_i / n.d are correctly rounded.
// Approximate tier: watertight ray-triangle, Woop, Benthin and Wald, JCGT 2(1), 2013 (a ray
// through a shared edge hits at least one of the two triangles); Moeller and Trumbore, JGT 2(1),
// 1997, kept as method::ray_triangle_moller_trumbore for comparison.
// Error bound (approximate), for inputs whose nonzero magnitudes lie in [2^-500, 2^500]:
// wrong only when some w_i or num is within 2^-36 of its permanent
// (sum of the absolute values of its monomials), i.e. within that relative distance of an
// edge, a vertex or the origin's plane (checked by tests/query/ray_triangle.cpp).
//
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
module;
#include <optional>
export module incidence.detail:engines.triangle;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;

export namespace incidence::detail {

template <class K>
[[nodiscard]] constexpr bool point_in_triangle(K& k, point3 x, const triangle3& t);
template <class K>
[[nodiscard]] constexpr bool in_projected_triangle(K& k, point3 x, const triangle3& t, int axis, sign na);

template <class K>
[[nodiscard]] constexpr bool linear_triangle(K& k, const linear3& s, const triangle3& t) {
    if (s.is_point()) return point_in_triangle(k, s.o, t);
    const point3 a = t.a, b = t.b, c = t.c;
    auto n_of = [=](auto L) {
        const auto A = arith::lift(L, a);
        return arith::cross(arith::lift(L, b) - A, arith::lift(L, c) - A);
    };
    // nd, the normal's components and num are zero for a line in the triangle's plane, by
    // structure in one plane z = c (hint::structural; see linear_linear).
    const sign nd = arith::sgn<arith::hint::structural>(k, [=](auto L) { return arith::dot(n_of(L), s.D(L)); });
    if (nd != sign::zero) {
        auto w = [&](point3 u, point3 v) {
            return k.sgn([=](auto L) { return arith::det3(s.D(L), arith::lift(L, u) - s.O(L), arith::lift(L, v) - s.O(L)); });
        };
        if (w(b, c) == -nd || w(c, a) == -nd || w(a, b) == -nd) return false;
        const sign num = k.sgn([=](auto L) { return arith::dot(n_of(L), arith::lift(L, a) - s.O(L)); });
        if (s.bounded_below() && num == -nd) return false; // t < 0
        if (!s.bounded_above()) return true;
        const sign over = k.sgn([=](auto L) { // n.d - num = n.(q - a)
            return arith::dot(n_of(L), s.O(L) + s.D(L) - arith::lift(L, a));
        });
        return over != -nd; // t <= 1
    }
    for (int axis = 0; axis < 3; ++axis) {
        const sign na = arith::sgn<arith::hint::structural>(k, [=](auto L) { return pick(n_of(L), axis); });
        if (na == sign::zero) continue;
        // Non-degenerate triangle, line parallel to its plane: coplanar iff the origin is in it.
        if (!arith::is_zero<arith::hint::structural>(k, [=](auto L) { return arith::dot(n_of(L), arith::lift(L, a) - s.O(L)); }))
            return false;
        if (in_projected_triangle(k, s.o, t, axis, na)) return true; // s.o is in the plane
        return linear_linear_2d(k, s, as_linear(segment3{a, b}), axis) || linear_linear_2d(k, s, as_linear(segment3{b, c}), axis) ||
               linear_linear_2d(k, s, as_linear(segment3{c, a}), axis);
    }
    // Degenerate triangle: the union of its edges is its convex hull.
    return linear_linear(k, s, as_linear(segment3{a, b})) || linear_linear(k, s, as_linear(segment3{b, c})) ||
           linear_linear(k, s, as_linear(segment3{c, a}));
}

// A point x in the plane of a non-degenerate triangle lies in it iff its projection along axis
// lies in the projected triangle, whose orientation is na, the sign of the normal's component
// along axis (nonzero).
template <class K>
[[nodiscard]] constexpr bool in_projected_triangle(K& k, point3 x, const triangle3& t, int axis, sign na) {
    auto side = [&](point3 u, point3 v) {
        return k.sgn([=](auto L) {
            const auto U = arith::lift(L, u);
            return arith::cross(drop_axis(arith::lift(L, v) - U, axis), drop_axis(arith::lift(L, x) - U, axis));
        });
    };
    return side(t.a, t.b) != -na && side(t.b, t.c) != -na && side(t.c, t.a) != -na;
}

// Closed triangle (or its hull when degenerate) contains the point x.
template <class K>
[[nodiscard]] constexpr bool point_in_triangle(K& k, point3 x, const triangle3& t) {
    const point3 a = t.a, b = t.b, c = t.c;
    if (!arith::is_zero<arith::hint::structural>(k, [=](auto L) { return poly::orient3d(L, a, b, c, x); }))
        return false; // see linear_triangle
    for (int axis = 0; axis < 3; ++axis) {
        const sign na = arith::sgn<arith::hint::structural>(k, [=](auto L) {
            const auto A = arith::lift(L, a);
            return pick(arith::cross(arith::lift(L, b) - A, arith::lift(L, c) - A), axis);
        });
        if (na == sign::zero) continue;
        return in_projected_triangle(k, x, t, axis, na);
    }
    // Degenerate: x on one of the edges (a zero-length segment is its point).
    const linear3 px{x, vec3{0, 0, 0}, x, extent::segment};
    auto on_edge = [&](point3 p, point3 q) {
        for (int axis = 0; axis < 3; ++axis) {
            const sign m = k.sgn([=](auto L) {
                return pick(arith::cross(arith::lift(L, q) - arith::lift(L, p), arith::lift(L, x) - arith::lift(L, p)), axis);
            });
            if (m != sign::zero) return false;
        }
        const sign d0 =
            k.sgn([=](auto L) { return arith::dot(arith::lift(L, x) - arith::lift(L, p), arith::lift(L, q) - arith::lift(L, p)); });
        const sign d1 =
            k.sgn([=](auto L) { return arith::dot(arith::lift(L, q) - arith::lift(L, x), arith::lift(L, q) - arith::lift(L, p)); });
        if (p == q) return x == p;
        return d0 != sign::negative && d1 != sign::negative;
    };
    (void)px;
    return on_edge(a, b) || on_edge(b, c) || on_edge(c, a);
}

// Watertight ray-triangle (Woop, Benthin, Wald 2013), closed triangle, t >= 0.
[[nodiscard]] constexpr std::optional<triangle_hit<double>> ray_triangle_watertight(const ray3& r, const triangle3& tri) {
    const double d[3] = {r.direction.x, r.direction.y, r.direction.z};
    int kz = 0;
    if (arith::abs(d[1]) > arith::abs(d[kz])) kz = 1;
    if (arith::abs(d[2]) > arith::abs(d[kz])) kz = 2;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0.0) {
        const int tmp = kx;
        kx = ky;
        ky = tmp;
    }
    if (!(d[kz] != 0.0)) return std::nullopt;
    const double sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0 / d[kz];
    const vec3 av = tri.a - r.origin, bv = tri.b - r.origin, cv = tri.c - r.origin;
    const double A[3] = {av.x, av.y, av.z}, B[3] = {bv.x, bv.y, bv.z}, C[3] = {cv.x, cv.y, cv.z};
    const double ax = A[kx] - sx * A[kz], ay = A[ky] - sy * A[kz];
    const double bx = B[kx] - sx * B[kz], by = B[ky] - sy * B[kz];
    const double cx = C[kx] - sx * C[kz], cy = C[ky] - sy * C[kz];
    const double U = cx * by - cy * bx;
    const double V = ax * cy - ay * cx;
    const double W = bx * ay - by * ax;
    if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) return std::nullopt;
    const double det = U + V + W;
    if (!(det != 0.0)) return std::nullopt;
    const double az = sz * A[kz], bz = sz * B[kz], cz = sz * C[kz];
    const double T = U * az + V * bz + W * cz;
    if ((det < 0.0 && T > 0.0) || (det > 0.0 && T < 0.0)) return std::nullopt;
    const double inv = 1.0 / det;
    const double t = T * inv;
    return triangle_hit<double>{t, r.at(t), cross(tri.b - tri.a, tri.c - tri.a), U * inv, V * inv, W * inv, certainty::uncertain};
}

// Moeller-Trumbore (1997), closed triangle, no epsilon: det == 0 is a miss.
[[nodiscard]] constexpr std::optional<triangle_hit<double>> ray_triangle_moller_trumbore(const ray3& r, const triangle3& tri) {
    const vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
    const vec3 p = cross(r.direction, e2);
    const double det = dot(e1, p);
    if (!(det != 0.0)) return std::nullopt;
    const double inv = 1.0 / det;
    const vec3 s = r.origin - tri.a;
    const double u = dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const vec3 q = cross(s, e1);
    const double v = dot(r.direction, q) * inv;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = dot(e2, q) * inv;
    if (!(t >= 0.0)) return std::nullopt;
    return triangle_hit<double>{t, r.at(t), cross(e1, e2), 1.0 - u - v, u, v, certainty::uncertain};
}

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
    auto orient = [&](point3 a, point3 b, point3 c, point3 d) { return k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, d); }); };
    const point3 P[3] = {p.a, p.b, p.c}, Q[3] = {q.a, q.b, q.c};
    // The signs of t's vertices against u's plane, into s: one_side when all three lie strictly on
    // one side, straddles when none is zero, touches at the first zero (the remaining signs unset).
    enum class against_plane : unsigned char { one_side, straddles, touches };
    auto sides = [&](const point3* t, const point3* u, sign* s) {
        for (int i = 0; i < 3; ++i)
            if ((s[i] = orient(u[0], u[1], u[2], t[i])) == sign::zero) return against_plane::touches;
        return s[0] == s[1] && s[1] == s[2] ? against_plane::one_side : against_plane::straddles;
    };
    sign sp[3] = {}, sq[3] = {};
    const against_plane from_p = sides(P, Q, sp);
    if (from_p == against_plane::one_side) return false;
    const against_plane from_q = sides(Q, P, sq);
    if (from_q == against_plane::one_side) return false;
    if (from_p == against_plane::straddles && from_q == against_plane::straddles) {
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
    return edge(p.a, p.b, q) || edge(p.b, p.c, q) || edge(p.c, p.a, q) || edge(q.a, q.b, p) || edge(q.b, q.c, p) || edge(q.c, q.a, p);
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
            pmin = x < pmin ? x : pmin;
            pmax = x > pmax ? x : pmax;
            qmin = y < qmin ? y : qmin;
            qmax = y > qmax ? y : qmax;
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

} // namespace incidence::detail
