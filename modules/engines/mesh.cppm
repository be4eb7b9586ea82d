// mesh3 against point3, contains(mesh, point), and the engine every mesh pair shares.
// Semantics: the mesh's point set is its triangles together with the points from which a ray
// crosses the surface an odd number of times (shapes/mesh3.cppm); a point on a triangle counts.
// Method (exact tiers): any other shape X (connected) meets that set iff it meets a triangle, or
// else lies wholly off the surface, where one point of X decides by the parity of crossings.
// The parity: the ray from p along u_j = (1, c_j, c_j^2), c_j = 0, 1, -1, 2, -2, ..., crosses a
// triangle's interior iff the three Pluecker signs u . ((a - p) x (b - p)), ... (degree 2) are
// all strictly of one sign s and the crossing lies ahead, det(a - p, b - p, c - p) of sign s
// (degree 3; their sum is u . n, so the crossing's parameter has the sign of both). A zero
// among signs that do not disagree is a ray through an edge or a vertex ahead, or in a
// triangle's plane: that direction is dropped and the next tried. Each edge plane, triangle plane
// and vertex direction rules out at most two values of c (u_j . w is a quadratic in c), so a
// clean direction comes within 8F + V + 8 tries; collinear triangles have no interior and are
// skipped. The vertices' bounding box answers first (outside it: outside), and along +x a
// triangle whose bounding box the ray misses is skipped.
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994), the crossings test,
// in 3D with exact orientation signs; the perturbation by a moment curve of directions follows
// Edelsbrunner and Muecke, "Simulation of Simplicity", ACM TOG 9(1), 1990, section 4 (a generic
// choice from a one-parameter family instead of a symbolic one).
// Approximate tier: the same signs in plain double (a ray may pass through an edge undetected,
// so a point near the surface may get the wrong parity). Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/mesh_point.cpp).
//
// mesh3 against segment3 (a point when a == b), and contains(mesh, segment).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any triangle meeting the segment (segment_triangle), else the parity of an end point.
// contains: every point of the segment a + t (b - a), 0 <= t <= 1, in the set. The parameters
// where the segment meets the surface form closed intervals; their end points are breakpoints: a
// triangle met across its plane gives t = det(b0 - a0, c0 - a0, a0 - a) / det(b0 - a0, c0 - a0,
// b - a); a triangle whose plane holds the segment (or a collinear one) gives, for each edge p q,
// where the segment's line meets the plane through p q along a coordinate axis e_k (where the
// edge's line crosses it), or, for an edge parallel to the segment, the parameters of p and q. All
// are det(E, F, x - a) / det(E, F, b - a) for two difference vectors E, F (edges, or unit axes
// lifted as L(1) - L(0), an input of degree 1), of degree 3 over degree 3; extra breakpoints
// only split an interval in two. Between two consecutive breakpoints (sorted exactly, degree 6)
// the segment lies wholly on one triangle in its plane or wholly off the surface, where parity is
// constant: one point of the piece decides, on such a triangle or by the crossing parity of
// mesh_point.cppm: a + t (b - a) for a double t proven between the two (degree 4), or else the
// exact midpoint V / W (V of degree 7, W = 2 D1 D2 > 0; degree 8 on the triangle, 9 for the
// parity). No triangle meeting the segment: the parity of an end point. The breakpoints are kept in a std::vector (an allocation
// only when the segment meets the surface).
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); the segment split at its crossings, as in point-in-polyhedron segment
// classification (O'Rourke, Computational Geometry in C, 2nd ed., 7.5).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent, or (contains) when a deciding sign's permanent leaves [2^-900, 2^900], where plain
// double under- or overflows: its signs have degree up to 9, so from inputs beyond about 2^+-90
// on (tests/query/mesh_segment.cpp).
//
// mesh3 against triangle3 (a collinear triangle is its hull), and contains(mesh, triangle).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any mesh triangle meeting it (triangle_triangle), else the parity
// of a vertex.
// contains: every point of the triangle t = a b c in the set. A collinear t is its three edges
// (contains(mesh, segment)); otherwise its vertices first, and with no mesh triangle meeting t,
// one vertex decides. Else t's plane H is cut by the surface into lines: a triangle crossing H
// gives the segment where it does (its crossing flips the parity: toggle 1), a triangle with one
// edge in H gives that edge (toggle 1 when it rises on the positive side of H, else nothing),
// and a triangle lying in H covers its area (on the surface, so in the set). Chords from an apex
// a to e(s) = b + s (c - b) sweep t. The directions of the lines' end points (mesh vertices in H,
// edges crossing H), of the points where lines meet b c, and of the points where a line crosses an
// edge of a covering triangle, are exact rationals s = N / D (degree 3/3; a crossing on such an
// edge 5/5, the order of two of them degree 10); one double chord strictly inside each open
// interval between them meets every cell of the arrangement: within a sector no line ends, so
// every line there crosses that chord, and (apart from the covering triangles' edges, whose
// crossings are directions too) the cells' parities are sums of toggles that the chord sees in
// order. The chord's s is a double, or where a sector holds none, a sum of two or three (each
// lifted as an input, so no degree grows), or a pair chord (below). Along a chord (degree 2: a + t ((b - a) + s (c - b))),
// the lines are crossed at t = N / D (degree 4/4, or 3/3 for an edge in H; compared at degree 8);
// the parity starts inside at a free
// apex (a vertex on no triangle, inside), or else outside the mesh's box, the chord's line being
// followed from t = -infinity through every triangle (at a itself a half-open rule: only the lines
// leaving a to the chord's left are crossed). Every piece of the chord inside t must be covered or
// of odd parity. A chord through a point where two lines cross (only on a self-intersecting
// surface) is moved to the next double; after 32 such moves, or where a sector holds no sum of
// three doubles (two directions closer than about 2^-159 apart: nearly coincident line ends, as
// on two shells glued face to face and nudged by ulps), the chord is w0 V0 + w1 V1, a positive
// combination of the sector's two bounding directions (each of degree 4), strictly inside the
// sector however thin: along it a cut's parameter is n / d with n of degree 3 and d of 7 (ordered
// at degree 10), and a cut before the chord's end is one on a's side of b c (degree 9). Each point
// where two lines cross rules out one ratio w1 / w0, so one of lines^2 + 2 ratios gives a clean
// chord, and one apex decides (free apexes first, then a vertex with the line followed from
// outside; the next apex, and after all of them "not contained", only for an inexact kernel).
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); the sweep of a plane section by a pencil of lines through a vertex, cut
// at the arrangement's vertices (Bentley and Ottmann, IEEE Trans. Computers 28(9), 1979, in
// angular form); the surface perturbed to one side of H for its in-plane edges as in Edelsbrunner
// and Muecke, "Simulation of Simplicity", ACM TOG 9(1), 1990.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent, or (contains) when a deciding sign's permanent leaves [2^-900, 2^900], where plain
// double under- or overflows: its signs have degree up to 10, so from inputs beyond about 2^+-90
// on (tests/query/mesh_triangle.cpp).
//
// aabb3 against mesh3 (closed box; an inverted box is empty), and contains(mesh, box).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any mesh triangle meeting the box (the 13-axis aabb_triangle
// test; a mesh inside the box has its triangles inside it), else the parity of a corner.
// contains: every point of the box in the set. A flat box is its rectangle's two triangles, a
// segment or a point (contains(mesh, triangle | segment | point)). A full box B lies in the set
// iff its interior does, and its interior off the surface is cut into cells whose parities differ
// across a wall only where the surface there is covered an odd number of times: so B lies in the
// set iff (1) no plane holds an odd part of the surface inside B, and (2) one point of B's
// interior off the surface has odd parity. (1): the non-collinear triangles reaching B's interior
// (the 13 axes with touching counted as separated, aabb_triangle's meets_interior) are grouped by
// plane (orient3d, degree 3); a plane with one of them is odd there. With several (coplanar
// triangles of one surface side by side, or of two shells glued face to face), their coverage is
// odd somewhere inside B iff their edges, added up modulo 2 along each line (collinearity seen
// along an axis the plane is not parallel to, degree 2; end points ordered by one coordinate),
// leave an odd piece reaching B's interior (a segment p q as the triangle p q q), or else the
// coverage, constant inside B, is odd at one point: where a diagonal of B whose corners lie
// strictly on either side crosses the plane, X = (s' k - s k') / (s' - s) with s = orient3d at
// the corners (degree 4 over 3), counted in each triangle seen along that axis and moved by
// eps e_u + eps^2 e_v off any edge through it (degree 5, then coordinate comparisons). (2): the
// parity at B's centre, V / W = (0.5 (min + max)) / 1 (mesh_point.cppm; the ray from a point on the
// surface counts the crossings of the point just ahead of it, inside B; degree 4).
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); the cells of a polyhedral subdivision and the parity change across a
// wall as in Edelsbrunner, Algorithms in Combinatorial Geometry (1987), ch. 7; the perturbed
// point as in Edelsbrunner and Muecke, "Simulation of Simplicity", ACM TOG 9(1), 1990.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/aabb_mesh.cpp); contains of a flat box (through contains(mesh,
// triangle), degree up to 10) also when a deciding sign's permanent leaves [2^-900, 2^900],
// from inputs beyond about 2^+-90 on.
module;
#include <type_traits>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>
export module incidence.detail:engines.mesh;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.triangle;
import :engines.tetrahedron;
import :engines.box;
import :intersects.triangle_pairs;
import :engines.box_triangle;
import :engines.segment_pieces;

