// convex_polyhedron3 against plane3.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the plane
// n . x = offset (a zero normal is everything when the offset is 0 and nothing otherwise; a
// non-finite number: no set). Touching at a vertex, an edge or a face counts.
// Method (exact tiers): a convex set meets the plane iff it has points on both closed sides. Each
// side is first tried at the set's vertex least or greatest along n, guessed in double and proven
// with signs of degree <= 4: that vertex strictly inside and strictly beyond the plane says yes;
// its three planes' multipliers for n all positive (a Farkas certificate that nothing of the set
// goes further) with the vertex short of the plane says no. Undecided sides (touching, unbounded,
// degenerate) get a half-space feasibility test (polyq::feasible in aabb_convex_polyhedron.cppm)
// of the set with n . x <= offset or -n . x <= -offset, which tries the minimal faces (vertices,
// lines or planes, by the rank of the normals): homogeneous signs of degree <= 5.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, sections 7.3 (Farkas) and 8.5
// (minimal faces).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_plane.cpp).
module;
#include <array>
export module incidence.query:convex_polyhedron_plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :convex_polyhedron_point;
import :aabb_convex_polyhedron;

export namespace incidence::pair {

namespace polyq {

// The vertices of the m half-spaces found in double (the triples of planes whose meeting point is
// nearly in every half-space), at most `capacity` of them: guesses, proven by the caller.
struct vertex_guesses {
    static constexpr int capacity = 128;
    std::array<std::array<int, 3>, capacity> triple{};
    std::array<point3, capacity> at{};
    int n = 0;
};
[[nodiscard]] constexpr vertex_guesses vertices_guess(const plane3* planes, int m) {
    auto norm1 = [](vec3 v) { return arith::abs(v.x) + arith::abs(v.y) + arith::abs(v.z); };
    vertex_guesses out;
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            for (int l = j + 1; l < m && out.n < vertex_guesses::capacity; ++l) {
                const plane3 a = planes[i], b = planes[j], c = planes[l];
                const vec3 bc = cross(b.normal, c.normal), ca = cross(c.normal, a.normal), ab = cross(a.normal, b.normal);
                const double d = dot(a.normal, bc);
                if (!(arith::abs(d) > 0x1p-30 * norm1(a.normal) * norm1(b.normal) * norm1(c.normal))) continue;
                const vec3 v = (bc * a.offset + ca * b.offset + ab * c.offset) * (1.0 / d);
                if (!finite(v)) continue;
                const double size = arith::abs(v.x) + arith::abs(v.y) + arith::abs(v.z);
                bool inside = true;
                for (int r = 0; r < m && inside; ++r) {
                    if (r == i || r == j || r == l) continue;
                    inside = dot(planes[r].normal, v) - planes[r].offset <= 0x1p-30 * (norm1(planes[r].normal) * size + arith::abs(planes[r].offset));
                }
                if (!inside) continue;
                const auto u = static_cast<unsigned>(out.n++);
                out.triple[u] = {i, j, l};
                out.at[u] = point3{v.x, v.y, v.z};
            }
    return out;
}

// Has the set of the m half-spaces a point x with g . x >= e? Decided from the vertex v = V / D of
// the three planes t only when every deciding sign is proven nonzero (arith::probe): yes when
// g . v > e and v is strictly inside every other half-space; no when g . v < e and
// g = y_i n_i + y_j n_j + y_l n_l with every y > 0 (Farkas: then g . x <= g . v on the whole set).
// 1: yes, 0: no, -1: not decided (the caller runs feasible()).
template <class K>
[[nodiscard]] constexpr int side_at_vertex(K& k, const plane3* planes, int m, const std::array<int, 3>& t, vec3 g, double e) {
    if (t[0] < 0) return -1;
    const plane3 a = planes[t[0]], b = planes[t[1]], c = planes[t[2]];
    const sign d = arith::probe(k, [=](auto L) { return arith::det3(arith::lift(L, a.normal), arith::lift(L, b.normal), arith::lift(L, c.normal)); });
    if (d == sign::zero) return -1;
    // g . V - e D, with g . (n_j x n_l) = det(g, n_j, n_l)
    const sign along = arith::probe(k, [=](auto L) {
        const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal), nc = arith::lift(L, c.normal), G = arith::lift(L, g);
        return L(a.offset) * arith::det3(G, nb, nc) + L(b.offset) * arith::det3(G, nc, na) + L(c.offset) * arith::det3(G, na, nb) -
               L(e) * arith::det3(na, nb, nc);
    });
    if (along == sign::zero) return -1;
    if (along == d) { // g . v > e: yes if v is in the set
        for (int r = 0; r < m; ++r) {
            if (r == t[0] || r == t[1] || r == t[2]) continue;
            const plane3 h = planes[r];
            const sign s = arith::probe(k, [=](auto L) {
                const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal), nc = arith::lift(L, c.normal);
                const auto nh = arith::lift(L, h.normal);
                return L(h.offset) * arith::det3(na, nb, nc) -
                       (L(a.offset) * arith::det3(nh, nb, nc) + L(b.offset) * arith::det3(nh, nc, na) + L(c.offset) * arith::det3(nh, na, nb));
            });
            if (s != d) return -1;
        }
        return 1;
    }
    // g . v < e: no if the multipliers y = (det(g, n_j, n_l), det(n_i, g, n_l), det(n_i, n_j, g)) / D are positive
    const sign y0 = arith::probe(k, [=](auto L) { return arith::det3(arith::lift(L, g), arith::lift(L, b.normal), arith::lift(L, c.normal)); });
    const sign y1 = arith::probe(k, [=](auto L) { return arith::det3(arith::lift(L, a.normal), arith::lift(L, g), arith::lift(L, c.normal)); });
    const sign y2 = arith::probe(k, [=](auto L) { return arith::det3(arith::lift(L, a.normal), arith::lift(L, b.normal), arith::lift(L, g)); });
    return y0 == d && y1 == d && y2 == d ? 0 : -1;
}

