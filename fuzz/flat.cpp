// The flat pairs: points, lines, rays, segments, planes and triangles against each other (every
// ordered pair of the six kinds, 36 in all), and points, segments, rays and lines in the plane
// (16 more), and a disk (circle2, doubles 20..22) against the first of those and against a disk of
// doubles 23..25 (contains too). Byte 0 picks the first shape's kind (the plane's when its top bit is set), byte 1
// the second's, then 9 doubles each (a shape reads the ones it needs: a point 3, a segment, ray
// or line 6, a plane 4 (normal, offset), a triangle 9; in the plane a point 2, the others 4). Differential against CGAL Epeck
// (oracle::flat): the exact tier agrees, conservative never misses, aggressive never lies,
// classify is never wrong, both argument orders agree; on NaN or infinite input every tier must
// finish and the exact tier says no. Polygon mode (bits 0x80 and 0x40 of byte 0): a polygon of six
// vertices (12 doubles; one ring, or two rings of three when byte 1 has bit 0x40) against a point,
// segment, ray or line in the plane (4 doubles) or a triangle polygon (6 doubles), byte 1 % 5;
// any positions, so possibly self-intersecting: polygon2::make must accept exactly the simple
// ones (CGAL Polygon_2::is_simple and disjoint rings, oracle::polygon_simple), and for those the
// contracts hold against oracle::polygon_intersect; contains(polygon, point | segment) too (the
// segment against oracle::polygon_contains_segment), and a disk (doubles 24..26) against the
// polygon both ways, contains(polygon, disk) against circle2_cases.hpp's polygon_holds_disk_truth. 3D polygon mode
// (byte 0 & 0xc0 == 0x40 and byte 1 & 0x80): a polygon3 of six vertices (12 doubles, one ring or
// two of three as above) in the plane where coordinate byte 0 % 3 is the 13th double, exactly
// planar, against the 3D shape of kind byte 1 % 6 (9 more doubles): polygon3::make must accept
// exactly the simple ones, whose contracts hold against the triangles of the polygon's CGAL
// triangulation (oracle::polygon3_triangles, each by oracle::flat), and contains(polygon3,
// segment3 | triangle3) against the oracle's covering by those triangles; the same vertices bent off the
// plane (one coordinate replaced) run every tier unchecked. With bit 0x20 of byte 1 too, the
// polygon3 is against a closed shape of kind byte 1 % 8 (up to 18 more doubles): a box (6, maybe
// inverted), an OBB (15), a tetrahedron (12), a convex polyhedron of 1 to 4 planes, a frustum
// (18), a 14-DOP (14), a mesh of octahedron topology (18, maybe self-intersecting) or a second
// polygon3 (13, its plane's coordinate (byte 1 / 8) % 3); the triangles go against it by
// oracle::flat, the exact LP or the mesh oracle (support::polygon3_truth). Any finding aborts.
#include "testkit/oracle/cgal_oracle.hpp"
#include "replay.hpp"
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
import incidence;
import incidence.detail;
#include "contracts.hpp"
#include "partners.hpp"
#include "testkit/testing.hpp"
#include "testkit/flat_cases.hpp"
#include "testkit/flat_shapes.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/mesh_cases.hpp"
#include "testkit/polygon3_cases.hpp"
#include "testkit/circle2_cases.hpp"
#include <array>
#include <cstdint>
#include <span>

using namespace incidence;

namespace {
template <class F>
void with_shape(int kind, const double* v, F f) {
    switch (kind) {
    case 0: f(point3{v[0], v[1], v[2]}); break;
    case 1: f(segment3{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}); break;
    case 2: f(ray3{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}); break;
    case 3: f(line3{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}); break;
    case 4: f(plane3{{v[0], v[1], v[2]}, v[3]}); break;
    default: f(triangle3{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}}); break;
    }
}
template <class F>
void with_shape2(int kind, const double* v, F f) {
    switch (kind) {
    case 0: f(point2{v[0], v[1]}); break;
    case 1: f(segment2{{v[0], v[1]}, {v[2], v[3]}}); break;
    case 2: f(ray2{{v[0], v[1]}, {v[2], v[3]}}); break;
    default: f(line2{{v[0], v[1]}, {v[2], v[3]}}); break;
    }
}
constexpr int used[] = {3, 6, 6, 6, 4, 9};
constexpr int used2[] = {2, 4, 4, 4};

