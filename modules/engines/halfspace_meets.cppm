// convex_polyhedron3 against triangle3, contains(convex_polyhedron3, triangle3), and the test of a
// triangle against a half-space set that frustum_triangle and kdop_triangle share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed solid
// triangle (collinear corners: the segments between them; a non-finite corner: no triangle).
// Touching at a vertex, an edge or a face counts. contains: the three corners in the set (convex).
// Method (exact tiers): the set P meets the plane H of the triangle in a convex polygon Q. The
// triangle meets P iff one of its edges meets P (the generalised slab test of
// convex_polyhedron_segment.cppm) or Q lies inside the triangle; Q is then bounded and not empty,
// so it has a vertex, where two planes of P whose normals are independent of the triangle normal
// n = (b - a) x (c - a) cross H: v = V / D with D = det(n_i, n_j, n) and
// V = c_i n_j x n + c_j n x n_i + (n . a) n_i x n_j. Such a v is tested in every half-space,
// sign(c_l D - n_l . V) zero or sign(D) (degree 6), and in the triangle, sign(((q - p) x (V - p D))
// . n) zero or sign(D) for its edges p q in turn (degree 8); each offset times a lifted 1, so every
// sign is homogeneous. A filter-proven violated half-space skips a pair before any sign is decided.
// The first vertex of Q found decides: Q is connected and misses the triangle's edges, so it lies
// inside the triangle or apart from it.
// First, a plane of P with the three corners beyond it says no.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5 (a nonempty
// pointed polyhedron has a vertex, where rank-many constraints are tight); Cyrus and Beck,
// Computers & Graphics 3(1), 1978, for the edges.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_triangle.cpp).
//
// convex_polyhedron3 against mesh3, and the test of a mesh against a half-space set that
// frustum_mesh and kdop_mesh share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the mesh's point
// set (shapes/mesh3.cppm: its triangles and the points of odd crossing parity); touching a
// triangle counts.
// Method (exact tiers): a plane of the set with every mesh vertex beyond it says no; a mesh
// triangle meeting the set (the triangle test of convex_polyhedron_triangle.cppm) says yes; else
// the convex set lies wholly off the surface, inside the mesh or outside it, and one of its points
// decides by the crossing parity of mesh_point.cppm: a vertex of the set (first_vertex of
// aabb_convex_polyhedron.cppm), the rational point V / D, whose parity signs times D are
// u . (D (x x y) + (y - x) x V) (degree 5) and n . (D a - V) (degree 6) for a triangle a b c of
// normal n (all of them flip with D's sign, which leaves their agreements as they are). A nonempty
// set without a vertex is unbounded, so it is not inside.
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/convex_polyhedron_mesh.cpp).
//
// convex_polyhedron3 against obb3, contains(convex_polyhedron3, obb3), and the test of a box
// against any half-space set that frustum_obb and kdop_obb share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded) and the closed box { c + s0 a0 + s1 a1 + s2 a2 : |s_j| <= h_j }, its axes read exactly
// as given (the parallelepiped they span; a zero extent or dependent axes give a flat box).
// Touching at a face, an edge or a corner counts. contains: the whole box in the set.
// Method (exact tiers): the set read in the box's own coordinates s, where the box is the cube
// |s_j| <= h_j and the plane n . x <= d is sum_j (n . a_j) s_j <= d - n . c, every coefficient a
// polynomial of the inputs, not a rounded double. First, a plane with the whole box beyond it
// (d - n . c + sum_j h_j |n . a_j| < 0) says no, and the centre inside every plane says yes. Then
// the box's six faces and the set's planes in s bound a polytope, which is not empty iff it has a
// vertex: three rows with independent normals meeting at a point inside every row (the vertex
// search of aabb_convex_polyhedron.cppm on these rows): homogeneous signs of degree <= 9.
// contains: for every plane, d - n . c - sum_j h_j |n . a_j| >= 0 (degree 3).
// Source: vertex enumeration for LP feasibility (Schrijver, Theory of Linear and Integer
// Programming, 1986, section 8.5), after the exact affine change of coordinates to the box's frame.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_obb.cpp).
//
// convex_polyhedron3 against polygon3, and the test of a polygon against a half-space set that
// frustum_polygon and kdop_polygon share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded) and the polygon's point set (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): an edge of the polygon meets the set (the generalised slab test of
// convex_polyhedron_segment.cppm), or else the set's section Q by the polygon's plane H lies
// wholly inside the polygon or outside it, and one vertex of Q decides: two planes of the set
// whose normals are independent of H's normal n cross H at v = V / D (D = det(n_i, n_j, n),
// V = c_i n_j x n + c_j n x n_i + (n . a) n_i x n_j, as in convex_polyhedron_triangle.cppm), the
// first such v in every half-space (degree 6) is tested by the homogeneous crossing test of
// point_polygon.cppm (degree <= 7); in a filter pass, first by planeq::rounded_inside (v in double
// within a proven radius from the filter's values of V and D). A Q that lies inside the polygon is bounded, so it has a
// vertex; an unbounded Q lies outside, and its vertex (if any) says so.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5; the
// boundary-plus-inside decomposition of point_polygon.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_polygon.cpp).
//
// convex_polyhedron3 against tetrahedron3, contains(convex_polyhedron3, tetrahedron3), and the test
// of a tetrahedron against a half-space set that frustum_tetrahedron and kdop_tetrahedron share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed solid
// tetrahedron (coplanar vertices: their hull; a non-finite vertex: no tetrahedron). Touching at a
// vertex, an edge or a face counts. contains: the four vertices in the set (it is convex).
// Method (exact tiers): the tetrahedron T meets the set P iff one of its four faces meets P (the
// triangle test of convex_polyhedron_triangle.cppm, its six edges once, then each face's section)
// or P lies inside T. When no face meets P, the convex P does not cross T's boundary, so it lies
// inside T or outside it; inside, it is bounded and not empty, so it has a vertex (first_vertex
// of aabb_convex_polyhedron.cppm, v = V / D).
// That vertex decides: it is in T iff for every face (p, q, r) with the remaining vertex s,
// sign(det(q - p, r - p, V - p D)) is zero or sign(D) sign(det(q - p, r - p, s - p)) (degree 6).
// A flat tetrahedron is its faces. First, a plane of P with the four vertices beyond it says no.
// Source: the boundary-plus-inside decomposition (point_tetrahedron.cppm), with Schrijver, Theory
// of Linear and Integer Programming, 1986, section 8.5 (a nonempty pointed polyhedron has a
// vertex).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_tetrahedron.cpp).
module;
#include <array>
#include <cstddef>
#include <utility>
export module incidence.detail:engines.halfspace_meets;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.separating_axes;
import :engines.tetrahedron;
import :engines.box;
import :engines.halfspace_slabs;
import :engines.halfspace_lp;
import :engines.mesh;
import :engines.polygon3;