export namespace incidence::detail {

namespace solid_mesh {

// Every index names a vertex and every vertex is finite (comparisons only).
[[nodiscard]] constexpr bool well_formed(const mesh3& m) {
    if (!m.indices_valid()) return false;
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
        if (!finite(m.vertices[i])) return false;
    return true;
}
// The vertices' bounding box (a well-formed mesh).
// The bounds of points and shapes, and their overlap (segment_segment.cppm), also under this name.
using detail::bounds;
using detail::boxes_meet;
[[nodiscard]] constexpr aabb3 bounds(const mesh3& m) { return bounds(m.vertices.data(), m.vertices.size()); }
[[nodiscard]] constexpr bool in_box(const aabb3& b, const point3& p) { return boxes_meet(b, bounds(p)); }

// The point whose parity is sought: a double point p (at_point) or a rational one, V / W with
// W > 0 (the homogeneous point of a caller). pl(L, x, y) has the sign of u . ((x - p) x (y - p)),
// ahead(L, a, b, c) that of det(a - p, b - p, c - p); near(box) is false only for a point known
// outside the box (comparisons), and along +x a triangle whose box the ray misses is skipped.
struct at_point {
    point3 p;
    template <class L>
    [[nodiscard]] constexpr auto pl(L lift, const vec3& u, const point3& x, const point3& y) const {
        const auto P = arith::lift(lift, p);
        return arith::dot(arith::lift(lift, u), arith::cross(arith::lift(lift, x) - P, arith::lift(lift, y) - P));
    }
    template <class L>
    [[nodiscard]] constexpr auto ahead(L lift, const point3& a, const point3& b, const point3& c) const {
        return poly::orient3d(lift, a, b, c, p); // det(a - p, b - p, c - p)
    }
    [[nodiscard]] constexpr bool near(const aabb3& b) const { return in_box(b, p); }
    [[nodiscard]] constexpr bool x_ray_misses(const aabb3& tb) const {
        return tb.max.x < p.x || p.y < tb.min.y || p.y > tb.max.y || p.z < tb.min.z || p.z > tb.max.z;
    }
};

// A rational point V / W as inside_at reads it, for any P whose weighted(L) gives {V, W} (W of
// either sign, nonzero): each parity sign is taken times W, u . (W (x x y) + (y - x) x V) and
// n . (W a - V) for a triangle a b c of normal n. W's sign flips all of them together, which
// leaves the decisions, agreements of those signs, as they are. P also gives near and
// x_ray_misses.
template <class P>
struct at_weighted : P {
    template <class L>
    [[nodiscard]] constexpr auto pl(L lift, const vec3& u, const point3& x, const point3& y) const {
        const auto [V, W] = this->weighted(lift);
        const auto X = arith::lift(lift, x), Y = arith::lift(lift, y);
        const auto xy = arith::cross(X, Y);
        const auto r = arith::cross(Y - X, V);
        using T = decltype(W * xy.x + r.x);
        return arith::dot(arith::lift(lift, u), arith::v3<T>{W * xy.x + r.x, W * xy.y + r.y, W * xy.z + r.z});
    }
    template <class L>
    [[nodiscard]] constexpr auto ahead(L lift, const point3& a0, const point3& b0, const point3& c0) const {
        const auto [V, W] = this->weighted(lift);
        const auto A = arith::lift(lift, a0);
        const auto n = arith::cross(arith::lift(lift, b0) - A, arith::lift(lift, c0) - A);
        using T = decltype(W * A.x - V.x);
        return arith::dot(n, arith::v3<T>{W * A.x - V.x, W * A.y - V.y, W * A.z - V.z});
    }
};

// The crossings of the ray from q along direction j (u_j = (1, c_j, c_j^2)): whether they are odd,
// nothing when not clean (through an edge or a vertex, or in a triangle's plane). Tentative: every sign by
// hint::optional, which may answer zero for a sign it cannot prove without touching the query's
// certainty, and any such zero that would matter makes the direction unclean.
template <class K, class Q>
[[nodiscard]] constexpr std::optional<bool> crossings(K& k, const mesh3& m, const Q& q, std::size_t j, bool tentative) {
    const double c = j == 0 ? 0.0 : (j % 2 ? double((j + 1) / 2) : -double(j / 2));
    const vec3 u{1.0, c, c * c};
    auto sgn = [&](const auto& f) { return tentative ? arith::sgn<arith::hint::optional>(k, f) : k.sgn(f); };
    bool odd = false;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        if (j == 0) { // the ray along +x misses a triangle whose box it misses (comparisons)
            const point3 v[3] = {t.a, t.b, t.c};
            if (q.x_ray_misses(bounds(v, 3))) continue;
        }
        auto pl = [&](point3 x, point3 y) { return sgn([=](auto L) { return q.pl(L, u, x, y); }); };
        const sign s0 = pl(t.a, t.b), s1 = pl(t.b, t.c), s2 = pl(t.c, t.a);
        const bool pos = s0 == sign::positive || s1 == sign::positive || s2 == sign::positive;
        const bool neg = s0 == sign::negative || s1 == sign::negative || s2 == sign::negative;
        if (pos && neg) continue; // the ray's line misses the triangle
        if (!pos && !neg) {       // in the triangle's plane, or a collinear triangle
            if (tentative) return std::nullopt;
            const point3 a = t.a, b = t.b, cc = t.c;
            bool collinear = true;
            for (int axis = 0; axis < 3 && collinear; ++axis)
                collinear = arith::is_zero(k, [=](auto L) {
                    const auto n = arith::cross(arith::lift(L, b) - arith::lift(L, a), arith::lift(L, cc) - arith::lift(L, a));
                    return axis == 0 ? n.x : (axis == 1 ? n.y : n.z);
                });
            if (!collinear) return std::nullopt;
            continue;
        }
        const sign s = pos ? sign::positive : sign::negative;
        const point3 a = t.a, b = t.b, cc = t.c;
        const sign d = sgn([=](auto L) { return q.ahead(L, a, b, cc); });
        if (tentative && d == sign::zero) return std::nullopt;
        // det(a - p, b - p, c - p): the crossing lies ahead iff it has sign s
        if (d != s) continue;
        if (s0 == sign::zero || s1 == sign::zero || s2 == sign::zero) return std::nullopt; // through an edge or vertex
        odd = !odd;
    }
    return odd;
}

// Is the point q, off the surface, inside (odd crossings)? For a closed surface every clean
// direction gives the same parity, so a kernel that can probe (the filter, the exact kernel's
// filter stages) first tries a few directions on signs it proves cheaply: an axis-parallel edge
// makes the first direction unclean for every point, and the filter cannot prove that zero. Then
// every direction in turn with exact signs.
template <class K, class Q>
[[nodiscard]] constexpr bool inside_at(K& k, const mesh3& m, const Q& q) {
    if (!q.near(bounds(m))) return false;
    if constexpr (requires { k.probe([](auto L) { return L(0.0); }); })
        for (std::size_t j = 0; j < 4; ++j)
            if (const auto odd = crossings(k, m, q, j, true)) return *odd;
    const std::size_t tries = 8 * m.triangles.size() + m.vertices.size() + 8;
    for (std::size_t j = 0; j < tries; ++j) {
        if (const auto odd = crossings(k, m, q, j, false)) return *odd;
        if constexpr (requires { k.failed(); })
            if (k.failed()) return false; // a filter that failed a sign: its answer is discarded
    }
    return false; // reached only by inexact arithmetic (the approximate tier, a filter's guess)
}
template <class K>
[[nodiscard]] constexpr bool inside(K& k, const mesh3& m, point3 p) {
    return inside_at(k, m, at_point{p});
}

// The mesh's point set against the connected shape x: a triangle meets x, or p (a point of x)
// lies inside. The caller has checked the mesh well formed and x finite. With x's bounding box
// `xb` (bounded shapes), triangles whose own box misses it are skipped (comparisons).
template <class K, class Meets>
[[nodiscard]] constexpr bool mesh_meets(K& k, const mesh3& m, const Meets& meets, point3 p, const aabb3* xb = nullptr) {
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        if (xb != nullptr) {
            const point3 v[3] = {t.a, t.b, t.c};
            if (!boxes_meet(bounds(v, 3), *xb)) continue;
        }
        if (meets(t)) return true;
    }
    return inside(k, m, p);
}

} // namespace solid_mesh

