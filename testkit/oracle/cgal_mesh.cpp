// The mesh oracle: closed triangle meshes; mesh against mesh by
// CGAL::Polygon_mesh_processing::do_intersect on CGAL Surface_mesh.
// Inside tests by crossing parity with CGAL::orientation over Epeck (see mesh_inside): with
// CGAL::Side_of_triangle_mesh over Epeck a test of 40,000 cases took 55 s, nearly all of it in
// the lazy exact AABB tree, and over Epick it did not finish on cases at 2^500.
#include "cgal_oracle.hpp"
#include "cgal_lp_point.hpp"
#include "cgal_parity.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace oracle {
namespace {
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

Mesh to_cgal(const mesh_data& m) {
    Mesh sm;
    std::vector<Mesh::Vertex_index> vi;
    for (const auto& p : m.v) vi.push_back(sm.add_vertex(K::Point_3(p[0], p[1], p[2])));
    for (const auto& t : m.t)
        if (sm.add_face(vi[t[0]], vi[t[1]], vi[t[2]]) == Mesh::null_face()) throw std::logic_error("mesh oracle: not a manifold mesh");
    return sm;
}
flat triangle_of(const mesh_data& m, const std::array<unsigned, 3>& t) {
    flat f{flat::triangle, {}};
    for (int j = 0; j < 3; ++j)
        for (int c = 0; c < 3; ++c) f.v[3 * j + c] = m.v[t[static_cast<unsigned>(j)]][static_cast<unsigned>(c)];
    return f;
}
} // namespace

bool mesh_inside(const mesh_data& m, const std::array<double, 3>& p) {
    std::array<double, 3> lo{}, hi{};
    vertex_box(m, lo, hi);
    for (unsigned k = 0; k < 3; ++k)
        if (p[k] < lo[k] || p[k] > hi[k]) return false;
    const flat point{flat::point, {p[0], p[1], p[2]}};
    for (const auto& t : m.t)
        if (flat_intersect(triangle_of(m, t), point)) return true;
    // orientation is an exact predicate; nothing is constructed
    using E = CGAL::Exact_predicates_inexact_constructions_kernel;
    return crossing_parity<E>(m, E::Point_3(p[0], p[1], p[2]), p, lo, hi);
}

bool mesh_intersect(const mesh_data& m, const flat& x) {
    // A box lo..hi (infinite bounds allowed) holding x: its points v[0..3n) for a bounded x; for a
    // ray o + t d, t >= 0, x_k >= o_k where d_k >= 0 and x_k <= o_k where d_k <= 0; for a line,
    // x_k = o_k where d_k = 0. A triangle whose vertices' box misses it cannot meet x (comparisons
    // of the inputs), and skips the exact test.
    const int n = x.kind == flat::point                            ? 1
                  : x.kind == flat::segment || x.kind == flat::box ? 2
                  : x.kind == flat::triangle                       ? 3
                  : x.kind == flat::tetrahedron                    ? 4
                                                                   : 0;
    const double inf = std::numeric_limits<double>::infinity();
    std::array<double, 3> lo{-inf, -inf, -inf}, hi{inf, inf, inf};
    for (int j = 0; j < n; ++j)
        for (unsigned k = 0; k < 3; ++k) {
            const double c = x.v[3 * j + static_cast<int>(k)];
            lo[k] = j == 0 ? c : std::min(lo[k], c), hi[k] = j == 0 ? c : std::max(hi[k], c);
        }
    if (x.kind == flat::ray || x.kind == flat::line)
        for (unsigned k = 0; k < 3; ++k) {
            const double o = x.v[k], d = x.v[3 + k];
            if (d >= 0 && (x.kind == flat::ray || d == 0)) lo[k] = o;
            if (d <= 0 && (x.kind == flat::ray || d == 0)) hi[k] = o;
        }
    const bool boxed = x.kind != flat::plane;
    for (const auto& t : m.t) {
        bool apart = false;
        for (unsigned k = 0; k < 3 && boxed; ++k) {
            const double a = m.v[t[0]][k], b = m.v[t[1]][k], c = m.v[t[2]][k];
            apart = apart || std::max({a, b, c}) < lo[k] || std::min({a, b, c}) > hi[k];
        }
        if (!apart && flat_intersect(triangle_of(m, t), x)) return true;
    }
    if (x.kind == flat::plane) return false; // a plane cannot lie inside a bounded solid
    if (x.kind == flat::box && !(x.v[0] <= x.v[3] && x.v[1] <= x.v[4] && x.v[2] <= x.v[5])) return false; // empty
    return mesh_inside(m, {x.v[0], x.v[1], x.v[2]}); // a point, an origin, a vertex or the box's min corner
}

