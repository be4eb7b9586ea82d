// The tetrahedron pairs: a tetrahedron against a point, segment, ray, line, plane, triangle,
// box, OBB or tetrahedron, and contains(tetrahedron, point | segment | triangle | box |
// tetrahedron) and contains(box, tetrahedron). Byte 0 picks the second shape's kind (mod 9);
// then 12 doubles for the tetrahedron and 15 for the other shape (it reads the ones it needs: a
// point 3, a segment, ray or line 6, a plane 4, a triangle 9, a box 6 (min, max), an OBB 15
// (centre, axes, extents), a tetrahedron 12). Differential against CGAL Epeck (oracle::flat:
// Tetrahedron_3, Iso_cuboid_3, the exact LP for coplanar tetrahedra and flat boxes) and the LP
// for the OBB: the exact tier agrees, conservative never misses, aggressive never lies, classify
// is never wrong, both argument orders agree; on NaN or infinite input every tier must finish
// and the exact tier says no. With the top bit of byte 0 set, the first shape is instead a closed
// mesh of octahedron topology (6 vertices, 18 doubles; any positions, so possibly
// self-intersecting: its set is its triangles plus the points of odd crossing parity, which the
// oracle's parity along another ray must match) against one of eight kinds (mod 8, up to 12
// doubles: a point, segment, ray, line, plane, triangle, box or tetrahedron), and
// contains(mesh, point | segment | triangle | box) (the segment against the oracle's exact
// breakpoints and midpoints, the triangle against its chords between the exact directions of the
// traces' vertices, the box against the cells of each plane through it); with bit 0x40 of byte 0 too, against a second such mesh (18 doubles;
// CGAL::Polygon_mesh_processing::do_intersect) or, for byte 0 % 8 == 7, an OBB (the LP per
// triangle), or for 6, 5, 4 a convex polyhedron of 1 to 4 planes, a frustum or a 14-DOP from 18
// doubles (the LP per triangle, then crossing parity from the LP's exact point of the set). And
// without that bit, the point batch against the tetrahedron (batches.hpp: every lane the scalar
// answer in every tier, on a SIMD target byte 0 picks). Any finding aborts.
#include "testkit/oracle/cgal_oracle.hpp"
#include "replay.hpp"
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
import incidence;
import incidence.detail;
#include "contracts.hpp"
#include "batches.hpp"
#include "partners.hpp"
#include "testkit/testing.hpp"
#include "testkit/flat_cases.hpp"
#include "testkit/mesh_cases.hpp"
#include <array>
#include <cstdint>
#include <span>

using namespace incidence;