export namespace incidence::detail {

namespace halfspaces {

// One of the m planes with the n points point(0), ..., point(n - 1) all proven beyond it (by the
// filter's probe, no exact sign): their hull misses the set.
template <class K, class Points>
[[nodiscard]] constexpr bool beyond_one_plane(K& k, const plane3* planes, int m, const Points& point, std::size_t n) {
    for (int i = 0; i < m; ++i) {
        const plane3 h = planes[i];
        bool beyond = true;
        for (std::size_t v = 0; v < n && beyond; ++v) {
            const point3 x = point(v);
            beyond = arith::sgn<arith::hint::optional>(k, [=](auto L) {
                         return L(h.offset) * L(1.0) - arith::dot(arith::lift(L, h.normal), arith::lift(L, x));
                     }) == sign::negative;
        }
        if (beyond) return true;
    }
    return false;
}

// Whether the section Q of the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i by the
// plane of the finite triangle t meets t, where the caller found that t's edges miss the set.
template <class K>
[[nodiscard]] constexpr bool section_meets(K& k, const triangle3& t, const plane3* planes, int m) {
    constexpr int capacity = convex_polyhedron3::capacity;
    const point3 corner[3] = {t.a, t.b, t.c};
    // a degenerate triangle is its edges
    auto normal = [=](auto L) {
        return arith::cross(arith::lift(L, t.b) - arith::lift(L, t.a), arith::lift(L, t.c) - arith::lift(L, t.a));
    };
    if (arith::sgn<arith::hint::often_zero>(k, [=](auto L) { return normal(L).x; }) == sign::zero &&
        arith::sgn<arith::hint::often_zero>(k, [=](auto L) { return normal(L).y; }) == sign::zero &&
        arith::sgn<arith::hint::often_zero>(k, [=](auto L) { return normal(L).z; }) == sign::zero)
        return false;
    // the vertices of Q: planes i and j of P crossing H at v = V / D
    auto parallel = [planes](int x, int y) {
        const vec3 a = planes[x].normal, c = planes[y].normal;
        return (a.x == 0 && a.y == 0 && a.z == 0) || (c.x == 0 && c.y == 0 && c.z == 0) || (a.x == c.x && a.y == c.y && a.z == c.z) ||
               (a.x == -c.x && a.y == -c.y && a.z == -c.z);
    };
    std::array<sign, capacity> s{};
    for (int i = 0; i < m; ++i) {
        for (int j = i + 1; j < m; ++j) {
            if (parallel(i, j)) continue;
            const plane3 pi = planes[i], pj = planes[j];
            auto D = [=](auto L) { return arith::det3(arith::lift(L, pi.normal), arith::lift(L, pj.normal), normal(L)); };
            auto V = [=](auto L) {
                const auto n = normal(L);
                const auto ni = arith::lift(L, pi.normal), nj = arith::lift(L, pj.normal);
                const auto one = L(1.0);
                const auto ci = L(pi.offset) * one, cj = L(pj.offset) * one;
                const auto h = arith::dot(n, arith::lift(L, t.a));
                const auto x = arith::cross(nj, n), y = arith::cross(n, ni);
                const auto z = arith::cross(ni, nj);
                using T = decltype(ci * x.x + cj * y.x + h * z.x);
                return arith::v3<T>{ci * x.x + cj * y.x + h * z.x, ci * x.y + cj * y.y + h * z.y, ci * x.z + cj * y.z + h * z.z};
            };
            const sign d = arith::sgn<arith::hint::often_zero>(k, D);
            if (d == sign::zero) continue; // no single point
            // D and V lifted into the filter once for all the conditions of this pair
            const arith::lifted_once<K, decltype(D)> Dl{D};
            const arith::lifted_once<K, decltype(V)> Vl{V};
            // condition r < m: v in half-space r (c_r D - n_r . V); r = m + e: v on the inner side
            // of the triangle's edge e, from corner e to e + 1 (((q - p) x (V - p D)) . n)
            auto in_plane = [=, &Dl, &Vl](int r) {
                const plane3 h = planes[r];
                return [=, &Dl, &Vl](auto L) { return L(h.offset) * L(1.0) * Dl(L) - arith::dot(arith::lift(L, h.normal), Vl(L)); };
            };
            auto in_edge = [=, &Dl, &Vl](int e) {
                const point3 p = corner[e], q = corner[(e + 1) % 3];
                return [=, &Dl, &Vl](auto L) {
                    const auto P = arith::lift(L, p);
                    const auto d = Dl(L);
                    const auto v = Vl(L);
                    using T = decltype(v.x - P.x * d);
                    const arith::v3<T> w{v.x - P.x * d, v.y - P.y * d, v.z - P.z * d};
                    return arith::dot(arith::cross(arith::lift(L, q) - P, w), normal(L));
                };
            };
            // settled: a third plane through the point, or an ulp off it, is common (see first_row_vertex)
            auto decided = [&](int r) {
                return r < m ? arith::sgn<arith::hint::often_zero>(k, in_plane(r)) : arith::sgn<arith::hint::often_zero>(k, in_edge(r - m));
            };
            // a half-space proven violated skips the pair; the proven ones are kept
            bool out = false;
            for (int r = 0; r < m && !out; ++r) {
                if (r == i || r == j) continue;
                s[static_cast<unsigned>(r)] = arith::sgn<arith::hint::optional>(k, in_plane(r));
                out = s[static_cast<unsigned>(r)] == -d;
            }
            if (out) continue;
            bool inside = true;
            for (int r = 0; r < m && inside; ++r) {
                if (r == i || r == j || s[static_cast<unsigned>(r)] == d) continue;
                const sign x = decided(r);
                inside = x == sign::zero || x == d;
            }
            if (!inside) continue;
            // v is a vertex of Q, and the edges miss P, so Q lies inside the triangle or apart from
            // it (Q is connected and does not meet the triangle's boundary): v decides
            for (int r = m; r < m + 3; ++r)
                if (const sign x = decided(r); x != sign::zero && x != d) return false;
            return true;
        }
    }
    return false;
}

// Does the solid triangle t meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool triangle_meets(K& k, const triangle3& t, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !finite(t)) return false;
    const point3 corner[3] = {t.a, t.b, t.c};
    if (beyond_one_plane(k, planes, m, [&](std::size_t v) { return corner[v]; }, 3)) return false;
    // the edges
    for (int v = 0; v < 3; ++v)
        if (halfspaces<slab_extent::segment>(k, planes, m, corner[v], vec3{0, 0, 0}, corner[(v + 1) % 3])) return true;
    return section_meets(k, t, planes, m);
}

} // namespace halfspaces