// Six vertices in the plane where coordinate `axis` is w[12], from w[0..12).
std::array<point3, 6> planar_hexagon(const double* w, int axis) {
    std::array<point3, 6> verts;
    for (unsigned i = 0; i < 6; ++i) {
        double c[3];
        c[axis] = w[12];
        c[(axis + 1) % 3] = w[2 * i], c[(axis + 2) % 3] = w[2 * i + 1];
        verts[i] = point3{c[0], c[1], c[2]};
    }
    return verts;
}
// The closed partners of a polygon3 (kind 0..7) and the doubles each reads (the convex polyhedron
// 4 per plane).
constexpr int used_closed[] = {6, 15, 12, 16, 18, 14, 18, 13};
template <class F>
void with_closed(int kind, const double* h, int planes, int axis, F f) {
    const point3 p{h[0], h[1], h[2]};
    switch (kind) {
    case 0: f(aabb3{p, {h[3], h[4], h[5]}}); break;
    case 1: f(obb3{p, {vec3{h[3], h[4], h[5]}, vec3{h[6], h[7], h[8]}, vec3{h[9], h[10], h[11]}}, {h[12], h[13], h[14]}}); break;
    case 2: f(tetrahedron3{p, {h[3], h[4], h[5]}, {h[6], h[7], h[8]}, {h[9], h[10], h[11]}}); break;
    case 3: f(fuzz::polyhedron_from(h, planes)); break;
    case 4: f(fuzz::frustum_from(h)); break;
    case 5: f(fuzz::kdop14_from(h)); break;
    case 6: {
        std::array<point3, 6> verts;
        for (unsigned i = 0; i < 6; ++i) verts[i] = point3{h[3 * i], h[3 * i + 1], h[3 * i + 2]};
        f(mesh3{verts, fuzz::octahedron});
        break;
    }
    default: {
        const auto verts = planar_hexagon(h, axis);
        const auto made = polygon3::make(verts, {});
        f(made.has_value() ? made.value() : polygon3{verts, {}, {0, 1, 2}, axis}); // unchecked when not made
        break;
    }
    }
}