namespace solid_mesh {

// A parameter along the segment s, t = N / D with N = det(E, F, x - a) and D = det(E, F, b - a),
// E = e1 - e0 and F = f1 - f0; both negated when `flip`, so that D > 0.
struct segment_param {
    point3 x, e0, e1, f0, f1;
    bool flip = false;
    template <class L>
    [[nodiscard]] constexpr auto fraction(L lift, const segment3& s) const {
        const auto E = arith::lift(lift, e1) - arith::lift(lift, e0), F = arith::lift(lift, f1) - arith::lift(lift, f0);
        const auto A = arith::lift(lift, s.a);
        const auto n = arith::det3(E, F, arith::lift(lift, x) - A), d = arith::det3(E, F, arith::lift(lift, s.b) - A);
        return flip ? std::pair{-n, -d} : std::pair{n, d};
    }
};
inline constexpr point3 origin{0.0, 0.0, 0.0};
[[nodiscard]] constexpr point3 unit(int axis) { return {axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0}; }

// A point of the segment s, inside its bounding box `box`: along +x the ray from it misses a
// triangle whose box the ray from any point of `box` misses.
struct in_segment_box {
    aabb3 box;
    [[nodiscard]] constexpr bool near(const aabb3&) const { return true; } // the caller checked the segment's box
    [[nodiscard]] constexpr bool x_ray_misses(const aabb3& tb) const {
        return tb.max.x < box.min.x || box.max.y < tb.min.y || box.min.y > tb.max.y || box.max.z < tb.min.z || box.min.z > tb.max.z;
    }
};
// The point a + t (b - a) for a double t, V / W with W = L(1) (a constant lifted as an input, so
// the signs stay homogeneous: degree 4 for the parity).
struct segment_at : in_segment_box {
    segment3 s;
    double t;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto W = lift(1.0), T = lift(t);
        const auto A = arith::lift(lift, s.a);
        const auto D = arith::lift(lift, s.b) - A;
        using U = decltype(W * A.x + T * D.x);
        return std::pair{arith::v3<U>{W * A.x + T * D.x, W * A.y + T * D.y, W * A.z + T * D.z}, W};
    }
};
// The point of s midway between the parameters lo and hi, V / W with W = 2 D_lo D_hi > 0 (degree
// 9 for the parity), where no double lies provably between them.
struct segment_point : in_segment_box {
    segment3 s;
    segment_param lo, hi;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto [n1, d1] = lo.fraction(lift, s);
        const auto [n2, d2] = hi.fraction(lift, s);
        const auto W = d1 * d2 + d1 * d2;
        const auto M = n1 * d2 + n2 * d1;
        const auto A = arith::lift(lift, s.a);
        const auto D = arith::lift(lift, s.b) - A;
        using T = decltype(W * A.x + M * D.x);
        return std::pair{arith::v3<T>{W * A.x + M * D.x, W * A.y + M * D.y, W * A.z + M * D.z}, W};
    }
};

// Is the midpoint q (of a segment in t's plane, or along a collinear t) on the triangle t?
template <class K, class Q>
[[nodiscard]] constexpr bool on_triangle(K& k, const triangle3& t, const Q& q) {
    const point3 v[3] = {t.a, t.b, t.c};
    auto normal = [&](int axis) {
        return k.sgn([=](auto L) {
            const auto a = arith::lift(L, v[0]);
            const auto n = arith::cross(arith::lift(L, v[1]) - a, arith::lift(L, v[2]) - a);
            return axis == 0 ? n.x : (axis == 1 ? n.y : n.z);
        });
    };
    // (y - x) x (V - W x), one component or all
    auto edge = [&](point3 x, point3 y, int axis) {
        return k.sgn([=, &q](auto L) {
            const auto [V, W] = q.weighted(L);
            const auto X = arith::lift(L, x);
            using T = decltype(V.x - W * X.x);
            const auto c = arith::cross(arith::lift(L, y) - X, arith::v3<T>{V.x - W * X.x, V.y - W * X.y, V.z - W * X.z});
            return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
        });
    };
    for (int axis = 0; axis < 3; ++axis)
        if (const sign n = normal(axis); n != sign::zero) { // the plane seen along this axis
            for (int i = 0; i < 3; ++i)
                if (const sign e = edge(v[i], v[(i + 1) % 3], axis); e != sign::zero && e != n) return false;
            return true;
        }
    // a collinear triangle: the union of its edges; (V - W x) . (y - x) >= 0 from both ends
    for (int i = 0; i < 3; ++i) {
        const point3 x = v[i], y = v[(i + 1) % 3];
        if (x.x == y.x && x.y == y.y && x.z == y.z) continue; // a point holds no piece
        if (edge(x, y, 0) != sign::zero || edge(x, y, 1) != sign::zero || edge(x, y, 2) != sign::zero) continue;
        auto from = [&](point3 p, point3 r) {
            return k.sgn([=, &q](auto L) {
                const auto [V, W] = q.weighted(L);
                const auto P = arith::lift(L, p);
                using T = decltype(V.x - W * P.x);
                return arith::dot(arith::v3<T>{V.x - W * P.x, V.y - W * P.y, V.z - W * P.z}, arith::lift(L, r) - P);
            });
        };
        if (from(x, y) != sign::negative && from(y, x) != sign::negative) return true;
    }
    return false;
}

} // namespace solid_mesh

