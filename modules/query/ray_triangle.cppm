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
module;
#include <optional>
export module incidence.query:ray_triangle;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :segment_segment;

export namespace incidence {

struct ray_triangle_hit {
    double t;            // parameter along the ray (or along the segment, in [0, 1])
    point3 point;        // origin + t * direction
    vec3 normal;         // (b - a) x (c - a), not normalised: its orientation tells the side hit
    double u, v, w;      // barycentrics of a, b, c: point = u a + v b + w c, u + v + w = 1
};

} // namespace incidence

export namespace incidence::pair {

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
    // structure in one plane z = c (arith::structural_sgn; see linear_linear).
    const sign nd = arith::structural_sgn(k, [=](auto L) { return arith::dot(n_of(L), s.D(L)); });
    if (nd != sign::zero) {
        auto w = [&](point3 u, point3 v) {
            return k.sgn([=](auto L) {
                return arith::det3(s.D(L), arith::lift(L, u) - s.O(L), arith::lift(L, v) - s.O(L));
            });
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
        const sign na = arith::structural_sgn(k, [=](auto L) { return pick(n_of(L), axis); });
        if (na == sign::zero) continue;
        // Non-degenerate triangle, line parallel to its plane: coplanar iff the origin is in it.
        if (!arith::structural_zero(k, [=](auto L) { return arith::dot(n_of(L), arith::lift(L, a) - s.O(L)); })) return false;
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
    if (!arith::structural_zero(k, [=](auto L) { return poly::orient3d(L, a, b, c, x); })) return false; // see linear_triangle
    for (int axis = 0; axis < 3; ++axis) {
        const sign na = arith::structural_sgn(k, [=](auto L) {
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
            const sign m = k.sgn([=](auto L) { return pick(arith::cross(arith::lift(L, q) - arith::lift(L, p), arith::lift(L, x) - arith::lift(L, p)), axis); });
            if (m != sign::zero) return false;
        }
        const sign d0 = k.sgn([=](auto L) { return arith::dot(arith::lift(L, x) - arith::lift(L, p), arith::lift(L, q) - arith::lift(L, p)); });
        const sign d1 = k.sgn([=](auto L) { return arith::dot(arith::lift(L, q) - arith::lift(L, x), arith::lift(L, q) - arith::lift(L, p)); });
        if (p == q) return x == p;
        return d0 != sign::negative && d1 != sign::negative;
    };
    (void)px;
    return on_edge(a, b) || on_edge(b, c) || on_edge(c, a);
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const triangle3& t) {
    if (boxes_apart(k, r, t)) return false; // exact, and cheap on the commonest no
    return linear_triangle(k, linear3{r.origin, r.direction, r.origin, extent::ray}, t);
}

// Watertight ray-triangle (Woop, Benthin, Wald 2013), closed triangle, t >= 0.
[[nodiscard]] constexpr std::optional<ray_triangle_hit> ray_triangle_watertight(const ray3& r, const triangle3& tri) {
    const double d[3] = {r.direction.x, r.direction.y, r.direction.z};
    int kz = 0;
    if (arith::abs(d[1]) > arith::abs(d[kz])) kz = 1;
    if (arith::abs(d[2]) > arith::abs(d[kz])) kz = 2;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0.0) { const int tmp = kx; kx = ky; ky = tmp; }
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
    return ray_triangle_hit{t, r.at(t), cross(tri.b - tri.a, tri.c - tri.a), U * inv, V * inv, W * inv};
}

// Moeller-Trumbore (1997), closed triangle, no epsilon: det == 0 is a miss.
[[nodiscard]] constexpr std::optional<ray_triangle_hit> ray_triangle_moller_trumbore(const ray3& r, const triangle3& tri) {
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
    return ray_triangle_hit{t, r.at(t), cross(e1, e2), 1.0 - u - v, u, v};
}

// First contact of a linear object lying in the triangle's plane (n.d == 0), or of any linear
// object with a degenerate (collinear) triangle: the smallest t >= 0 over the origin (t = 0 when
// it lies on the triangle) and the edges' crossings, all compared exactly as rationals num/den.
struct contact {
    arith::dyadic num, den; // t = num / den, den > 0
    bool found = false;
};
using dv3 = arith::v3<arith::dyadic>;
[[nodiscard]] constexpr arith::dyadic pick_d(const dv3& v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }
[[nodiscard]] constexpr arith::dyadic cross2_d(const dv3& a, const dv3& b, int axis) { // along `axis` dropped
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    return pick_d(a, i) * pick_d(b, j) - pick_d(a, j) * pick_d(b, i);
}
[[nodiscard]] constexpr dv3 scaled(const dv3& v, const arith::dyadic& k) { return {v.x * k, v.y * k, v.z * k}; }
constexpr void keep_first(contact& best, arith::dyadic num, arith::dyadic den) {
    if (arith::sign_of(den) < 0) { num = -num; den = -den; }
    if (!best.found || arith::sign_of(num * best.den - best.num * den) < 0) best = {num, den, true};
}
// Contact of o + t d (t >= 0) with the edge [P, Q], in the projection dropping `axis`, which
// must be injective on a plane holding the ray and the edge.
constexpr void edge_contact(contact& best, const dv3& O, const dv3& D, const dv3& P, const dv3& Q, int axis) {
    using arith::sign_of;
    const int sp = sign_of(cross2_d(D, P - O, axis)), sq = sign_of(cross2_d(D, Q - O, axis));
    if (sp != 0 && sp == sq) return;
    if (sp == 0 && sq == 0) { // on the ray's line: the nearer end point, or the origin itself
        const auto tp = arith::dot(P - O, D), tq = arith::dot(Q - O, D), dd = arith::dot(D, D);
        const int a = sign_of(tp), b = sign_of(tq);
        if (a < 0 && b < 0) return;
        if (a < 0 || b < 0) { keep_first(best, arith::dyadic{}, dd); return; }
        keep_first(best, sign_of(tp - tq) <= 0 ? tp : tq, dd);
        return;
    }
    const auto num = cross2_d(P - O, Q - P, axis), den = cross2_d(D, Q - P, axis);
    if (sign_of(num) * sign_of(den) < 0) return; // crossing at t < 0
    keep_first(best, num, den);
}

// Exact hit values, correctly rounded: t, the point, the normal (b - a) x (c - a) and the
// barycentrics (zero for a degenerate triangle, which has none). Requires an intersection.
[[nodiscard]] constexpr ray_triangle_hit linear_triangle_values(const linear3& s, const triangle3& tri) {
    using arith::dyadic;
    using arith::sign_of;
    auto D3 = [](point3 p) { return dv3{arith::to_dyadic(p.x), arith::to_dyadic(p.y), arith::to_dyadic(p.z)}; };
    const auto O = D3(s.o), A = D3(tri.a), B = D3(tri.b), C = D3(tri.c);
    const auto Dv = s.kind == extent::segment ? D3(s.q) - O
                                               : dv3{arith::to_dyadic(s.d.x), arith::to_dyadic(s.d.y), arith::to_dyadic(s.d.z)};
    const auto n = arith::cross(B - A, C - A);
    const dyadic nd = arith::dot(n, Dv);
    const vec3 normal{arith::to_double(n.x), arith::to_double(n.y), arith::to_double(n.z)};
    contact first;
    int axis = -1; // projection for barycentrics: n_axis != 0
    for (int k = 0; k < 3 && axis < 0; ++k)
        if (sign_of(pick_d(n, k)) != 0) axis = k;
    if (sign_of(nd) != 0) {
        first = {arith::dot(n, A - O), nd, true}; // t = n.(a - o) / n.d
        if (sign_of(first.den) < 0) { first.num = -first.num; first.den = -first.den; }
    } else if (s.is_point()) {
        first = {dyadic{}, arith::to_dyadic(1.0), true};
    } else if (axis >= 0) {
        // Coplanar with a proper triangle: t = 0 if the origin is on it, else the first edge crossing.
        const int orient = sign_of(pick_d(n, axis));
        const bool inside = sign_of(cross2_d(B - A, O - A, axis)) != -orient && sign_of(cross2_d(C - B, O - B, axis)) != -orient &&
                            sign_of(cross2_d(A - C, O - C, axis)) != -orient;
        if (inside) first = {dyadic{}, arith::to_dyadic(1.0), true};
        else {
            edge_contact(first, O, Dv, A, B, axis);
            edge_contact(first, O, Dv, B, C, axis);
            edge_contact(first, O, Dv, C, A, axis);
        }
    } else {
        // Degenerate triangle: its edges, each in a plane it shares with the ray.
        const dv3 edges[3][2] = {{A, B}, {B, C}, {C, A}};
        for (const auto& e : edges) {
            if (sign_of(arith::det3(Dv, e[0] - O, e[1] - O)) != 0) continue; // not coplanar
            const auto m = arith::cross(Dv, e[1] - e[0]);
            int k = -1;
            for (int i = 0; i < 3 && k < 0; ++i)
                if (sign_of(pick_d(m, i)) != 0) k = i;
            if (k >= 0) { edge_contact(first, O, Dv, e[0], e[1], k); continue; }
            const auto off = arith::cross(Dv, e[0] - O); // parallel: on the ray's line?
            if (sign_of(off.x) != 0 || sign_of(off.y) != 0 || sign_of(off.z) != 0) continue;
            for (int i = 0; i < 3; ++i) // collinear: any projection keeps the 1D order
                if (sign_of(pick_d(Dv, (i + 1) % 3)) != 0 || sign_of(pick_d(Dv, (i + 2) % 3)) != 0) {
                    edge_contact(first, O, Dv, e[0], e[1], i);
                    break;
                }
        }
    }
    if (!first.found) return ray_triangle_hit{0.0, s.o, normal, 0.0, 0.0, 0.0}; // not reached when intersecting
    const dyadic& num = first.num;
    const dyadic& den = first.den;
    const double t = arith::quotient(num, den);
    // point = o + (num / den) d = (o den + num d) / den
    const dv3 Pn = scaled(O, den) + scaled(Dv, num);
    const point3 p{arith::quotient(Pn.x, den), arith::quotient(Pn.y, den), arith::quotient(Pn.z, den)};
    if (axis < 0) return ray_triangle_hit{t, p, normal, 0.0, 0.0, 0.0};
    // Barycentrics: signed areas in the projection dropping `axis`, scaled by den^2.
    const dyadic area = cross2_d(B - A, C - A, axis) * den * den;
    const dv3 Ad = scaled(A, den), Bd = scaled(B, den), Cd = scaled(C, den);
    return ray_triangle_hit{t, p, normal, arith::quotient(cross2_d(Bd - Pn, Cd - Pn, axis), area),
                            arith::quotient(cross2_d(Pn - Ad, Cd - Ad, axis), area),
                            arith::quotient(cross2_d(Bd - Ad, Pn - Ad, axis), area)};
}

} // namespace incidence::pair

export namespace incidence::pair {
// The approximate tier of intersects(ray3, triangle3) is the watertight algorithm.
[[nodiscard]] constexpr bool intersects_approximate(const ray3& r, const triangle3& t) {
    return ray_triangle_watertight(r, t).has_value();
}
} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const ray3&, const triangle3&);
} // namespace incidence::pair
