// The polygon oracle: polygons with holes in the plane as CGAL Polygon_2 rings over Epeck.
// A point is in the polygon when it lies on an edge (do_intersect of Epeck objects, via
// flat_intersect) or on the bounded side of an odd number of rings (Polygon_2::bounded_side, one
// ring at a time: for disjoint simple rings, the even-odd rule). A shape meets the polygon when
// it meets an edge or a point of it is in the polygon.
#include "cgal_oracle.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/intersections.h>
#include <gmpxx.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <algorithm>
#include <list>
#include <stdexcept>

namespace oracle {
namespace {
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Ring = CGAL::Polygon_2<K>;

std::vector<Ring> rings_of(const polygon_data& g) {
    std::vector<Ring> rings;
    unsigned b = 0;
    for (unsigned e : g.ring_ends) {
        Ring r;
        for (unsigned i = b; i < e; ++i) r.push_back(K::Point_2(g.v[i][0], g.v[i][1]));
        rings.push_back(r);
        b = e;
    }
    return rings;
}
template <class F>
bool any_edge(const polygon_data& g, const F& f) {
    unsigned b = 0;
    for (unsigned e : g.ring_ends) {
        for (unsigned i = b; i < e; ++i) {
            const auto& p = g.v[i];
            const auto& q = g.v[i + 1 == e ? b : i + 1];
            if (f(flat2{flat2::segment, {p[0], p[1], q[0], q[1]}})) return true;
        }
        b = e;
    }
    return false;
}
bool odd_rings(const std::vector<Ring>& rings, const std::array<double, 2>& p) {
    const K::Point_2 P(p[0], p[1]);
    bool odd = false;
    for (const auto& r : rings)
        if (r.bounded_side(P) == CGAL::ON_BOUNDED_SIDE) odd = !odd;
    return odd;
}
std::array<double, 2> a_point(const flat2& x) { return {x.v[0], x.v[1]}; }
} // namespace

bool polygon_simple(const polygon_data& g) {
    const auto rings = rings_of(g);
    for (const auto& r : rings)
        if (r.size() < 3 || !r.is_simple()) return false;
    // rings pairwise disjoint: no edge of one meets an edge of another
    unsigned b = 0;
    for (std::size_t i = 0; i < g.ring_ends.size(); ++i) {
        const unsigned e = g.ring_ends[i];
        for (unsigned j = b; j < e; ++j) {
            const auto& p = g.v[j];
            const auto& q = g.v[j + 1 == e ? b : j + 1];
            const flat2 edge{flat2::segment, {p[0], p[1], q[0], q[1]}};
            unsigned b2 = e;
            for (std::size_t k = i + 1; k < g.ring_ends.size(); ++k) {
                const unsigned e2 = g.ring_ends[k];
                for (unsigned m = b2; m < e2; ++m) {
                    const auto& r = g.v[m];
                    const auto& s = g.v[m + 1 == e2 ? b2 : m + 1];
                    if (flat_intersect(edge, flat2{flat2::segment, {r[0], r[1], s[0], s[1]}})) return false;
                }
                b2 = e2;
            }
        }
        b = e;
    }
    return true;
}

bool polygon_intersect(const polygon_data& g, const flat2& x) {
    if (any_edge(g, [&](const flat2& e) { return flat_intersect(e, x); })) return true;
    return odd_rings(rings_of(g), a_point(x));
}

bool polygon_polygon_intersect(const polygon_data& a, const polygon_data& b) {
    const bool edges = any_edge(a, [&](const flat2& e) { return any_edge(b, [&](const flat2& f) { return flat_intersect(e, f); }); });
    return edges || odd_rings(rings_of(b), a.v[0]) || odd_rings(rings_of(a), b.v[0]);
}

// The triangles of a planar polygon in space: its projection triangulated with the ring edges as
// constraints (the rings are disjoint and simple, so no constraint crosses another and the
// triangulation adds no vertex), each face's nesting depth counted by a flood fill from the
// infinite face that steps up by one across a constraint; odd depth is inside (even-odd rule).
// Source: CGAL's 2D triangulation package (Yvinec, CGAL manual, "2D Triangulations", section
// on constrained triangulations and domain marking).
std::vector<std::array<double, 9>> polygon3_triangles(const polygon3_data& g) {
    using KI = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<unsigned, KI>;
    using Fb0 = CGAL::Constrained_triangulation_face_base_2<KI>;
    using Fb = CGAL::Triangulation_face_base_with_info_2<int, KI, Fb0>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using CDT = CGAL::Constrained_Delaunay_triangulation_2<KI, Tds, CGAL::Exact_predicates_tag>;
    const int u = (g.axis + 1) % 3, w = (g.axis + 2) % 3;
    CDT cdt;
    std::vector<CDT::Vertex_handle> handle(g.v.size());
    for (unsigned i = 0; i < g.v.size(); ++i) {
        handle[i] = cdt.insert(KI::Point_2(g.v[i][static_cast<unsigned>(u)], g.v[i][static_cast<unsigned>(w)]));
        handle[i]->info() = i;
    }
    unsigned b = 0;
    for (unsigned e : g.ring_ends) {
        for (unsigned i = b; i < e; ++i) cdt.insert_constraint(handle[i], handle[i + 1 == e ? b : i + 1]);
        b = e;
    }
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::list<CDT::Edge> border;
    auto flood = [&](CDT::Face_handle start, int depth) {
        std::list<CDT::Face_handle> queue{start};
        while (!queue.empty()) {
            const CDT::Face_handle f = queue.front();
            queue.pop_front();
            if (f->info() != -1) continue;
            f->info() = depth;
            for (int i = 0; i < 3; ++i) {
                const CDT::Face_handle n = f->neighbor(i);
                if (n->info() != -1) continue;
                if (cdt.is_constrained(CDT::Edge(f, i))) border.push_back(CDT::Edge(f, i));
                else queue.push_back(n);
            }
        }
    };
    flood(cdt.infinite_face(), 0);
    while (!border.empty()) {
        const CDT::Edge e = border.front();
        border.pop_front();
        const CDT::Face_handle n = e.first->neighbor(e.second);
        if (n->info() == -1) flood(n, e.first->info() + 1);
    }
    std::vector<std::array<double, 9>> out;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (f->info() % 2 != 1) continue;
        std::array<double, 9> t{};
        for (int j = 0; j < 3; ++j)
            for (int c = 0; c < 3; ++c) t[static_cast<unsigned>(3 * j + c)] = g.v[f->vertex(j)->info()][static_cast<unsigned>(c)];
        out.push_back(t);
    }
    return out;
}