namespace halfspaces {

// The vertex of a half-space set where planes a, c and e meet, V / D, as solid_mesh::inside_at reads a
// point (solid_mesh::at_weighted: each parity sign times D).
struct set_vertex_point {
    plane3 a, c, e;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        return std::pair{vertex_numerator(lift, a, c, e),
                         arith::det3(arith::lift(lift, a.normal), arith::lift(lift, c.normal), arith::lift(lift, e.normal))};
    }
    [[nodiscard]] constexpr bool near(const aabb3&) const { return true; }
    [[nodiscard]] constexpr bool x_ray_misses(const aabb3&) const { return false; }
};

// Does the mesh m meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool mesh_meets(K& k, const mesh3& m, const plane3* planes, int count) {
    if (!well_formed(planes, count, convex_polyhedron3::capacity) || !solid_mesh::well_formed(m) || m.triangles.empty()) return false;
    if (beyond_one_plane(k, planes, count, [&](std::size_t j) { return m.vertices[j]; }, m.vertices.size())) return false;
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        if (triangle_meets(k, m.triangle(i), planes, count)) return true;
    const set_vertex v = first_vertex(k, planes, static_cast<unsigned>(count));
    if (!v.found) return false;
    return solid_mesh::inside_at(k, m, solid_mesh::at_weighted<set_vertex_point>{{v.i, v.j, v.l}});
}

} // namespace halfspaces