// Every tier must finish on any bits; on finite input the contracts hold against the oracle.
template <class A, class B>
void check(const A& a, const B& b, bool finite) {
    (void)intersects<approximate>(a, b);
    (void)intersects<conservative>(b, a);
    (void)intersects<aggressive>(a, b);
    (void)classify(b, a);
    if (!finite) {
        if (intersects<exact>(a, b)) std::abort(); // NaN or infinite input: no
        return;
    }
    contracts(a, b, support::flat_truth(a, b));
}
oracle::polygon_data data_of(const polygon2& g) {
    oracle::polygon_data d;
    for (const auto& p : g.vertices) d.v.push_back({p.x, p.y});
    if (g.ring_ends.empty()) d.ring_ends.push_back(static_cast<unsigned>(g.vertices.size()));
    for (auto e : g.ring_ends) d.ring_ends.push_back(e);
    return d;
}
template <class B>
void check_polygon(const polygon2& g, const B& b, bool finite) {
    (void)intersects<approximate>(g, b);
    (void)intersects<conservative>(b, g);
    (void)intersects<aggressive>(g, b);
    (void)classify(b, g);
    if (!finite) {
        if (intersects<exact>(g, b)) std::abort();
        if constexpr (std::is_same_v<B, segment2>) (void)contains<approximate>(g, b), (void)classify_contains(g, b);
        if constexpr (std::is_same_v<B, segment2>)
            if (contains(g, b)) std::abort();
        bool vertices_finite = true;
        for (const auto& p : g.vertices) vertices_finite = vertices_finite && std::isfinite(p.x) && std::isfinite(p.y);
        if (!vertices_finite && polygon2::make(g.vertices, g.ring_ends).has_value()) std::abort();
        return;
    }
    const bool simple = oracle::polygon_simple(data_of(g));
    if (polygon2::make(g.vertices, g.ring_ends).has_value() != simple) std::abort();
    if (!simple) return; // the even-odd set is defined, but bounded_side needs a simple ring
    bool truth;
    if constexpr (std::is_same_v<B, polygon2>) {
        if (!oracle::polygon_simple(data_of(b))) return;
        truth = oracle::polygon_polygon_intersect(data_of(g), data_of(b));
    } else {
        truth = oracle::polygon_intersect(data_of(g), support::to_flat(b));
    }
    contracts(g, b, truth);
    if constexpr (std::is_same_v<B, point2>)
        if (contains(g, b) != truth) std::abort();
    if constexpr (std::is_same_v<B, segment2>) // contains against the oracle's exact breakpoints
        contains_contracts_with(g, b, oracle::polygon_contains_segment(data_of(g), {b.a.x, b.a.y}, {b.b.x, b.b.y}));
}
// A disk of the doubles d[0..3) (centre, radius) against b: every tier on any bits; on finite ones
// the contracts against testkit/circle2_cases.hpp's oracle, and contains(disk, b) for a point, a
// segment, a disk or a polygon, and contains(polygon, disk).
template <class B>
void check_disk(const double* d, const B& b, bool finite) {
    const circle2 c{{d[0], d[1]}, d[2]};
    (void)intersects<approximate>(c, b);
    (void)intersects<conservative>(b, c);
    (void)intersects<aggressive>(c, b);
    (void)classify(b, c);
    if (!(finite && std::isfinite(d[0]) && std::isfinite(d[1]) && std::isfinite(d[2]))) {
        if (intersects<exact>(c, b)) std::abort();
        if constexpr (std::is_same_v<B, polygon2>)
            if (contains(b, c)) std::abort();
        return;
    }
    contracts(c, b, support::disk_truth(c, b));
    if constexpr (!std::is_same_v<B, ray2> && !std::is_same_v<B, line2>) contains_contracts_with(c, b, support::disk_holds_truth(c, b));
    if constexpr (std::is_same_v<B, polygon2>) contains_contracts_with(b, c, support::polygon_holds_disk_truth(b, c));
}
// The 3D polygon: every tier finishes; on finite input make() accepts exactly the simple rings, and
// the contracts hold against the triangulation oracle (support::polygon3_truth).
template <class B>
void check_polygon3(const std::array<point3, 6>& verts, std::span<const std::uint32_t> ends, int axis, const B& b, bool finite) {
    const auto made = polygon3::make(verts, ends);
    const polygon3 g = made.has_value() ? made.value() : polygon3{verts, ends, {0, 1, 2}, axis};
    (void)intersects<approximate>(g, b);
    (void)intersects<conservative>(b, g);
    (void)intersects<aggressive>(g, b);
    (void)classify(b, g);
    if (!finite) {
        bool vertices_finite = true;
        for (const auto& p : verts) vertices_finite = vertices_finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        if (!vertices_finite && made.has_value()) std::abort();
        if (intersects<exact>(g, b)) std::abort();
        if constexpr (std::is_same_v<B, segment3> || std::is_same_v<B, triangle3>) {
            (void)contains<approximate>(g, b), (void)classify_contains(g, b);
            if (contains(g, b)) std::abort();
        }
        return;
    }
    oracle::polygon_data flat;
    for (const auto& p : verts) {
        const double c[3] = {p.x, p.y, p.z};
        flat.v.push_back({c[(axis + 1) % 3], c[(axis + 2) % 3]});
    }
    if (ends.empty()) flat.ring_ends.push_back(6);
    for (auto e : ends) flat.ring_ends.push_back(e);
    const bool simple = oracle::polygon_simple(flat);
    // a ring on one line has no area: make refuses it as degenerate (polygon_simple may accept it)
    if (made.has_value() && !simple) std::abort();
    if (!made.has_value()) return;
    if constexpr (std::is_same_v<B, polygon3>)
        if (!polygon3::make(b.vertices, b.ring_ends).has_value()) return; // a partner that is no set: unchecked
    // empty partners: the oracle's forms need bounds in order, the library says no
    bool empty = false;
    if constexpr (std::is_same_v<B, aabb3>) empty = !(b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z);
    if constexpr (std::is_same_v<B, obb3>) empty = !(b.half_extents[0] >= 0 && b.half_extents[1] >= 0 && b.half_extents[2] >= 0);
    if (empty) {
        if (intersects(g, b)) std::abort();
        return;
    }
    bool truth = false;
    try {
        truth = support::polygon3_truth(g, b);
    } catch (const std::runtime_error&) {
        return; // the oracle declined (the LP's certificate check, or no clean ray for the parity)
    }
    contracts(g, b, truth);
    if constexpr (std::is_same_v<B, point3>)
        if (contains(g, b) != truth) std::abort();
    if constexpr (std::is_same_v<B, segment3> || std::is_same_v<B, triangle3>) { // contains: in the plane, covered by the triangulation
        try {
            if constexpr (std::is_same_v<B, segment3>) truth = support::segment_in_polygon3_truth(g, b);
            else truth = support::triangle_in_polygon3_truth(g, b);
        } catch (const std::runtime_error&) { return; }
        contains_contracts_with(g, b, truth);
    }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    double v[32] = {};
    std::memcpy(v, data + 2, size - 2 < sizeof v ? size - 2 : sizeof v);
    bool finite = true;
    if ((data[0] & 0xc0) == 0xc0) { // a polygon in the plane
        const int kb = data[1] % 5;
        for (int i = 0; i < 12 + (kb == 4 ? 6 : (kb == 0 ? 2 : 4)); ++i) finite = finite && std::isfinite(v[i]);
        std::array<point2, 6> verts;
        for (unsigned i = 0; i < 6; ++i) verts[i] = point2{v[2 * i], v[2 * i + 1]};
        static constexpr std::array<std::uint32_t, 2> two_rings{{3, 6}};
        const polygon2 g{verts, (data[1] & 0x40) ? std::span<const std::uint32_t>(two_rings) : std::span<const std::uint32_t>()};
        if (kb == 4) {
            const std::array<point2, 3> tri{{{v[12], v[13]}, {v[14], v[15]}, {v[16], v[17]}}};
            check_polygon(g, polygon2{tri, {}}, finite);
        } else {
            with_shape2(kb, v + 12, [&](const auto& b) { check_polygon(g, b, finite); });
        }
        bool vertices_finite = true;
        for (int i = 0; i < 12; ++i) vertices_finite = vertices_finite && std::isfinite(v[i]);
        if (!vertices_finite) check_disk(v + 24, g, false);
        else if (oracle::polygon_simple(data_of(g))) check_disk(v + 24, g, true); // the oracle's even-odd set needs simple rings
        return 0;
    }
    if ((data[0] & 0xc0) == 0x40 && (data[1] & 0x80)) { // a planar polygon in space
        const int axis = data[0] % 3;
        const bool closed = (data[1] & 0x20) != 0;
        const int kb = closed ? data[1] % 8 : data[1] % 6, planes = 1 + (data[0] >> 2) % 4;
        for (int i = 0; i < 13; ++i) finite = finite && std::isfinite(v[i]);
        const int reads = !closed ? used[kb] : (kb == 3 ? 4 * planes : used_closed[kb]);
        for (int i = 0; i < reads; ++i) finite = finite && std::isfinite(v[13 + i]);
        const std::array<point3, 6> verts = planar_hexagon(v, axis);
        static constexpr std::array<std::uint32_t, 2> two_rings{{3, 6}};
        const std::span<const std::uint32_t> ends =
            (data[1] & 0x40) ? std::span<const std::uint32_t>(two_rings) : std::span<const std::uint32_t>();
        auto run = [&](const auto& b) {
            check_polygon3(verts, ends, axis, b, finite);
            std::array<point3, 6> bent = verts; // off the plane: unchecked, every tier finishes
            bent[data[1] % 6].x = v[(data[1] + 7) % 24];
            const polygon3 g{bent, ends, {0, 2, 4}, axis};
            (void)intersects<exact>(g, b);
            (void)intersects<approximate>(b, g);
            (void)classify(g, b);
        };
        if (closed) with_closed(kb, v + 13, planes, (data[1] >> 3) % 3, run);
        else with_shape(kb, v + 13, run);
        return 0;
    }
    if (data[0] & 0x80) { // in the plane
        const int ka = data[0] % 4, kb = data[1] % 4;
        for (int i = 0; i < used2[ka]; ++i) finite = finite && std::isfinite(v[i]);
        for (int i = 0; i < used2[kb]; ++i) finite = finite && std::isfinite(v[9 + i]);
        with_shape2(ka, v, [&](const auto& a) { with_shape2(kb, v + 9, [&](const auto& b) { check(a, b, finite); }); });
        bool a_finite = true; // a disk of doubles 20..22 against the first shape and the disk of doubles 23..25
        for (int i = 0; i < used2[ka]; ++i) a_finite = a_finite && std::isfinite(v[i]);
        with_shape2(ka, v, [&](const auto& a) { check_disk(v + 20, a, a_finite); });
        check_disk(v + 20, circle2{{v[23], v[24]}, v[25]}, std::isfinite(v[23]) && std::isfinite(v[24]) && std::isfinite(v[25]));
        return 0;
    }
    const int ka = data[0] % 6, kb = data[1] % 6;
    for (int i = 0; i < used[ka]; ++i) finite = finite && std::isfinite(v[i]);
    for (int i = 0; i < used[kb]; ++i) finite = finite && std::isfinite(v[9 + i]);
    with_shape(ka, v, [&](const auto& a) { with_shape(kb, v + 9, [&](const auto& b) { check(a, b, finite); }); });
    return 0;
}
