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
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
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

} // namespace oracle