// Containment of a segment (exact breakpoints, exact midpoints) and of a triangle (exact areas).
namespace {
// t = (P - A) . D / D . D for the points where the segment A B meets each of `edges`, sorted,
// with 0 and 1; the open pieces between them each lie on an edge or off all of them.
std::vector<K::FT> breakpoints(const K::Segment_2& S, const std::vector<K::Segment_2>& edges) {
    const K::Point_2 A = S.source();
    const K::Vector_2 D = S.target() - A;
    const K::FT dd = D * D;
    std::vector<K::FT> ts{K::FT(0), K::FT(1)};
    for (const auto& E : edges) {
        if (E.is_degenerate()) {
            if (S.has_on(E.source())) ts.push_back(((E.source() - A) * D) / dd);
            continue;
        }
        const auto r = CGAL::intersection(S, E);
        if (!r) continue;
        if (const K::Point_2* p = boost::get<K::Point_2>(&*r)) ts.push_back(((*p - A) * D) / dd);
        else if (const K::Segment_2* q = boost::get<K::Segment_2>(&*r)) {
            ts.push_back(((q->source() - A) * D) / dd);
            ts.push_back(((q->target() - A) * D) / dd);
        }
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    return ts;
}
std::vector<K::Segment_2> edges_of(const polygon_data& g) {
    std::vector<K::Segment_2> out;
    unsigned b = 0;
    for (unsigned e : g.ring_ends) {
        for (unsigned i = b; i < e; ++i) {
            const auto& p = g.v[i];
            const auto& q = g.v[i + 1 == e ? b : i + 1];
            out.emplace_back(K::Point_2(p[0], p[1]), K::Point_2(q[0], q[1]));
        }
        b = e;
    }
    return out;
}
// The polygon's triangles (polygon3_triangles) projected, as Epeck triangles.
std::vector<K::Triangle_2> projected_triangles(const polygon3_data& g) {
    const unsigned u = static_cast<unsigned>((g.axis + 1) % 3), w = static_cast<unsigned>((g.axis + 2) % 3);
    std::vector<K::Triangle_2> out;
    for (const auto& t : polygon3_triangles(g))
        out.emplace_back(K::Point_2(t[u], t[w]), K::Point_2(t[3 + u], t[3 + w]), K::Point_2(t[6 + u], t[6 + w]));
    return out;
}
// Are the points in the polygon's plane (CGAL::orientation against a triangle of it)?
bool in_plane(const polygon3_data& g, const std::vector<std::array<double, 3>>& pts) {
    const auto tris = polygon3_triangles(g);
    if (tris.empty()) throw std::runtime_error("polygon3 oracle: no triangle");
    const auto& t = tris[0];
    const K::Point_3 a(t[0], t[1], t[2]), b(t[3], t[4], t[5]), c(t[6], t[7], t[8]);
    for (const auto& p : pts)
        if (CGAL::orientation(a, b, c, K::Point_3(p[0], p[1], p[2])) != CGAL::COPLANAR) return false;
    return true;
}
K::Point_2 project(const polygon3_data& g, const std::array<double, 3>& p) {
    return {p[static_cast<unsigned>((g.axis + 1) % 3)], p[static_cast<unsigned>((g.axis + 2) % 3)]};
}
// Is the segment in the union of the triangles (a closed set)?
bool segment_in_triangles(const std::vector<K::Triangle_2>& tris, const K::Point_2& A, const K::Point_2& B) {
    if (A == B) {
        for (const auto& T : tris)
            if (!T.has_on_unbounded_side(A)) return true;
        return false;
    }
    const K::Segment_2 S(A, B);
    std::vector<K::Segment_2> edges;
    for (const auto& T : tris)
        for (int i = 0; i < 3; ++i) edges.emplace_back(T.vertex(i), T.vertex(i + 1));
    const auto ts = breakpoints(S, edges);
    const K::Vector_2 D = B - A;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
        const K::Point_2 M = A + ((ts[i] + ts[i + 1]) / 2) * D;
        bool in = false;
        for (const auto& T : tris) in = in || !T.has_on_unbounded_side(M);
        if (!in) return false;
    }
    return true; // the breakpoints lie in the closures of the pieces
}
} // namespace