namespace halfspaces {

// The box's six faces and the m planes of a set, read in the box's own coordinates s: row x < 6
// is the face +-s_(x/2) <= h_(x/2) (through the identity frame), row 6 + i is plane i of the set,
// sum_j (n . a_j) s_j <= d - n . c. Every normal is of degree 2 and every offset of degree 3 (its
// terms balanced with a lifted 1), written as one expression for both kinds of rows.
struct frame_rows {
    const plane3* p;
    unsigned m;
    const obb3* b;
    sign axes; // sign(det A), A: the box's axes as columns (triple_sign)
    [[nodiscard]] constexpr unsigned size() const { return m + 6; }
    [[nodiscard]] constexpr bool zero(unsigned x) const { return x >= 6 && zero_normal(p, x - 6); }
    [[nodiscard]] constexpr bool parallel(unsigned x, unsigned y) const {
        if (x < 6 && y < 6) return x / 2 == y / 2;
        return x >= 6 && y >= 6 && parallel_normals(p, x - 6, y - 6);
    }
    struct row {
        vec3 n, a0, a1, a2;
        point3 c;
        double d;
    };
    [[nodiscard]] constexpr row at(unsigned x) const {
        if (x >= 6) return {p[x - 6].normal, b->axes[0], b->axes[1], b->axes[2], b->center, p[x - 6].offset};
        const double s = (x & 1u) ? -1.0 : 1.0;
        const unsigned j = x / 2;
        const vec3 n{j == 0 ? s : 0.0, j == 1 ? s : 0.0, j == 2 ? s : 0.0};
        return {n, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}, b->half_extents[j]};
    }
    template <class L>
    [[nodiscard]] constexpr auto normal(L l, unsigned x) const {
        const row r = at(x);
        const auto n = arith::lift(l, r.n);
        using T = decltype(arith::dot(n, arith::lift(l, r.a0)));
        return arith::v3<T>{arith::dot(n, arith::lift(l, r.a0)), arith::dot(n, arith::lift(l, r.a1)), arith::dot(n, arith::lift(l, r.a2))};
    }
    template <class L>
    [[nodiscard]] constexpr auto offset(L l, unsigned x) const {
        const row r = at(x);
        return (l(r.d) * l(1.0) - arith::dot(arith::lift(l, r.n), arith::lift(l, r.c))) * l(1.0);
    }
    // The sign of det(A^T n_i, A^T n_j, A^T n_l) for three planes of the set (A: the axes as
    // columns) is sign(det A) sign(det(n_i, n_j, n_l)), exactly (the determinant is
    // multiplicative): dependent normals, such as a k-DOP's (1, 0, 0), (0, 1, 0) and (1, 1, 0),
    // give an exact zero that the cheap stages settle on the normals alone, where the product with
    // the axes rounds. Rows with a box face: the lifted det.
    template <class K, class Det>
    [[nodiscard]] constexpr sign triple_sign(K& k, unsigned i, unsigned j, unsigned l, const Det& det) const {
        if (i < 6 || j < 6 || l < 6) return arith::sgn<arith::hint::often_zero>(k, det);
        const vec3 a = p[i - 6].normal, c = p[j - 6].normal, e = p[l - 6].normal;
        const sign n = arith::sgn<arith::hint::often_zero>(
            k, [=](auto L) { return arith::det3(arith::lift(L, a), arith::lift(L, c), arith::lift(L, e)); });
        return axes == sign::positive ? n : axes == sign::negative ? -n : sign::zero;
    }
    // The decided sign of c_h D - n_h . V (vertex_of_rows) for four planes of the set is sign(det A)
    // times the same sign on the planes as given: it is the 4 x 4 determinant of the rows, and the
    // rows in s are (n, d) [[A, -c], [0, 1]], whose determinant is det A. Degree 4 instead of 9, so
    // a fourth plane exactly through the vertex of three (a k-DOP's corner) is settled by the cheap
    // exact stages, where the rows in s went to the big integers. In plain double (no filter to
    // lift): the rows in s, as that tier rounds them.
    template <class K, class F>
    [[nodiscard]] constexpr sign beyond_sign(K& k, unsigned i, unsigned j, unsigned l, unsigned h, const F& in_frame) const {
        if (!arith::lifts_filter<K>() || i < 6 || j < 6 || l < 6 || h < 6) return arith::sgn<arith::hint::decisive>(k, in_frame);
        const plane_rows w{p, m};
        const sign s = arith::sgn<arith::hint::decisive>(k, [=](auto L) { return four_rows(L, w, i - 6, j - 6, l - 6, h - 6); });
        return axes == sign::positive ? s : axes == sign::negative ? -s : sign::zero;
    }
};