namespace solid_mesh {

// The k-th component of u x v: the cross product of the projections along axis k.
template <class U, class V>
[[nodiscard]] constexpr auto cross_along(int k, const arith::v3<U>& u, const arith::v3<V>& v) {
    return k == 0 ? u.y * v.z - u.z * v.y : (k == 1 ? u.z * v.x - u.x * v.z : u.x * v.y - u.y * v.x);
}

// A chord's parameter s = c0 + c1 + c2, a sum of doubles (lifted as three inputs: the degrees do not
// change), so that a sector too thin to hold a double still holds an s.
struct sweep_s {
    double c[3] = {0.0, 0.0, 0.0};
    template <class L>
    [[nodiscard]] constexpr auto lift(L l) const {
        return l(c[0]) + l(c[1]) + l(c[2]);
    }
};

// The triangle a b c swept from its apex a by chords to e(s) = b + s (c - b), seen along `axis`
// (its normal's component there is nonzero).
struct sweep_frame {
    point3 a, b, c;
    int axis;
    // (b - a) + s (c - b), of degree 2 (with 1 lifted as an input)
    template <class L>
    [[nodiscard]] constexpr auto dir(L lift, const sweep_s& s) const {
        const auto one = lift(1.0);
        const auto S = s.lift(lift);
        const auto u = arith::lift(lift, b) - arith::lift(lift, a), w = arith::lift(lift, c) - arith::lift(lift, b);
        using T = decltype(u.x * one + S * w.x);
        return arith::v3<T>{u.x * one + S * w.x, u.y * one + S * w.y, u.z * one + S * w.z};
    }
    // The plane through a, b, c, as a segment_param's plane (the parameter where p q crosses it).
    [[nodiscard]] constexpr segment_param plane() const { return {a, a, b, a, c}; }
};

// A direction from the apex, as the s of the point where its line meets b c: a plane through
// the apex (or a plane b c crosses), s = det(E, F, x - b) / det(E, F, c - b) (degree 3/3); or
// (`on_edge`) the point z where the edge p q crosses `plane`, s = cross(b - a, Z) / cross(Z, c -
// b) along the axis with Z = (z - a) D (degree 5/5; D's sign cancels in the quotient). Negated
// so that the denominator is positive when `flip`.
struct sweep_dir {
    segment_param plane;
    bool on_edge = false;
    segment3 edge{};
    bool flip = false;
};
// (z - a) D for the point z = p + (N / D) (q - p) of the edge p q where it crosses the plane
// `at`: degree 4, of z - a's direction when D > 0 (at's flip).
template <class L>
[[nodiscard]] constexpr auto offset_on_edge(L lift, const segment_param& at, const segment3& e, const point3& a) {
    const auto [n, d] = at.fraction(lift, e);
    const auto P = arith::lift(lift, e.a), Q = arith::lift(lift, e.b), A = arith::lift(lift, a);
    using T = decltype((P.x - A.x) * d + (Q.x - P.x) * n);
    return arith::v3<T>{(P.x - A.x) * d + (Q.x - P.x) * n, (P.y - A.y) * d + (Q.y - P.y) * n, (P.z - A.z) * d + (Q.z - P.z) * n};
}
// use(f) with f(L) = {N, D} of the direction d (its own expression type for each kind).
template <class Use>
[[nodiscard]] constexpr auto with_dir(const sweep_frame& fr, const sweep_dir& d, const Use& use) {
    if (!d.on_edge) {
        segment_param p = d.plane;
        p.flip = d.flip;
        return use([p, bc = segment3{fr.b, fr.c}](auto L) { return p.fraction(L, bc); });
    }
    return use([fr, d](auto L) {
        const auto Z = offset_on_edge(L, d.plane, d.edge, fr.a);
        const auto n = cross_along(fr.axis, arith::lift(L, fr.b) - arith::lift(L, fr.a), Z);
        const auto den = cross_along(fr.axis, Z, arith::lift(L, fr.c) - arith::lift(L, fr.b));
        return d.flip ? std::pair{-n, -den} : std::pair{n, den};
    });
}

// Where a line of the section meets the chord: an end point of a crossing triangle's segment (a
// vertex in H, or where the edge p q crosses H, `at` made D > 0).
struct sweep_end {
    bool vertex = true;
    point3 p{}, q{};
    segment_param at{};
};
// A line of the section: kind 0, the segment where the triangle a0 a1 a2 crosses H (between e0
// and e1); kind 1, an edge a0 a1 lying in H. tau: the parity's change across it (0 or 1); band:
// the covering triangle whose edge it is, or -1.
struct sweep_line {
    int kind = 0;
    point3 a0{}, a1{}, a2{};
    sweep_end e0{}, e1{};
    int tau = 0;
    int band = -1;
    bool near = true; // from a triangle meeting t
};
// A line crossed by the chord at t = N / D (D > 0 with flip); pos: its group along the chord.
struct chord_cut {
    std::size_t line = 0;
    bool flip = false;
    int pos = 0;
};
// A chord of the sweep from the apex a: its direction dir(L); a cut at t = n / d along a + t dir,
// where num(L, x) balances a cut's numerator x with dir's degree; before(L, n, d), whose sign
// times before_sign is positive when the cut lies before the chord's end on b c.
// s_chord: the chord to e(s), dir = e(s) - a (degree 2, with 1 lifted), the end at t = 1.
struct s_chord {
    sweep_frame fr;
    sweep_s s;
    int before_sign = 1;
    template <class L>
    [[nodiscard]] constexpr auto dir(L lift) const {
        return fr.dir(lift, s);
    }
    template <class L, class T>
    [[nodiscard]] constexpr auto num(L lift, const T& x) const {
        return lift(1.0) * x;
    }
    template <class L, class N, class D>
    [[nodiscard]] constexpr auto before(L, const N& n, const D& d) const {
        return d - n;
    }
};
// The direction of a sector's bound from the apex, of degree 4 and pointing into the triangle:
// e(s) - a times D for a direction s = N / D (D > 0; s = 0 and 1 as the planes through b and c
// across b c along coordinate axes), or (z - a) D for a crossing z on an edge (`negate` when that
// D is negative).
struct sector_bound {
    sweep_dir d{};
    bool negate = false;
};
template <class L>
[[nodiscard]] constexpr auto bound_vector(L lift, const sweep_frame& fr, const sector_bound& b) {
    if (b.d.on_edge) {
        const auto Z = offset_on_edge(lift, b.d.plane, b.d.edge, fr.a);
        using T = decltype(Z.x);
        return b.negate ? arith::v3<T>{-Z.x, -Z.y, -Z.z} : Z;
    }
    segment_param p = b.d.plane;
    p.flip = b.d.flip;
    const auto [n, dd] = p.fraction(lift, segment3{fr.b, fr.c});
    const auto A = arith::lift(lift, fr.a), B = arith::lift(lift, fr.b);
    const auto u = B - A, w = arith::lift(lift, fr.c) - B;
    using T = decltype(u.x * dd + w.x * n);
    return arith::v3<T>{u.x * dd + w.x * n, u.y * dd + w.y * n, u.z * dd + w.z * n};
}
// pair_chord: w0 V0 + w1 V1 for the bounds V0, V1 of a sector (degree 5, strictly inside it
// however thin it is); a cut's numerator as it is (t = n / d is then of degree -4), and its side
// of b c, d S_a + n ((c - b) x dir) along the axis (degree 9), against that of a, S_a.
struct pair_chord {
    sweep_frame fr;
    sector_bound lo, hi;
    double w0 = 1.0, w1 = 1.0;
    int before_sign = 1; // the sign of S_a = (c - b) x (a - b) along the axis
    template <class L>
    [[nodiscard]] constexpr auto dir(L lift) const {
        const auto v0 = bound_vector(lift, fr, lo), v1 = bound_vector(lift, fr, hi);
        const auto x0 = lift(w0), x1 = lift(w1);
        using T = decltype(v0.x * x0 + v1.x * x1);
        return arith::v3<T>{v0.x * x0 + v1.x * x1, v0.y * x0 + v1.y * x1, v0.z * x0 + v1.z * x1};
    }
    template <class L, class T>
    [[nodiscard]] constexpr const T& num(L, const T& x) const {
        return x;
    }
    template <class L, class N, class D>
    [[nodiscard]] constexpr auto before(L lift, const N& n, const D& d) const {
        const auto B = arith::lift(lift, fr.b);
        const auto w = arith::lift(lift, fr.c) - B;
        return d * cross_along(fr.axis, w, arith::lift(lift, fr.a) - B) + n * cross_along(fr.axis, w, dir(lift));
    }
};
// use(f) with f(L) = {N, D} of the cut's parameter along the chord ch.
template <class Chord, class Use>
[[nodiscard]] constexpr auto with_cut(const sweep_frame& fr, const Chord& ch, const sweep_line& l, bool flip, const Use& use) {
    if (l.kind == 1)
        return use([fr, ch, l, flip](auto L) {
            const auto P = arith::lift(L, l.a0), A = arith::lift(L, fr.a);
            const auto e = arith::lift(L, l.a1) - P;
            const auto n = ch.num(L, cross_along(fr.axis, e, P - A));
            const auto d = cross_along(fr.axis, e, ch.dir(L));
            return flip ? std::pair{-n, -d} : std::pair{n, d};
        });
    return use([fr, ch, l, flip](auto L) {
        const auto P = arith::lift(L, l.a0), A = arith::lift(L, fr.a);
        const auto nf = arith::cross(arith::lift(L, l.a1) - P, arith::lift(L, l.a2) - P);
        const auto n = ch.num(L, arith::dot(nf, P - A));
        const auto d = arith::dot(nf, ch.dir(L));
        return flip ? std::pair{-n, -d} : std::pair{n, d};
    });
}
// use(f) with f(L) the direction of the line in H (an edge, degree 1, or n_f x n_t, degree 4).
template <class Use>
[[nodiscard]] constexpr auto with_line_dir(const sweep_frame& fr, const sweep_line& l, const Use& use) {
    if (l.kind == 1) return use([l](auto L) { return arith::lift(L, l.a1) - arith::lift(L, l.a0); });
    return use([fr, l](auto L) {
        const auto P = arith::lift(L, l.a0), A = arith::lift(L, fr.a);
        return arith::cross(arith::cross(arith::lift(L, l.a1) - P, arith::lift(L, l.a2) - P),
                            arith::cross(arith::lift(L, fr.b) - A, arith::lift(L, fr.c) - A));
    });
}

enum class sweep_result { inside, outside, retry };

// A filter kernel that has failed a sign: its answer will be discarded (the exact kernel decides,
// or classify says uncertain), so the search for a clean chord can stop.
template <class K>
[[nodiscard]] constexpr bool gave_up(const K& k) {
    if constexpr (requires { k.failed(); }) return k.failed();
    else return false;
}

// s with its last nonzero part moved to the next double up or down
[[nodiscard]] constexpr sweep_s next_s(sweep_s s, bool up) {
    const int i = s.c[2] != 0.0 ? 2 : (s.c[1] != 0.0 ? 1 : 0);
    const auto b = std::bit_cast<std::uint64_t>(s.c[i]);
    s.c[i] = std::bit_cast<double>(up ? b + 1 : b - 1);
    return s;
}

// The sweep from fr.a (see the top comment). `free_apex`: fr.a lies on no triangle and inside,
// and `near` lists every triangle meeting t; else every triangle is followed.
template <class K>
[[nodiscard]] constexpr sweep_result sweep(K& k, const mesh3& m, const sweep_frame& fr, bool free_apex,
                                           const std::vector<std::size_t>& near) {
    const point3 A = fr.a, B = fr.b, C = fr.c;
    const int axis = fr.axis;
    const point3 ek = unit(axis);
    std::vector<sweep_line> lines;
    std::vector<sweep_dir> dirs, far_dirs;
    int bands = 0;
    auto plane_side = [&](point3 p) { return k.sgn([=](auto L) { return poly::orient3d(L, A, B, C, p); }); };
    // d's s when strictly inside (0, 1), with D made positive
    auto keep_dir = [&](sweep_dir d, std::vector<sweep_dir>& into) {
        d.flip = false;
        const sign den = with_dir(fr, d, [&](auto f) { return k.sgn([=](auto L) { return f(L).second; }); });
        if (den == sign::zero) return;
        d.flip = den == sign::negative;
        const bool inside = with_dir(fr, d, [&](auto f) {
            return k.sgn([=](auto L) { return f(L).first; }) == sign::positive && k.sgn([=](auto L) {
                const auto [n, dd] = f(L);
                return dd - n;
            }) == sign::positive;
        });
        if (inside) into.push_back(d);
    };
    // where the edge p q (strictly across H) crosses it
    auto crossing_end = [&](point3 p, point3 q) {
        segment_param at = fr.plane();
        const segment3 e{p, q};
        at.flip = k.sgn([=](auto L) { return at.fraction(L, e).second; }) == sign::negative;
        return sweep_end{false, p, q, at};
    };
    // Is the end e (a vertex in H, or where an edge crosses H) in the closed triangle? Only such
    // points are vertices of the cells the sweep must meet; the others matter only where the
    // chord's line is followed from outside (a line's end on it would break the half-open count).
    // the side of y from the line x0 x1 in H, seen along the axis (degree 2)
    auto side_of = [&](point3 x0, point3 x1, point3 y) {
        return k.sgn([=](auto L) {
            const auto X = arith::lift(L, x0);
            return cross_along(axis, arith::lift(L, x1) - X, arith::lift(L, y) - X);
        });
    };
    const sign turn = side_of(A, B, C);
    auto in_triangle = [&](const sweep_end& e) {
        auto side = [&](point3 u0, point3 u1) {
            if (e.vertex) return side_of(u0, u1, e.p);
            const segment_param at = e.at;
            const segment3 pq{e.p, e.q};
            return k.sgn([=](auto L) { // (x - u0) D = (x - a) D - (u0 - a) D
                const auto F = offset_on_edge(L, at, pq, A);
                const auto d = at.fraction(L, pq).second;
                const auto U = arith::lift(L, u0) - arith::lift(L, A);
                using T = decltype(F.x - U.x * d);
                return cross_along(axis, arith::lift(L, u1) - arith::lift(L, u0),
                                   arith::v3<T>{F.x - U.x * d, F.y - U.y * d, F.z - U.z * d});
            });
        };
        const point3 corner[3] = {A, B, C};
        for (int j = 0; j < 3; ++j)
            if (const sign x = side(corner[j], corner[(j + 1) % 3]); x != sign::zero && x != turn) return false;
        return true;
    };
    auto add_face = [&](std::size_t i, bool is_near) {
        const triangle3 f = m.triangle(i);
        const point3 v[3] = {f.a, f.b, f.c};
        const sign o[3] = {plane_side(v[0]), plane_side(v[1]), plane_side(v[2])};
        int zeros = 0, pos = 0, neg = 0;
        for (const sign x : o) zeros += x == sign::zero, pos += x == sign::positive, neg += x == sign::negative;
        if (zeros == 0 && (pos == 0 || neg == 0)) return; // off H
        bool collinear = true;
        for (int ax = 0; ax < 3 && collinear; ++ax)
            collinear = arith::is_zero(k, [=](auto L) {
                const auto P = arith::lift(L, v[0]);
                const auto n = arith::cross(arith::lift(L, v[1]) - P, arith::lift(L, v[2]) - P);
                return ax == 0 ? n.x : (ax == 1 ? n.y : n.z);
            });
        if (collinear) return; // no interior: neither crossed nor covering
        for (int j = 0; j < 3; ++j) {
            const point3 p = v[j], q = v[(j + 1) % 3];
            // a point in the triangle goes to dirs; one outside only to far_dirs, and only when the
            // chord's line is followed from outside
            auto to = [&](const sweep_end& e) -> std::vector<sweep_dir>* {
                if (is_near && in_triangle(e)) return &dirs;
                return free_apex ? nullptr : &far_dirs;
            };
            if (o[j] == sign::zero && !(p.x == A.x && p.y == A.y && p.z == A.z)) // a vertex in H: the plane through a, p and e_k
                if (std::vector<sweep_dir>* d = to(sweep_end{true, p})) keep_dir(sweep_dir{segment_param{A, A, p, origin, ek}}, *d);
            if ((o[j] == sign::positive && o[(j + 1) % 3] == sign::negative) ||
                (o[j] == sign::negative && o[(j + 1) % 3] == sign::positive))
                if (std::vector<sweep_dir>* d = to(crossing_end(p, q))) // an edge across H: the plane through a, p, q
                    keep_dir(sweep_dir{segment_param{A, A, p, A, q}}, *d);
        }
        // where an edge in H meets b c, when it does (a cell's vertex)
        auto meets_bc = [&](point3 p, point3 q) {
            const sign sp = side_of(B, C, p), sq = side_of(B, C, q), sb = side_of(p, q, B), sc = side_of(p, q, C);
            return sp != sq && sb != sc && !(sp == sign::zero && sq == sign::zero);
        };
        auto in_plane_edge = [&](point3 p, point3 q, int tau, int band) {
            lines.push_back(sweep_line{1, p, q, q, sweep_end{true, p}, sweep_end{true, q}, tau, band, is_near});
            if (is_near && meets_bc(p, q)) keep_dir(sweep_dir{segment_param{p, p, q, origin, ek}}, dirs);
        };
        if (zeros == 3) { // covering
            const int band = bands++;
            for (int j = 0; j < 3; ++j) in_plane_edge(v[j], v[(j + 1) % 3], 0, band);
            return;
        }
        if (zeros == 2) { // an edge in H; the surface just above H crosses it when the third vertex is above
            const int j = o[0] != sign::zero ? 0 : (o[1] != sign::zero ? 1 : 2);
            if (o[j] == sign::positive) in_plane_edge(v[(j + 1) % 3], v[(j + 2) % 3], 1, -1);
            return;
        }
        sweep_end ends[2];
        if (zeros == 1) {
            const int j = o[0] == sign::zero ? 0 : (o[1] == sign::zero ? 1 : 2);
            if (o[(j + 1) % 3] == o[(j + 2) % 3]) return; // touching H at a vertex
            ends[0] = sweep_end{true, v[j]};
            ends[1] = crossing_end(v[(j + 1) % 3], v[(j + 2) % 3]);
        } else {
            int n = 0;
            for (int j = 0; j < 3; ++j)
                if (o[j] != o[(j + 1) % 3]) ends[n++] = crossing_end(v[j], v[(j + 1) % 3]);
        }
        lines.push_back(sweep_line{0, v[0], v[1], v[2], ends[0], ends[1], 1, -1, is_near});
        if (is_near && intersects(k, segment3{B, C}, f)) // where b c crosses it
            keep_dir(sweep_dir{segment_param{v[0], v[0], v[1], v[0], v[2]}}, dirs);
    };
    if (free_apex) {
        for (const std::size_t i : near) add_face(i, true);
    } else {
        std::vector<unsigned char> is_near(m.triangles.size(), 0); // (std::vector<bool> is not usable in constant evaluation here)
        for (const std::size_t i : near) is_near[i] = 1;
        for (std::size_t i = 0; i < m.triangles.size(); ++i) add_face(i, is_near[i] != 0);
    }
    if (gave_up(k)) return sweep_result::outside; // (a filter that failed here would find every triangle in H)
    // crossings of a covering triangle's edge by another line, strictly inside both (lines of
    // triangles meeting t: no other line has a point in t)
    const std::size_t n_lines = lines.size();
    for (std::size_t i = 0; i < n_lines && bands > 0; ++i) {
        if (lines[i].band < 0 || !lines[i].near) continue;
        const point3 p = lines[i].a0, q = lines[i].a1;
        const segment3 e{p, q};
        for (std::size_t j = 0; j < n_lines; ++j) {
            const sweep_line& l = lines[j];
            if (j == i || l.band == lines[i].band || !l.near) continue;
            if (l.kind == 0) {
                const point3 g0 = l.a0, g1 = l.a1, g2 = l.a2;
                const sign sp = k.sgn([=](auto L) { return poly::orient3d(L, g0, g1, g2, p); });
                const sign sq = k.sgn([=](auto L) { return poly::orient3d(L, g0, g1, g2, q); });
                if (sp == sign::zero || sq == sign::zero || sp == sq) continue;
                const sign s0 = k.sgn([=](auto L) { return poly::orient3d(L, p, q, g0, g1); });
                const sign s1 = k.sgn([=](auto L) { return poly::orient3d(L, p, q, g1, g2); });
                const sign s2 = k.sgn([=](auto L) { return poly::orient3d(L, p, q, g2, g0); });
                if (s0 == sign::zero || s0 != s1 || s1 != s2) continue;
                keep_dir(sweep_dir{segment_param{g0, g0, g1, g0, g2}, true, e}, dirs);
            } else {
                const point3 r = l.a0, w = l.a1;
                const sign a1 = side_of(p, q, r), a2 = side_of(p, q, w), b1 = side_of(r, w, p), b2 = side_of(r, w, q);
                if (a1 == sign::zero || a2 == sign::zero || a1 == a2 || b1 == sign::zero || b2 == sign::zero || b1 == b2) continue;
                keep_dir(sweep_dir{segment_param{r, r, w, origin, ek}, true, e}, dirs);
            }
        }
    }
    auto order = [&](const sweep_dir& x, const sweep_dir& y) {
        return with_dir(fr, x, [&](auto fx) {
            return with_dir(fr, y, [&](auto fy) {
                return k.sgn([=](auto L) {
                    const auto [nx, dx] = fx(L);
                    const auto [ny, dy] = fy(L);
                    return nx * dy - ny * dx;
                });
            });
        });
    };
    // the sign of s - d
    auto above = [&](const sweep_s& s, const sweep_dir& d) {
        return with_dir(fr, d, [&](auto f) {
            return k.sgn([=](auto L) {
                const auto [n, dd] = f(L);
                return s.lift(L) * dd - L(1.0) * n;
            });
        });
    };
    auto estimate = [&](const sweep_dir& d) {
        return with_dir(fr, d, [&](auto f) {
            const auto [n, dd] = f(arith::lift_double{});
            return n / dd;
        });
    };
    pieces::merge_sort(dirs, [&](const sweep_dir& x, const sweep_dir& y) { return order(x, y) == sign::negative; });

    // One chord: inside, outside, or retry (it passes where two lines cross).
    std::vector<chord_cut> cuts;
    std::vector<std::array<int, 3>> band_at; // per covering triangle: its crossings' groups, and their count
    auto chord = [&](const auto& ch) {
        cuts.clear();
        band_at.assign(static_cast<std::size_t>(bands), std::array<int, 3>{0, 0, 0});
        int parity = free_apex ? 1 : 0;
        auto end_side = [&](const sweep_end& e) {
            if (e.vertex) {
                const point3 p = e.p;
                return k.sgn([=](auto L) { return cross_along(axis, ch.dir(L), arith::lift(L, p) - arith::lift(L, A)); });
            }
            const segment_param at = e.at;
            const segment3 pq{e.p, e.q};
            return k.sgn([=](auto L) { return cross_along(axis, ch.dir(L), offset_on_edge(L, at, pq, A)); });
        };
        auto band_mark = [&](int band, int pos) {
            auto& b = band_at[static_cast<std::size_t>(band)];
            if (b[2] < 2) b[static_cast<std::size_t>(b[2])] = pos;
            ++b[2];
        };
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const sweep_line& l = lines[i];
            if ((end_side(l.e0) == sign::positive) == (end_side(l.e1) == sign::positive)) continue; // half-open: not crossed
            const sign den = with_cut(fr, ch, l, false, [&](auto f) { return k.sgn([=](auto L) { return f(L).second; }); });
            if (den == sign::zero) continue;
            const bool flip = den == sign::negative;
            const sign num = with_cut(fr, ch, l, flip, [&](auto f) { return k.sgn([=](auto L) { return f(L).first; }); });
            if (num != sign::positive) { // at or before the apex
                if (!free_apex) parity ^= l.tau;
                if (l.band >= 0) band_mark(l.band, -1);
                continue;
            }
            const sign rest = with_cut(fr, ch, l, flip, [&](auto f) {
                return k.sgn([=](auto L) {
                    const auto [n, d] = f(L);
                    return ch.before(L, n, d);
                });
            });
            if (rest == sign::zero || (rest == sign::positive) != (ch.before_sign > 0)) { // at or beyond the chord's end on b c
                if (l.band >= 0) band_mark(l.band, -2);
                continue;
            }
            cuts.push_back(chord_cut{i, flip, 0});
        }
        auto cut_order = [&](const chord_cut& x, const chord_cut& y) {
            return with_cut(fr, ch, lines[x.line], x.flip, [&](auto fx) {
                return with_cut(fr, ch, lines[y.line], y.flip, [&](auto fy) {
                    return k.sgn([=](auto L) {
                        const auto [nx, dx] = fx(L);
                        const auto [ny, dy] = fy(L);
                        return nx * dy - ny * dx;
                    });
                });
            });
        };
        pieces::merge_sort(cuts, [&](const chord_cut& x, const chord_cut& y) { return cut_order(x, y) == sign::negative; });
        int groups = 0;
        for (std::size_t i = 0; i < cuts.size(); ++i) {
            if (i > 0 && cut_order(cuts[i - 1], cuts[i]) != sign::zero) ++groups;
            cuts[i].pos = groups;
        }
        if (!cuts.empty()) ++groups;
        // two lines through one point of the chord, not along one line: move the chord
        for (std::size_t i = 1; i < cuts.size(); ++i) {
            std::size_t first = i;
            while (first > 0 && cuts[first - 1].pos == cuts[i].pos) --first;
            if (first == i) continue;
            const sign par = with_line_dir(fr, lines[cuts[first].line], [&](auto fx) {
                return with_line_dir(fr, lines[cuts[i].line],
                                     [&](auto fy) { return k.sgn([=](auto L) { return cross_along(axis, fx(L), fy(L)); }); });
            });
            if (par != sign::zero) return sweep_result::retry;
        }
        for (const chord_cut& c : cuts)
            if (lines[c.line].band >= 0) band_mark(lines[c.line].band, c.pos);
        // piece i lies between groups i - 1 and i (the apex before group 0, e(s) after the last)
        std::size_t next = 0;
        for (int piece = 0; piece <= groups; ++piece) {
            bool member = parity == 1;
            for (int b = 0; b < bands && !member; ++b) {
                const auto& at = band_at[static_cast<std::size_t>(b)];
                if (at[2] != 2) continue;
                auto place = [&](int x) { return x == -1 ? -1 : (x == -2 ? groups : x); };
                const int lo = place(at[0]) < place(at[1]) ? place(at[0]) : place(at[1]);
                const int hi = place(at[0]) < place(at[1]) ? place(at[1]) : place(at[0]);
                member = lo <= piece - 1 && hi >= piece;
            }
            if (!member) return sweep_result::outside;
            while (next < cuts.size() && cuts[next].pos == piece) parity ^= lines[cuts[next++].line].tau;
        }
        return sweep_result::inside;
    };
    // no far direction exactly at s (the chord's line, followed before the apex, meets no line's end)
    auto generic = [&](const sweep_s& s) {
        for (const sweep_dir& d : far_dirs)
            if (above(s, d) == sign::zero) return false;
        return true;
    };
    // the same for a pair chord: its direction parallel to none
    auto generic_pair = [&](const pair_chord& c) {
        for (const sweep_dir& d : far_dirs)
            if (arith::is_zero(k, [=](auto L) { return cross_along(axis, c.dir(L), bound_vector(L, fr, sector_bound{d, false})); }))
                return false;
        return true;
    };
    // a sector's bound: a direction (an edge's crossing z with its D's sign), or for s = 0 (b) or
    // s = 1 (c) the plane through that point and two coordinate axes, det(e_j, e_k, x - b) =
    // (x - b)_i for an axis i along which b c moves
    const int along = B.x != C.x ? 0 : (B.y != C.y ? 1 : 2);
    const bool descends = along == 0 ? C.x < B.x : (along == 1 ? C.y < B.y : C.z < B.z);
    auto bound_of = [&](const sweep_dir* d, bool end) {
        if (d == nullptr)
            return sector_bound{
                sweep_dir{segment_param{end ? C : B, origin, unit((along + 1) % 3), origin, unit((along + 2) % 3)}, false, {}, descends},
                false};
        bool negate = false;
        if (d->on_edge) {
            const segment_param at = d->plane;
            const segment3 e = d->edge;
            negate = k.sgn([=](auto L) { return at.fraction(L, e).second; }) == sign::negative;
        }
        return sector_bound{*d, negate};
    };
    // the side of b c that a lies on, seen along the axis
    const int side_a = k.sgn([=](auto L) {
        const auto Bl = arith::lift(L, B);
        return cross_along(axis, arith::lift(L, C) - Bl, arith::lift(L, A) - Bl);
    }) == sign::positive
                           ? 1
                           : -1;
    const sweep_dir* lo = nullptr; // s = 0
    for (std::size_t i = 0; i <= dirs.size(); ++i) {
        const sweep_dir* hi = i < dirs.size() ? &dirs[i] : nullptr; // nullptr: s = 1
        if (lo != nullptr && hi != nullptr && order(*lo, *hi) == sign::zero) continue;
        // lo < s < hi (0 and 1 where there is no direction)
        auto above_lo = [&](const sweep_s& x) {
            return lo == nullptr ? k.sgn([=](auto L) { return x.lift(L); }) == sign::positive : above(x, *lo) == sign::positive;
        };
        auto below_hi = [&](const sweep_s& x) {
            return hi == nullptr ? k.sgn([=](auto L) { return L(1.0) - x.lift(L); }) == sign::positive : above(x, *hi) == sign::negative;
        };
        sweep_s s{{0.5 * ((lo != nullptr ? estimate(*lo) : 0.0) + (hi != nullptr ? estimate(*hi) : 1.0)), 0.0, 0.0}};
        if (!(s.c[0] > 0.0 && s.c[0] < 1.0) || !above_lo(s) || !below_hi(s)) {
            // part by part, the least value of bit patterns in [0, 1] putting s above lo (bisection),
            // until s is below hi; else the largest not above lo, and on to the next part
            bool found = false;
            s = sweep_s{};
            for (int part = 0; part < 3 && !found; ++part) {
                std::uint64_t a = 0, b = std::bit_cast<std::uint64_t>(1.0);
                auto at = [&](std::uint64_t bits) {
                    sweep_s x = s;
                    x.c[part] = std::bit_cast<double>(bits);
                    return x;
                };
                while (b - a > 1) {
                    const std::uint64_t mid = a + (b - a) / 2;
                    if (above_lo(at(mid))) b = mid;
                    else a = mid;
                }
                found = below_hi(at(b));
                s = found ? at(b) : at(a);
            }
            if (!found) s = sweep_s{{-1.0, 0.0, 0.0}}; // no s of three doubles in this sector
        }
        bool done = false;
        sweep_s up = s, down = s;
        for (int attempt = 0; attempt < 33 && !done && s.c[0] >= 0.0; ++attempt) {
            const sweep_s c = attempt == 0 ? s : (attempt % 2 == 1 ? (up = next_s(up, true)) : (down = next_s(down, false)));
            if ((attempt > 0 && (!above_lo(c) || !below_hi(c))) || !generic(c)) continue;
            const sweep_result r = chord(s_chord{fr, c});
            if (r == sweep_result::outside || gave_up(k)) return sweep_result::outside;
            done = r == sweep_result::inside;
        }
        if (!done) { // chords w0 V_lo + w1 V_hi between the sector's bounds: each point where two lines
                     // cross, and each far direction, rules out one ratio w1 / w0
            const sector_bound blo = bound_of(lo, false), bhi = bound_of(hi, true);
            // (plain double reaches here where its signs disagree with the exact ones, near a zero: a
            // guess, two ratios, rather than lines^2 chords of lines^2 cuts each)
            const std::size_t tries = std::is_same_v<K, arith::approx_kernel> ? 2 : lines.size() * lines.size() + far_dirs.size() + 2;
            for (std::size_t w = 1; w <= tries && !done; ++w) {
                const pair_chord c{fr, blo, bhi, 1.0, double(w), side_a};
                if (!generic_pair(c)) continue;
                const sweep_result r = chord(c);
                if (r == sweep_result::outside || gave_up(k)) return sweep_result::outside;
                done = r == sweep_result::inside;
            }
            if (!done) return sweep_result::retry; // (an inexact kernel's guesses)
        }
        lo = hi;
    }
    return sweep_result::inside;
}

} // namespace solid_mesh