namespace {
constexpr int used[] = {3, 6, 6, 6, 4, 9, 6, 15, 12};

template <class F>
void with_shape(int kind, const double* v, F f) {
    const point3 p{v[0], v[1], v[2]}, q{v[3], v[4], v[5]}, s{v[6], v[7], v[8]}, t{v[9], v[10], v[11]};
    switch (kind) {
    case 0: f(p); break;
    case 1: f(segment3{p, q}); break;
    case 2: f(ray3{p, {v[3], v[4], v[5]}}); break;
    case 3: f(line3{p, {v[3], v[4], v[5]}}); break;
    case 4: f(plane3{{v[0], v[1], v[2]}, v[3]}); break;
    case 5: f(triangle3{p, q, s}); break;
    case 6: f(aabb3{p, q}); break; // may be inverted: empty
    case 7: f(obb3{p, {vec3{v[3], v[4], v[5]}, vec3{v[6], v[7], v[8]}, vec3{v[9], v[10], v[11]}}, {v[12], v[13], v[14]}}); break;
    default: f(tetrahedron3{p, q, s, t}); break;
    }
}

// The oracle's answer, or nothing when it declines (the LP's certificate check refuses some
// inputs spanning the whole exponent range at once; those only check that nothing crashes).
template <class B>
std::optional<bool> truth(const tetrahedron3& a, const B& b) {
    if constexpr (std::is_same_v<B, obb3>) {
        return oracle::lp_intersect_verified(support::lp(a), support::lp(b));
    } else {
        try {
            return support::flat_truth(a, b);
        } catch (const std::runtime_error&) { return std::nullopt; }
    }
}
template <class A, class B>
std::optional<bool> contains_truth(const A& a, const B& b) {
    try {
        if constexpr (std::is_same_v<A, tetrahedron3> && std::is_same_v<B, obb3>) {
            // the box's exact corners against CGAL Epeck's Tetrahedron_3 (a flat one: its faces)
            const double c[3] = {b.center.x, b.center.y, b.center.z};
            double x[9];
            for (unsigned i = 0; i < 3; ++i) x[3 * i] = b.axes[i].x, x[3 * i + 1] = b.axes[i].y, x[3 * i + 2] = b.axes[i].z;
            const double tv[12] = {a.a.x, a.a.y, a.a.z, a.b.x, a.b.y, a.b.z, a.c.x, a.c.y, a.c.z, a.d.x, a.d.y, a.d.z};
            return oracle::box_in_tetrahedron(c, x, b.half_extents.data(), tv);
        } else {
            return support::flat_contains_truth(a, b);
        }
    } catch (const std::runtime_error&) { return std::nullopt; }
}
template <class A, class B>
void contains_contracts(const A& a, const B& b, bool finite) {
    (void)contains<approximate>(a, b);
    (void)classify_contains(a, b);
    const bool e = contains<exact>(a, b);
    if (!finite) {
        if (e) std::abort();
        return;
    }
    const auto t = contains_truth(a, b);
    if (!t) return;
    if (e != *t) std::abort();
    if (*t && !contains<conservative>(a, b)) std::abort();
    if (!*t && contains<aggressive>(a, b)) std::abort();
    const certainty c = classify_contains(a, b);
    if (c != certainty::uncertain && (c == certainty::yes) != *t) std::abort();
}

template <class B>
void check(const tetrahedron3& a, const B& b, bool finite) {
    (void)intersects<approximate>(a, b);
    (void)intersects<conservative>(b, a);
    (void)intersects<aggressive>(a, b);
    (void)classify(b, a);
    if constexpr (requires { contains(a, b); }) {
        // an inverted box or a negative extent is no set the oracle can take: only the empty answer is checked
        bool ordered = true;
        if constexpr (std::is_same_v<B, aabb3>) ordered = b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z;
        if constexpr (std::is_same_v<B, obb3>) ordered = b.half_extents[0] >= 0 && b.half_extents[1] >= 0 && b.half_extents[2] >= 0;
        if (ordered) contains_contracts(a, b, finite);
        else if (contains(a, b)) std::abort();
    }
    if constexpr (std::is_same_v<B, aabb3>) {
        const bool ordered = b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z;
        if (ordered) contains_contracts(b, a, finite);
        else if (contains(b, a)) std::abort();
    }
    if (!finite) {
        if (intersects<exact>(a, b)) std::abort(); // NaN or infinite input: no
        return;
    }
    if constexpr (std::is_same_v<B, obb3>) {
        // the LP takes extents as given: a negative one is an empty box, which the library says too
        if (!(b.half_extents[0] >= 0 && b.half_extents[1] >= 0 && b.half_extents[2] >= 0)) {
            if (intersects(a, b)) std::abort();
            return;
        }
    }
    if (const auto t = truth(a, b)) contracts(a, b, *t);
}
using fuzz::octahedron;

// Two meshes that may intersect themselves (any vertex positions): PMP::do_intersect, the
// tests' oracle, expects self-intersection-free meshes, so here the oracle is the set's
// definition with CGAL's pieces: a triangle pair meets (Epeck), or a vertex of one lies inside
// the other (oracle::mesh_inside, crossing parity by CGAL::orientation).
bool mesh_mesh_truth(const mesh3& a, const mesh3& b) {
    const auto da = support::mesh_data_of(a), db = support::mesh_data_of(b);
    auto tri = [](const oracle::mesh_data& d, const std::array<unsigned, 3>& t) {
        oracle::flat f{oracle::flat::triangle, {}};
        for (unsigned j = 0; j < 3; ++j)
            for (unsigned c = 0; c < 3; ++c) f.v[3 * j + c] = d.v[t[j]][c];
        return f;
    };
    for (const auto& s : da.t)
        for (const auto& u : db.t)
            if (oracle::flat_intersect(tri(da, s), tri(db, u))) return true;
    return oracle::mesh_inside(db, da.v[0]) || oracle::mesh_inside(da, db.v[0]);
}

template <class B>
void check_mesh(const mesh3& m, const B& b, bool finite) {
    (void)intersects<approximate>(m, b);
    (void)intersects<conservative>(b, m);
    (void)intersects<aggressive>(m, b);
    (void)classify(b, m);
    if (!finite) {
        if (intersects<exact>(m, b)) std::abort();
        if constexpr (std::is_same_v<B, point3> || std::is_same_v<B, segment3> || std::is_same_v<B, triangle3> || std::is_same_v<B, aabb3>)
            if (contains(m, b)) std::abort();
        if constexpr (std::is_same_v<B, segment3> || std::is_same_v<B, triangle3> || std::is_same_v<B, aabb3>)
            (void)contains<approximate>(m, b), (void)classify_contains(m, b);
        return;
    }
    if constexpr (std::is_same_v<B, aabb3>)
        if (!(b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z)) {
            if (intersects(m, b) || contains(m, b)) std::abort(); // an inverted box is empty
            (void)contains<approximate>(m, b), (void)classify_contains(m, b);
            return;
        }
    if constexpr (std::is_same_v<B, obb3>)
        if (!(b.half_extents[0] >= 0 && b.half_extents[1] >= 0 && b.half_extents[2] >= 0)) {
            if (intersects(m, b)) std::abort(); // a negative extent: an empty box
            return;
        }
    std::optional<bool> t;
    try {
        if constexpr (std::is_same_v<B, mesh3>) t = mesh_mesh_truth(m, b);
        else t = support::mesh_truth(m, b);
    } catch (const std::runtime_error&) {
        return; // the oracle declined (the LP's certificate check, or no clean ray in 1,000 draws)
    }
    contracts(m, b, *t);
    if constexpr (std::is_same_v<B, point3>)
        if (contains(m, b) != *t) std::abort();
    if constexpr (std::is_same_v<B, segment3>) { // contains against the oracle's exact breakpoints
        bool in = false;
        try {
            in = support::segment_in_mesh_truth(m, b);
        } catch (const std::runtime_error&) { return; }
        contains_contracts_with(m, b, in);
    }
    if constexpr (std::is_same_v<B, aabb3>) { // contains against the oracle's cells of each plane through the box
        bool in = false;
        try {
            in = support::box_in_mesh_truth(m, b);
        } catch (const std::runtime_error&) { return; }
        contains_contracts_with(m, b, in);
    }
    if constexpr (std::is_same_v<B, triangle3>) { // contains against the oracle's chords between exact directions
        bool in = false;
        try {
            in = support::triangle_in_mesh_truth(m, b);
        } catch (const std::runtime_error&) { return; }
        contains_contracts_with(m, b, in);
    }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    if (data[0] & 0x80) {
        double w[36] = {};
        std::memcpy(w, data + 1, size - 1 < sizeof w ? size - 1 : sizeof w);
        std::array<point3, 6> verts, verts2;
        for (unsigned i = 0; i < 6; ++i) verts[i] = point3{w[3 * i], w[3 * i + 1], w[3 * i + 2]};
        for (unsigned i = 0; i < 6; ++i) verts2[i] = point3{w[18 + 3 * i], w[19 + 3 * i], w[20 + 3 * i]};
        const mesh3 m{verts, octahedron};
        bool finite = true;
        if ((data[0] & 0x40) && data[0] % 8 >= 4 && data[0] % 8 <= 6) { // a half-space set (18 doubles)
            // the doubles each set reads: 4 per plane (1 to 4), a frustum's 18, a 14-DOP's 14
            const int reads = data[0] % 8 == 6 ? 4 * (1 + data[0] / 8 % 4) : (data[0] % 8 == 5 ? 18 : 14);
            for (int i = 0; i < 18 + reads; ++i) finite = finite && std::isfinite(w[i]);
            const double* h = w + 18;
            if (data[0] % 8 == 6) check_mesh(m, fuzz::polyhedron_from(h, 1 + data[0] / 8 % 4), finite); // 1 to 4 planes
            else if (data[0] % 8 == 5) check_mesh(m, fuzz::frustum_from(h), finite); // six planes, the doubles read again
            else check_mesh(m, fuzz::kdop14_from(h), finite);                        // a 14-DOP's bounds (maybe inverted: empty)
            return 0;
        }
        if (data[0] & 0x40) { // a second mesh (18 doubles), or an OBB when byte 0 % 8 == 7 (its LP per triangle is slow)
            const bool box = data[0] % 8 == 7;
            for (int i = 0; i < 18 + (box ? 15 : 18); ++i) finite = finite && std::isfinite(w[i]);
            if (box)
                with_shape(7, w + 18, [&](const auto& b) {
                    if constexpr (std::is_same_v<std::decay_t<decltype(b)>, obb3>) check_mesh(m, b, finite);
                });
            else check_mesh(m, mesh3{verts2, octahedron}, finite);
            return 0;
        }
        const int kb = data[0] % 8 == 7 ? 8 : data[0] % 8; // a tetrahedron for 7
        for (int i = 0; i < 18 + used[kb]; ++i) finite = finite && std::isfinite(w[i]);
        with_shape(kb, w + 18, [&](const auto& b) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(b)>, obb3>) check_mesh(m, b, finite);
        });
        return 0;
    }
    double v[27] = {};
    std::memcpy(v, data + 1, size - 1 < sizeof v ? size - 1 : sizeof v);
    const int kb = data[0] % 9;
    bool finite = true;
    for (int i = 0; i < 12; ++i) finite = finite && std::isfinite(v[i]);
    for (int i = 0; i < used[kb]; ++i) finite = finite && std::isfinite(v[12 + i]);
    const tetrahedron3 a{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}, {v[9], v[10], v[11]}};
    with_shape(kb, v + 12, [&](const auto& b) { check(a, b, finite); });
    // the point batch: the five points of the other doubles, the vertices, an ulp off one, and
    // the rounded midpoints of two edges, every lane equal to the scalar answer in every tier
    const point3 ps[12] = {{v[12], v[13], v[14]},
                           {v[15], v[16], v[17]},
                           {v[18], v[19], v[20]},
                           {v[21], v[22], v[23]},
                           {v[24], v[25], v[26]},
                           a.a,
                           a.b,
                           a.c,
                           a.d,
                           {std::nextafter(a.a.x, 0.0), a.a.y, a.a.z},
                           {0.5 * a.a.x + 0.5 * a.b.x, 0.5 * a.a.y + 0.5 * a.b.y, 0.5 * a.a.z + 0.5 * a.b.z},
                           {0.5 * a.c.x + 0.5 * a.d.x, 0.5 * a.c.y + 0.5 * a.d.y, 0.5 * a.c.z + 0.5 * a.d.z}};
    batch_contracts(a, std::span<const point3>(ps), data[0]);
    return 0;
}