namespace {
// Does a triangle of m meet the convex set x (for each: the exact certificates, else the LP)?
bool triangles_meet(const mesh_data& m, const convex_set& x) {
    // A box around x (points plus bounded generators), widened by 2^-30 of its size and more than
    // any rounding in computing it: a triangle outside it cannot meet x, and skips its LP.
    std::array<double, 3> lo{}, hi{};
    bool bounded = !x.plane && !x.points.empty();
    for (const auto& g : x.generators) bounded = bounded && g.has_lo && g.has_hi;
    if (bounded) {
        lo = hi = x.points[0];
        for (const auto& p : x.points)
            for (unsigned k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
        for (unsigned k = 0; k < 3; ++k) {
            double reach = 0;
            for (const auto& g : x.generators) reach += std::fabs(g.g[k]) * std::max(std::fabs(g.lo), std::fabs(g.hi));
            const double slack = (reach + std::fabs(lo[k]) + std::fabs(hi[k])) * 0x1p-30 + 0x1p-1000;
            lo[k] -= reach + slack, hi[k] += reach + slack;
            bounded = bounded && std::isfinite(lo[k]) && std::isfinite(hi[k]);
        }
    }
    for (const auto& t : m.t) {
        if (bounded) {
            bool apart = false;
            for (unsigned k = 0; k < 3; ++k) {
                const double a = m.v[t[0]][k], b = m.v[t[1]][k], c = m.v[t[2]][k];
                apart = apart || std::max({a, b, c}) < lo[k] || std::min({a, b, c}) > hi[k];
            }
            if (apart) continue;
        }
        if (lp_intersect(lp_set(triangle_of(m, t)), x)) return true; // the certificates first, then the LP
    }
    return false;
}
} // namespace

bool any_triangle_meets(const mesh_data& soup, const convex_set& x) { return triangles_meet(soup, x); }

bool mesh_intersect(const mesh_data& m, const convex_set& x, const std::array<double, 3>& inner) {
    return triangles_meet(m, x) || mesh_inside(m, inner);
}

bool mesh_intersect(const mesh_data& m, const convex_set& x) {
    if (triangles_meet(m, x)) return true;
    // off the surface: x is wholly inside or outside, and any of its points decides
    const auto q = lp_point(x);
    if (!q) return false; // empty
    std::array<double, 3> lo{}, hi{}, p{};
    vertex_box(m, lo, hi);
    for (unsigned k = 0; k < 3; ++k) {
        if ((*q)[k] < mpq_class(lo[k]) || (*q)[k] > mpq_class(hi[k])) return false;
        p[k] = (*q)[k].get_d();
    }
    using E = CGAL::Exact_predicates_exact_constructions_kernel;
    return crossing_parity<E>(m, E::Point_3(E::FT((*q)[0]), E::FT((*q)[1]), E::FT((*q)[2])), p, lo, hi);
}

namespace {
// Does the triangle t's vertices' box miss the box lo..hi (comparisons)?
bool apart(const mesh_data& m, const std::array<unsigned, 3>& t, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    for (unsigned k = 0; k < 3; ++k) {
        const double x = m.v[t[0]][k], y = m.v[t[1]][k], z = m.v[t[2]][k];
        if (std::max({x, y, z}) < lo[k] || std::min({x, y, z}) > hi[k]) return true;
    }
    return false;
}
// The triangle t's vertices as Epeck points.
std::array<K::Point_3, 3> corners(const mesh_data& m, const std::array<unsigned, 3>& t) {
    std::array<K::Point_3, 3> c;
    for (unsigned j = 0; j < 3; ++j) c[j] = K::Point_3(m.v[t[j]][0], m.v[t[j]][1], m.v[t[j]][2]);
    return c;
}
// Is every point of the segment A B (Epeck points, A != B, inside the double box lo3..hi3) in the mesh's
// point set? Epeck constructs where it meets each triangle (CGAL::intersection: a point or a
// segment; a collinear triangle as its three edges), as parameters t = (P - A) . d / d . d; the
// open intervals between consecutive ones each lie on a triangle or off the surface, and their
// exact midpoints decide: on a triangle (do_intersect, or an edge's has_on) or inside by crossing
// parity over Epeck. The end points count through the closure (the set is closed).
bool segment_in_mesh(const mesh_data& m, const K::Point_3& A, const K::Point_3& B, const std::array<double, 3>& lo3,
                     const std::array<double, 3>& hi3) {
    using P = K::Point_3;
    const K::Segment_3 S(A, B);
    const K::Vector_3 D = B - A;
    const K::FT dd = D * D;
    std::vector<K::FT> ts{K::FT(0), K::FT(1)};
    std::vector<K::Triangle_3> tris;
    std::vector<K::Segment_3> edges;
    auto add = [&](const auto& r) {
        if (!r) return;
        if (const P* p = boost::get<P>(&*r)) ts.push_back(((*p - A) * D) / dd);
        else if (const K::Segment_3* q = boost::get<K::Segment_3>(&*r)) {
            ts.push_back(((q->source() - A) * D) / dd);
            ts.push_back(((q->target() - A) * D) / dd);
        }
    };
    for (const auto& t : m.t) {
        if (apart(m, t, lo3, hi3)) continue;
        const auto [p, q, r] = corners(m, t);
        if (!CGAL::collinear(p, q, r)) {
            const K::Triangle_3 T(p, q, r);
            add(CGAL::intersection(S, T));
            tris.push_back(T);
            continue;
        }
        for (const auto& [x, y] : {std::pair{p, q}, std::pair{q, r}, std::pair{r, p}}) {
            if (x == y) {
                if (S.has_on(x)) ts.push_back(((x - A) * D) / dd);
                continue;
            }
            const K::Segment_3 E(x, y);
            add(CGAL::intersection(S, E));
            edges.push_back(E);
        }
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    std::array<double, 3> lo{}, hi{};
    vertex_box(m, lo, hi);
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
        const K::FT tm = (ts[i] + ts[i + 1]) / 2;
        const P M = A + tm * D;
        bool on = false;
        for (const auto& T : tris) on = on || CGAL::do_intersect(T, M);
        for (const auto& E : edges) on = on || E.has_on(M);
        if (on) continue;
        const std::array<double, 3> approx{CGAL::to_double(M.x()), CGAL::to_double(M.y()), CGAL::to_double(M.z())};
        if (!crossing_parity<K>(m, M, approx, lo, hi)) return false;
    }
    return true;
}
} // namespace

bool mesh_contains_segment(const mesh_data& m, const std::array<double, 3>& a, const std::array<double, 3>& b) {
    if (!mesh_inside(m, a) || !mesh_inside(m, b)) return false;
    if (a == b) return true;
    std::array<double, 3> lo{}, hi{};
    for (unsigned k = 0; k < 3; ++k) lo[k] = std::min(a[k], b[k]), hi[k] = std::max(a[k], b[k]);
    return segment_in_mesh(m, K::Point_3(a[0], a[1], a[2]), K::Point_3(b[0], b[1], b[2]), lo, hi);
}

// Is every point of the triangle a b c in the mesh's point set? Its vertices by mesh_inside; a
// collinear one as its three edges. Otherwise the surface's traces on it (CGAL::intersection of
// it with every triangle: points, segments, and the edges of coplanar overlaps) cut it into
// cells; their vertices are the traces' end points and every crossing of two traces
// (CGAL::intersection of segments, all pairs). The directions of those vertices from a, s along b
// c (exact rationals), sorted; every cell is met by the chord from a to b + s (c - b) for an s
// strictly between two consecutive ones, and the triangle is in the (closed) set iff each such
// chord, at the exact midpoints, is (segment_in_mesh).
bool mesh_contains_triangle(const mesh_data& m, const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const std::array<double, 3>& c) {
    if (!mesh_inside(m, a) || !mesh_inside(m, b) || !mesh_inside(m, c)) return false;
    using P = K::Point_3;
    const P A(a[0], a[1], a[2]), B(b[0], b[1], b[2]), C(c[0], c[1], c[2]);
    if (CGAL::collinear(A, B, C)) return mesh_contains_segment(m, a, b) && mesh_contains_segment(m, b, c) && mesh_contains_segment(m, c, a);
    std::array<double, 3> lo{}, hi{};
    for (unsigned k = 0; k < 3; ++k) lo[k] = std::min({a[k], b[k], c[k]}), hi[k] = std::max({a[k], b[k], c[k]});
    const K::Triangle_3 T(A, B, C);
    std::vector<K::Segment_3> traces;
    std::vector<P> vertices;
    auto add_segment = [&](const P& x, const P& y) {
        vertices.push_back(x), vertices.push_back(y);
        if (x != y) traces.emplace_back(x, y);
    };
    for (const auto& t : m.t) {
        if (apart(m, t, lo, hi)) continue;
        const auto [p, q, r] = corners(m, t);
        if (CGAL::collinear(p, q, r)) {
            for (const auto& [x, y] : {std::pair{p, q}, std::pair{q, r}, std::pair{r, p}}) {
                if (x == y) {
                    if (CGAL::do_intersect(T, x)) vertices.push_back(x);
                    continue;
                }
                const auto res = CGAL::intersection(T, K::Segment_3(x, y));
                if (!res) continue;
                if (const P* v = boost::get<P>(&*res)) vertices.push_back(*v);
                else if (const K::Segment_3* e = boost::get<K::Segment_3>(&*res)) add_segment(e->source(), e->target());
            }
            continue;
        }
        const auto res = CGAL::intersection(T, K::Triangle_3(p, q, r));
        if (!res) continue;
        if (const P* v = boost::get<P>(&*res)) vertices.push_back(*v);
        else if (const K::Segment_3* e = boost::get<K::Segment_3>(&*res)) add_segment(e->source(), e->target());
        else if (const K::Triangle_3* f = boost::get<K::Triangle_3>(&*res)) {
            for (int i = 0; i < 3; ++i) add_segment(f->vertex(i), f->vertex(i + 1));
        } else if (const auto* poly = boost::get<std::vector<P>>(&*res)) {
            for (std::size_t i = 0; i < poly->size(); ++i) add_segment((*poly)[i], (*poly)[(i + 1) % poly->size()]);
        }
    }
    for (std::size_t i = 0; i < traces.size(); ++i)
        for (std::size_t j = i + 1; j < traces.size(); ++j) {
            const auto res = CGAL::intersection(traces[i], traces[j]);
            if (!res) continue;
            if (const P* v = boost::get<P>(&*res)) vertices.push_back(*v);
            else if (const K::Segment_3* e = boost::get<K::Segment_3>(&*res))
                vertices.push_back(e->source()), vertices.push_back(e->target());
        }
    // s of the line from A through V on B C, in the plane seen along an axis where T's normal is nonzero
    const K::Vector_3 n = CGAL::cross_product(B - A, C - A);
    const int axis = n.x() != 0 ? 0 : (n.y() != 0 ? 1 : 2);
    auto cross = [axis](const K::Vector_3& u, const K::Vector_3& v) { return CGAL::cross_product(u, v)[axis]; };
    std::vector<K::FT> ss{K::FT(0), K::FT(1)};
    for (const P& V : vertices) {
        if (V == A) continue;
        const K::FT den = cross(V - A, C - B);
        if (den == 0) continue;
        const K::FT s = cross(B - A, V - A) / den;
        if (s > 0 && s < 1) ss.push_back(s);
    }
    std::sort(ss.begin(), ss.end());
    ss.erase(std::unique(ss.begin(), ss.end()), ss.end());
    for (std::size_t i = 0; i + 1 < ss.size(); ++i) {
        const K::FT s = (ss[i] + ss[i + 1]) / 2;
        if (!segment_in_mesh(m, A, B + s * (C - B), lo, hi)) return false;
    }
    return true;
}

bool mesh_mesh_intersect(const mesh_data& a, const mesh_data& b) {
    const Mesh x = to_cgal(a), y = to_cgal(b);
    return CGAL::Polygon_mesh_processing::do_intersect(x, y, CGAL::parameters::do_overlap_test_of_bounded_sides(true),
                                                       CGAL::parameters::do_overlap_test_of_bounded_sides(true));
}

} // namespace oracle