namespace solid_mesh {

// The centre of the full box `box`, V / W = (0.5 (min + max)) / 1, both lifted as inputs so the
// parity's signs stay homogeneous (degree 4).
struct box_centre : in_segment_box {
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto h = lift(0.5);
        const auto lo = arith::lift(lift, box.min), hi = arith::lift(lift, box.max);
        using T = decltype(h * (lo.x + hi.x));
        return std::pair{arith::v3<T>{h * (lo.x + hi.x), h * (lo.y + hi.y), h * (lo.z + hi.z)}, lift(1.0)};
    }
};

// Where the diagonal from the corner k to the corner kk crosses the plane of t: with s and s' the
// orient3d values of k and kk, X = (s' k - s kk) / (s' - s), V of degree 4 and W of degree 3.
struct diagonal_point {
    triangle3 t;
    point3 k, kk;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto s = poly::orient3d(lift, t.a, t.b, t.c, k), s2 = poly::orient3d(lift, t.a, t.b, t.c, kk);
        const auto K = arith::lift(lift, k), KK = arith::lift(lift, kk);
        using T = decltype(s2 * K.x - s * KK.x);
        return std::pair{arith::v3<T>{s2 * K.x - s * KK.x, s2 * K.y - s * KK.y, s2 * K.z - s * KK.z}, s2 - s};
    }
};