// d - n . c + t sum_j h_j |n . a_j| (t = +1: the box's farthest point along -n is inside the plane
// iff >= 0, so < 0 puts the whole box beyond it; t = -1: the whole box inside iff >= 0).
template <class L>
[[nodiscard]] constexpr auto box_reach(L l, const obb3& b, const plane3& h, bool farthest) {
    const auto n = arith::lift(l, h.normal);
    const auto one = l(1.0);
    const auto gap = (l(h.offset) * one - arith::dot(n, arith::lift(l, b.center))) * one;
    using sat::magnitude;
    const auto r = l(b.half_extents[0]) * magnitude(arith::dot(n, arith::lift(l, b.axes[0]))) +
                   l(b.half_extents[1]) * magnitude(arith::dot(n, arith::lift(l, b.axes[1]))) +
                   l(b.half_extents[2]) * magnitude(arith::dot(n, arith::lift(l, b.axes[2])));
    return farthest ? gap - r : gap + r;
}

// Does the box meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool obb_meets(K& k, const obb3& b, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !sat::well_formed(b) || !finite(b)) return false;
    for (int i = 0; i < m; ++i) { // a plane with the whole box beyond it
        const plane3 h = planes[i];
        if (k.sgn([=](auto L) { return box_reach(L, b, h, false); }) == sign::negative) return false;
    }
    // A point of the box strictly inside every plane: checks whose failure decides nothing. The
    // centre, then for each plane it is not proven inside, the box corner least along that normal
    // (c + sum_j s_j h_j a_j, s_j = -1 where n . a_j > 0 in double, else 1: a corner whichever way
    // the rounding chooses; its signs are of degree 3, the corner itself is never rounded).
    auto centre_inside = [&](int first) {
        for (int i = first; i < m; ++i) {
            const plane3 h = planes[i];
            if (arith::sgn<arith::hint::optional>(k, [=](auto L) {
                    return L(h.offset) * L(1.0) - arith::dot(arith::lift(L, h.normal), arith::lift(L, b.center));
                }) != sign::positive)
                return i;
        }
        return m;
    };
    auto corner_inside = [&](vec3 along) {
        double s[3];
        for (unsigned j = 0; j < 3; ++j) s[j] = dot(along, b.axes[j]) > 0 ? -b.half_extents[j] : b.half_extents[j];
        for (int i = 0; i < m; ++i) {
            const plane3 h = planes[i];
            if (arith::sgn<arith::hint::optional>(k, [=](auto L) {
                    const auto n = arith::lift(L, h.normal);
                    const auto one = L(1.0);
                    const auto gap = (L(h.offset) * one - arith::dot(n, arith::lift(L, b.center))) * one;
                    return gap - (L(s[0]) * arith::dot(n, arith::lift(L, b.axes[0])) + L(s[1]) * arith::dot(n, arith::lift(L, b.axes[1])) +
                                  L(s[2]) * arith::dot(n, arith::lift(L, b.axes[2])));
                }) != sign::positive)
                return false;
        }
        return true;
    };
    int outside = centre_inside(0);
    if (outside == m) return true;
    for (; outside < m; outside = centre_inside(outside + 1))
        if (corner_inside(planes[outside].normal)) return true;
    const sign axes = arith::sgn<arith::hint::often_zero>(
        k, [=](auto L) { return arith::det3(arith::lift(L, b.axes[0]), arith::lift(L, b.axes[1]), arith::lift(L, b.axes[2])); });
    return first_row_vertex(k, frame_rows{planes, static_cast<unsigned>(m), &b, axes}).found;
}
// Is the whole box inside the m half-spaces? (Every plane read, so a NaN gives no in the exact tier.)
template <class K>
[[nodiscard]] constexpr bool obb_inside(K& k, const obb3& b, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !sat::well_formed(b) || !finite(b)) return false;
    bool all = true;
    for (int i = 0; i < m; ++i) {
        const plane3 h = planes[i];
        all = k.sgn([=](auto L) { return box_reach(L, b, h, true); }) != sign::negative && all;
    }
    return all;
}

} // namespace halfspaces

