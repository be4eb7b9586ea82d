// Inside the oracle only (CGAL types): the crossing parity of a point off a closed mesh's surface,
// and the mesh vertices' box (cgal_mesh.cpp, cgal_mesh_box.cpp).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cgal_oracle.hpp"

namespace oracle {
// Inside (mesh_inside): on a triangle, or an odd number of crossings of the segment from p to a
// random point q outside the bounding box, decided by CGAL::orientation alone: p and q strictly on
// opposite sides of a triangle's plane, and the three orientations of the segment against its
// edges all strictly of one sign. A zero among them (the segment through an edge or a vertex, or
// lying in the plane) draws another q.
// The parity of the crossings of a segment from P0 (approximately p, inside the vertices' box lo,
// hi, and off the surface) to random far points, until one segment passes through no edge, vertex
// or triangle plane.
template <class Kern>
bool crossing_parity(const mesh_data& m, const typename Kern::Point_3& P0, const std::array<double, 3>& p, const std::array<double, 3>& lo,
                     const std::array<double, 3>& hi) {
    using P = typename Kern::Point_3;
    std::mt19937_64 g(12345);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int attempt = 0; attempt < 1000; ++attempt) {
        // q beyond the box along a random direction: each coordinate 3 box widths out, or more
        std::array<double, 3> q{};
        for (unsigned k = 0; k < 3; ++k) {
            const double w = std::max(hi[k] - lo[k], std::max(std::fabs(lo[k]), std::fabs(hi[k])));
            q[k] = p[k] + 3 * w * u(g);
        }
        const unsigned far = static_cast<unsigned>(attempt % 3);
        q[far] = u(g) < 0 ? lo[far] - 2 * (hi[far] - lo[far]) - std::fabs(lo[far]) - 1
                          : hi[far] + 2 * (hi[far] - lo[far]) + std::fabs(hi[far]) + 1;
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2])) continue;
        if (q[far] >= lo[far] && q[far] <= hi[far]) continue; // rounding kept it inside the box
        const P Q(q[0], q[1], q[2]);
        bool odd = false, clean = true;
        for (const auto& t : m.t) {
            const P a(m.v[t[0]][0], m.v[t[0]][1], m.v[t[0]][2]), b(m.v[t[1]][0], m.v[t[1]][1], m.v[t[1]][2]),
                c(m.v[t[2]][0], m.v[t[2]][1], m.v[t[2]][2]);
            if (CGAL::collinear(a, b, c)) continue; // no interior to cross
            const auto o1 = CGAL::orientation(a, b, c, P0), o2 = CGAL::orientation(a, b, c, Q);
            if (o1 == CGAL::COPLANAR && o2 == CGAL::COPLANAR) {
                clean = false;
                break;
            }
            if (o1 == CGAL::COPLANAR || o2 == CGAL::COPLANAR || o1 == o2) continue; // meets the plane at p or q, or not at all
            const auto s1 = CGAL::orientation(P0, Q, a, b), s2 = CGAL::orientation(P0, Q, b, c), s3 = CGAL::orientation(P0, Q, c, a);
            const bool pos = s1 == CGAL::POSITIVE || s2 == CGAL::POSITIVE || s3 == CGAL::POSITIVE;
            const bool neg = s1 == CGAL::NEGATIVE || s2 == CGAL::NEGATIVE || s3 == CGAL::NEGATIVE;
            if (pos && neg) continue;
            if (s1 == CGAL::ZERO || s2 == CGAL::ZERO || s3 == CGAL::ZERO) {
                clean = false;
                break;
            }
            odd = !odd;
        }
        if (clean) return odd;
    }
    throw std::runtime_error("mesh_inside: no clean segment in 1000 draws");
}
inline void vertex_box(const mesh_data& m, std::array<double, 3>& lo, std::array<double, 3>& hi) {
    lo = hi = m.v[0];
    for (const auto& v : m.v)
        for (unsigned k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
}
} // namespace oracle