// Do the m half-spaces n_i . x <= c_i (m <= convex_polyhedron3::capacity) meet the plane?
template <class K>
[[nodiscard]] constexpr bool plane_meets(K& k, const plane3* planes, int m, const plane3& p) {
    constexpr int capacity = convex_polyhedron3::capacity;
    if (!well_formed(planes, m, capacity) || !finite(p.normal) || !finite(p.offset)) return false;
    // First the set's vertices least and greatest along the normal, guessed in double and proven
    // with signs: they decide most cases without the enumeration of feasible() (which meets the
    // near-zero signs of a camera frustum's side planes, nearly concurrent at the eye). The guess:
    // a linear program each (lp::guess_of), or for up to eight planes (a frustum, a box) every
    // triple in double, which measured cheaper there (and in constant evaluation).
    std::array<int, 3> least{-1, -1, -1}, greatest{-1, -1, -1};
    if (!__builtin_is_constant_evaluated() && m > 8) {
        const plane_rows view{planes, static_cast<unsigned>(m)};
        auto triple = [](const lp::guess& g) {
            return g.vertex ? std::array<int, 3>{static_cast<int>(g.r[0]), static_cast<int>(g.r[1]), static_cast<int>(g.r[2])} : std::array<int, 3>{-1, -1, -1};
        };
        least = triple(lp::guess_of(view, {p.normal.x, p.normal.y, p.normal.z}));
        greatest = triple(lp::guess_of(view, {-p.normal.x, -p.normal.y, -p.normal.z}));
    } else {
        const vertex_guesses g = vertices_guess(planes, m);
        double lo = 0, hi = 0;
        for (int v = 0; v < g.n; ++v) {
            const auto u = static_cast<unsigned>(v);
            const double t = dot(p.normal, g.at[u] - point3{0, 0, 0});
            if (least[0] < 0 || t < lo) least = g.triple[u], lo = t;
            if (greatest[0] < 0 || t > hi) greatest = g.triple[u], hi = t;
        }
    }
    const int upper = side_at_vertex(k, planes, m, greatest, p.normal, p.offset); // a point with n . x >= c?
    if (upper == 0) return false;
    const int lower = side_at_vertex(k, planes, m, least, -p.normal, -p.offset); // and with n . x <= c?
    if (lower == 0) return false;
    std::array<plane3, capacity + 1> rows{};
    for (int i = 0; i < m; ++i) rows[static_cast<unsigned>(i)] = planes[i];
    const auto n = static_cast<unsigned>(m);
    if (lower != 1) {
        rows[n] = p; // the set's points on the plane's lower side
        if (!feasible(k, rows.data(), n + 1)) return false;
    }
    if (upper != 1) {
        rows[n] = plane3{-p.normal, -p.offset}; // and on its upper side
        if (!feasible(k, rows.data(), n + 1)) return false;
    }
    return true;
}

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const plane3& p) {
    return polyq::plane_meets(k, c.planes.data(), c.count, p);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const plane3&);
} // namespace incidence::pair