namespace halfspaces {

// Does the polygon g meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool polygon_meets(K& k, const polygon3& g, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !polygon3d::usable(k, g)) return false;
    if (polygon3d::any_edge(g, [&](const segment3& e) { return halfspaces<slab_extent::segment>(k, planes, m, e.a, vec3{0, 0, 0}, e.b); }))
        return true;
    const point3 a = g.vertices[g.plane_vertices[0]];
    for (int i = 0; i < m; ++i) {
        for (int j = i + 1; j < m; ++j) {
            if (zero_normal(planes, static_cast<unsigned>(i)) || zero_normal(planes, static_cast<unsigned>(j)) ||
                parallel_normals(planes, static_cast<unsigned>(i), static_cast<unsigned>(j)))
                continue;
            const plane3 pi = planes[i], pj = planes[j];
            auto D = [=](auto L) { return arith::det3(arith::lift(L, pi.normal), arith::lift(L, pj.normal), polygon3d::normal(L, g)); };
            auto V = [=](auto L) {
                const auto n = polygon3d::normal(L, g);
                const auto ni = arith::lift(L, pi.normal), nj = arith::lift(L, pj.normal);
                const auto one = L(1.0);
                const auto ci = L(pi.offset) * one, cj = L(pj.offset) * one;
                const auto h = arith::dot(n, arith::lift(L, a));
                const auto x = arith::cross(nj, n), y = arith::cross(n, ni);
                const auto z = arith::cross(ni, nj);
                using T = decltype(ci * x.x + cj * y.x + h * z.x);
                return arith::v3<T>{ci * x.x + cj * y.x + h * z.x, ci * x.y + cj * y.y + h * z.y, ci * x.z + cj * y.z + h * z.z};
            };
            const sign d = arith::sgn<arith::hint::often_zero>(k, D);
            if (d == sign::zero) continue; // no single point
            // D and V lifted into the filter once for every condition
            const arith::lifted_once<K, decltype(D)> Dl{D};
            const arith::lifted_once<K, decltype(V)> Vl{V};
            auto in_plane = [=, &Dl, &Vl](int r) {
                const plane3 h = planes[r];
                return [=, &Dl, &Vl](auto L) { return L(h.offset) * L(1.0) * Dl(L) - arith::dot(arith::lift(L, h.normal), Vl(L)); };
            };
            bool out = false; // a condition the filter proves violated skips the pair
            for (int r = 0; r < m && !out; ++r)
                if (r != i && r != j) out = arith::sgn<arith::hint::optional>(k, in_plane(r)) == -d;
            if (out) continue;
            bool in = true;
            for (int r = 0; r < m && in; ++r) {
                if (r == i || r == j) continue;
                const sign x = k.sgn(in_plane(r));
                in = x == sign::zero || x == d;
            }
            if (!in) continue;
            if (arith::rounded_stage_applies<K>())
                if (const certainty s = polygon3d::rounded_inside(g, Vl.kept, Dl.kept); s != certainty::uncertain)
                    return s == certainty::yes;
            return polygon3d::inside(k, g, polygon3d::at_homogeneous<decltype(V), decltype(D)>{V, D, d});
        }
    }
    return false;
}

} // namespace halfspaces