[[nodiscard]] constexpr double coord(const point3& p, int i) { return i == 0 ? p.x : (i == 1 ? p.y : p.z); }

// The sign of the k-th component of t's normal (b - a) x (c - a).
template <class K>
[[nodiscard]] constexpr sign normal_sign(K& k, const triangle3& t, int axis) {
    return k.sgn([=](auto L) {
        const auto a = arith::lift(L, t.a);
        return cross_along(axis, arith::lift(L, t.b) - a, arith::lift(L, t.c) - a);
    });
}
[[nodiscard]] constexpr bool same(const point3& p, const point3& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }
// An axis along which t's normal is nonzero, or -1 for a collinear triangle. A triangle in a
// coordinate plane can only have that axis (comparisons); otherwise an axis the filter proves
// nonzero comes first, then exact signs (a zero component is often exact, which only those settle).
template <class K>
[[nodiscard]] constexpr int normal_axis(K& k, const triangle3& t) {
    for (int axis = 0; axis < 3; ++axis)
        if (coord(t.a, axis) == coord(t.b, axis) && coord(t.a, axis) == coord(t.c, axis))
            return normal_sign(k, t, axis) != sign::zero ? axis : -1;
    for (int axis = 0; axis < 3; ++axis)
        if (arith::sgn<arith::hint::optional>(k, [=](auto L) {
                const auto a = arith::lift(L, t.a);
                return cross_along(axis, arith::lift(L, t.b) - a, arith::lift(L, t.c) - a);
            }) != sign::zero)
            return axis;
    for (int axis = 0; axis < 3; ++axis)
        if (normal_sign(k, t, axis) != sign::zero) return axis;
    return -1;
}
// Does the plane of r hold the triangle f? (A vertex of r's lies in it.)
template <class K>
[[nodiscard]] constexpr bool coplanar(K& k, const triangle3& r, const triangle3& f) {
    for (const point3& p : {f.a, f.b, f.c})
        if (!same(p, r.a) && !same(p, r.b) && !same(p, r.c) &&
            !arith::is_zero(k, [=](auto L) { return poly::orient3d(L, r.a, r.b, r.c, p); }))
            return false;
    return true;
}