bool polygon_contains_segment(const polygon_data& g, const std::array<double, 2>& a, const std::array<double, 2>& b) {
    const auto rings = rings_of(g);
    const auto edges = edges_of(g);
    auto in_set = [&](const K::Point_2& P) {
        for (const auto& E : edges)
            if (E.has_on(P)) return true;
        bool odd = false;
        for (const auto& r : rings)
            if (r.bounded_side(P) == CGAL::ON_BOUNDED_SIDE) odd = !odd;
        return odd;
    };
    const K::Point_2 A(a[0], a[1]), B(b[0], b[1]);
    if (!in_set(A) || !in_set(B)) return false;
    if (A == B) return true;
    const K::Segment_2 S(A, B);
    const auto ts = breakpoints(S, edges);
    const K::Vector_2 D = B - A;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i)
        if (!in_set(A + ((ts[i] + ts[i + 1]) / 2) * D)) return false;
    return true;
}

bool polygon3_contains_segment(const polygon3_data& g, const std::array<double, 3>& a, const std::array<double, 3>& b) {
    if (!in_plane(g, {a, b})) return false;
    return segment_in_triangles(projected_triangles(g), project(g, a), project(g, b));
}

bool polygon3_contains_triangle(const polygon3_data& g, const std::array<double, 9>& t) {
    const std::array<double, 3> p{t[0], t[1], t[2]}, q{t[3], t[4], t[5]}, r{t[6], t[7], t[8]};
    if (!in_plane(g, {p, q, r})) return false;
    const auto tris = projected_triangles(g);
    const K::Point_2 P = project(g, p), Qp = project(g, q), R = project(g, r);
    if (CGAL::collinear(P, Qp, R))
        return segment_in_triangles(tris, P, Qp) && segment_in_triangles(tris, Qp, R) && segment_in_triangles(tris, R, P);
    // the triangle in the union of the polygon's triangles (disjoint interiors) iff the areas of
    // its intersections with them add up to its own: each intersection by clipping the triangle
    // against the three edges of the other (Sutherland-Hodgman) in GMP rationals
    using Q = mpq_class;
    using Pt = std::array<Q, 2>;
    auto to_q = [](const K::Point_2& x) { return Pt{Q(CGAL::to_double(x.x())), Q(CGAL::to_double(x.y()))}; }; // the inputs are doubles
    auto cross = [](const Pt& o, const Pt& a, const Pt& b) { return Q((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])); };
    auto area2 = [](const std::vector<Pt>& poly) { // twice the signed area
        Q s = 0;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Pt& a = poly[i];
            const Pt& b = poly[(i + 1) % poly.size()];
            s += a[0] * b[1] - a[1] * b[0];
        }
        return s;
    };
    auto ccw = [&](std::vector<Pt> poly) {
        if (area2(poly) < 0) std::reverse(poly.begin(), poly.end());
        return poly;
    };
    const std::vector<Pt> x = ccw({to_q(P), to_q(Qp), to_q(R)});
    Q covered = 0;
    for (const auto& T : tris) {
        const std::vector<Pt> t = ccw({to_q(T.vertex(0)), to_q(T.vertex(1)), to_q(T.vertex(2))});
        std::vector<Pt> poly = x;
        for (std::size_t e = 0; e < 3 && !poly.empty(); ++e) {
            const Pt &a = t[e], &b = t[(e + 1) % 3];
            std::vector<Pt> out;
            for (std::size_t i = 0; i < poly.size(); ++i) {
                const Pt &p0 = poly[i], &p1 = poly[(i + 1) % poly.size()];
                const Q s0 = cross(a, b, p0), s1 = cross(a, b, p1);
                if (s0 >= 0) out.push_back(p0);
                if ((s0 > 0 && s1 < 0) || (s0 < 0 && s1 > 0)) {
                    const Q f = s0 / (s0 - s1);
                    out.push_back(Pt{Q(p0[0] + f * (p1[0] - p0[0])), Q(p0[1] + f * (p1[1] - p0[1]))});
                }
            }
            poly = out;
        }
        if (poly.size() >= 3) covered += area2(poly);
    }
    return covered == area2(x);
}

} // namespace oracle