namespace halfspaces {

// Does the solid tetrahedron t meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool tetrahedron_meets(K& k, const tetrahedron3& t, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !finite(t)) return false;
    const point3 v[4] = {t.a, t.b, t.c, t.d};
    if (beyond_one_plane(k, planes, m, [&](std::size_t j) { return v[j]; }, 4)) return false;
    // the six edges, then each face's section (section_meets: its edges miss the set), unless the
    // face's corners lie beyond one plane
    for (int x = 0; x < 3; ++x)
        for (int y = x + 1; y < 4; ++y)
            if (halfspaces<slab_extent::segment>(k, planes, m, v[x], vec3{0, 0, 0}, v[y])) return true;
    for (int f = 0; f < 4; ++f) {
        const triangle3 face = t.face(f);
        const point3 corner[3] = {face.a, face.b, face.c};
        if (!beyond_one_plane(k, planes, m, [&](std::size_t j) { return corner[j]; }, 3) && section_meets(k, face, planes, m)) return true;
    }
    // face f is (p, q, r), the vertices other than v[f] in order; s = v[f]
    auto face_det = [=](int f, auto L, const auto& x) {
        const point3 p = v[f == 0 ? 1 : 0], q = v[f <= 1 ? 2 : 1], r = v[f <= 2 ? 3 : 2];
        const auto P = arith::lift(L, p);
        return arith::det3(arith::lift(L, q) - P, arith::lift(L, r) - P, x(P));
    };
    const sign o = k.sgn([=](auto L) { return face_det(3, L, [=](const auto& P) { return arith::lift(L, v[3]) - P; }); });
    if (o == sign::zero) return false; // flat: its faces
    const set_vertex c = first_vertex(k, planes, static_cast<unsigned>(m));
    if (!c.found) return false; // empty, or unbounded without a vertex: not inside T
    for (int f = 0; f < 4; ++f) {
        const point3 s = v[f];
        const sign side = f == 3 ? o : k.sgn([=](auto L) { return face_det(f, L, [=](const auto& P) { return arith::lift(L, s) - P; }); });
        const plane3 a = c.i, b = c.j, e = c.l;
        const sign w = k.sgn([=](auto L) {
            return face_det(f, L, [=](const auto& P) {
                const auto V = vertex_numerator(L, a, b, e);
                const auto D = arith::det3(arith::lift(L, a.normal), arith::lift(L, b.normal), arith::lift(L, e.normal));
                using T = decltype(V.x - P.x * D);
                return arith::v3<T>{V.x - P.x * D, V.y - P.y * D, V.z - P.z * D};
            });
        });
        if (w != sign::zero && w != (c.d == sign::positive ? side : -side)) return false;
    }
    return true;
}

} // namespace halfspaces

} // namespace incidence::detail