// Does the triangle f, seen along `axis` in the plane, hold the point q = V / W (W of sign
// `w`) moved by eps e_u + eps^2 e_v, (axis, u, v) cyclic? Off every edge line, so strictly.
template <class K, class Q>
[[nodiscard]] constexpr bool holds_nudged(K& k, const triangle3& f, int axis, const Q& q, sign w) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const sign turn = normal_sign(k, f, axis);
    const point3 p[3] = {f.a, f.b, f.c};
    for (int i = 0; i < 3; ++i) {
        const point3 a = p[i], c = p[(i + 1) % 3];
        sign e = k.sgn([=, &q](auto L) { // (c - a) x (V - W a) along the axis
            const auto [V, W] = q.weighted(L);
            const auto A = arith::lift(L, a);
            using T = decltype(V.x - W * A.x);
            return cross_along(axis, arith::lift(L, c) - A, arith::v3<T>{V.x - W * A.x, V.y - W * A.y, V.z - W * A.z});
        });
        if (w == sign::negative) e = e == sign::positive ? sign::negative : (e == sign::negative ? sign::positive : sign::zero);
        // on the edge's line: (c - a) x e_u = -(c - a)_v, then (c - a) x e_v = (c - a)_u
        if (e == sign::zero) e = arith::compare(k, coord(a, v), coord(c, v));
        if (e == sign::zero) e = arith::compare(k, coord(c, u), coord(a, u));
        if (e != turn) return false;
    }
    return true;
}

// The triangles `group` (indices into m, at least two, all in the plane of the first, each reaching
// the interior of the full box b): is their coverage odd somewhere inside b? See the top comment.
template <class K>
[[nodiscard]] constexpr bool odd_inside(K& k, const mesh3& m, const aabb3& b, const std::vector<std::size_t>& group) {
    const triangle3 r = m.triangle(group[0]);
    const int axis = normal_axis(k, r);
    if (axis < 0) return false; // (a collinear triangle is never grouped; an inexact kernel's guess)
    auto side = [&](point3 x0, point3 x1, point3 y) {
        return k.sgn([=](auto L) {
            const auto X = arith::lift(L, x0);
            return cross_along(axis, arith::lift(L, x1) - X, arith::lift(L, y) - X);
        });
    };
    // The edges, by line: each line's end points in the order of a coordinate that changes along it.
    struct end {
        double at;
        point3 p;
    };
    std::vector<std::array<point3, 2>> edges;
    for (const std::size_t i : group) {
        const triangle3 f = m.triangle(i);
        edges.push_back({f.a, f.b}), edges.push_back({f.b, f.c}), edges.push_back({f.c, f.a});
    }
    std::vector<unsigned char> done(edges.size(), 0);
    std::vector<end> ends;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (done[i] != 0) continue;
        const point3 p = edges[i][0], q = edges[i][1];
        const int c = p.x != q.x ? 0 : (p.y != q.y ? 1 : 2);
        ends.clear();
        for (std::size_t j = i; j < edges.size(); ++j) {
            if (done[j] != 0) continue;
            auto on_line = [&](const point3& y) { return same(y, p) || same(y, q) || side(p, q, y) == sign::zero; };
            if (j != i && (!on_line(edges[j][0]) || !on_line(edges[j][1]))) continue;
            done[j] = 1;
            ends.push_back({coord(edges[j][0], c), edges[j][0]}), ends.push_back({coord(edges[j][1], c), edges[j][1]});
        }
        pieces::merge_sort(ends, [](const end& x, const end& y) { return x.at < y.at; });
        // between two consecutive distinct points, the parity of the end points up to the first
        std::size_t below = 0;
        for (std::size_t n = 0; n < ends.size();) {
            std::size_t next = n;
            while (next < ends.size() && ends[next].at == ends[n].at) ++next;
            below += next - n;
            if (next < ends.size() && below % 2 == 1 && meets_interior(k, b, triangle3{ends[n].p, ends[next].p, ends[next].p})) return true;
            n = next;
        }
    }
    // No odd piece of an edge inside b: the coverage is constant there. A diagonal k kk of b with
    // its corners strictly on either side of the plane crosses it inside b.
    const box_corners corner(b);
    for (int i = 0; i < 4; ++i) {
        const point3 c0 = corner.p[i], c1 = corner.p[7 - i];
        const sign s0 = k.sgn([=](auto L) { return poly::orient3d(L, r.a, r.b, r.c, c0); });
        const sign s1 = k.sgn([=](auto L) { return poly::orient3d(L, r.a, r.b, r.c, c1); });
        if (s0 == sign::zero || s1 == sign::zero || s0 == s1) continue;
        const diagonal_point X{r, c0, c1};
        const sign w = s1 == sign::positive ? sign::positive : sign::negative; // s' - s
        bool odd = false;
        for (const std::size_t f : group) odd = odd != holds_nudged(k, m.triangle(f), axis, X, w);
        return odd;
    }
    return false; // (every plane reaching b's interior has such a diagonal; an inexact kernel's guess)
}

} // namespace solid_mesh

} // namespace incidence::detail
