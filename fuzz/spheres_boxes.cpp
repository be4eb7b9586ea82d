// The sphere and box pairs: point_sphere, sphere_sphere (intersects, contains), aabb_point,
// aabb_aabb (intersects, contains, covers), aabb_ray, aabb_segment, aabb_line, aabb_plane and ray_sphere,
// differential against CGAL Epeck (the line against exact rational slabs) on raw bit patterns. Exact answers must match; conservative/aggressive/classify keep
// their contracts; both argument orders agree; exact t values of ray hits are correctly
// rounded. Every call must survive NaN, infinities and subnormals. And the batches: both
// boxes' and both spheres' points (the 16 doubles' points and their ulp neighbours), both boxes
// and both spheres against five boxes and five balls of the same doubles, the ray against those,
// and six rays of the same doubles against each box and ball, on a SIMD target the first byte
// picks, every lane equal to the scalar answer in every tier; and the ray's first hit among those
// boxes and balls (batches.hpp, first_hit_contracts). And a ball against half-spaces
// (frustum_sphere, convex_polyhedron_sphere, kdop_sphere) and against an oriented box (obb_sphere):
// a frustum, a polyhedron of 1 to 6 planes, a 14-DOP and a box of any (skew, flat) axes from the
// doubles, every tier on any bits, and the culling batch of five balls against the frustum (byte 3
// picks the target); on finite ones, one of the four (byte 2) against the exact QP (the squared
// distance to the set) and contains against the rows in rationals (the half-space sets). And a ball
// against a segment, a line, a plane, a triangle and a tetrahedron of the same doubles
// (segment_sphere, line_sphere, plane_sphere, sphere_triangle, sphere_tetrahedron), every tier on
// any bits, against CGAL's squared distance from the centre over Epeck on finite ones. And a capsule
// of the doubles against a point, a ball, a capsule, a segment, a ray, a line, a plane, a triangle, a
// tetrahedron, a box and an oriented box of them, every tier on any bits, one partner (byte 4) against the exact QP
// on finite ones. And a ball and a capsule against a polygon3 (four vertices at one height, unchecked
// on any bits; where make() accepts them, against the CGAL triangulation) and the closed mesh of
// the tetrahedron p q c e (polygon_sphere, capsule_polygon, mesh_sphere, capsule_mesh), against
// testkit/ball_view_truth.hpp's oracle on finite ones. And contains with a capsule: the capsule
// around a point, a segment, a triangle, a box, an oriented box (its corners in rationals), a ball and a capsule, a ball and the half-space
// set of byte 2 around it, against Epeck and rationals; and that capsule against that set, against
// the exact QP. And the signed and squared distance from a point to a ball, a capsule, a box, the
// oriented box, the three half-space sets, the tetrahedron and its mesh, every tier on any bits;
// on finite ones one solid's signed or squared distance (byte 5) against the exact value
// (testkit/oracle/cgal_distance.cpp). Any finding aborts.
#include "testkit/oracle/cgal_oracle.hpp"
#include "replay.hpp"
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <span>
import incidence;
import incidence.detail;
#include "contracts.hpp"
#include "batches.hpp"
#include "testkit/testing.hpp"
#include "testkit/flat_cases.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/flat_shapes.hpp"
#include "testkit/mesh_cases.hpp"
#include "testkit/polygon3_cases.hpp"
#include "testkit/ball_view_truth.hpp"
#include <array>
#include <cstdint>

using namespace incidence;

namespace {
void arr(point3 p, double* o) {
    o[0] = p.x;
    o[1] = p.y;
    o[2] = p.z;
}
// The closed mesh of a tetrahedron's four corners.
constexpr std::array<std::array<std::uint32_t, 3>, 4> tetrahedron_faces{{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
aabb3 ordered(point3 a, point3 b) {
    return {{std::fmin(a.x, b.x), std::fmin(a.y, b.y), std::fmin(a.z, b.z)},
            {std::fmax(a.x, b.x), std::fmax(a.y, b.y), std::fmax(a.z, b.z)}};
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    double v[16] = {};
    std::memcpy(v, data, size < sizeof v ? size : sizeof v);
    const point3 p{v[0], v[1], v[2]}, q{v[3], v[4], v[5]}, c{v[6], v[7], v[8]}, e{v[9], v[10], v[11]};
    const double r1 = v[12], r2 = v[13];
    const ray3 ray{p, vec3{v[3], v[4], v[5]}};
    const sphere3 s1{c, r1}, s2{e, r2};
    const aabb3 b1{c, e}, b2{p, q}; // unchecked: may be inverted or NaN
    {
        const point3 ps[11] = {p,
                               q,
                               c,
                               e,
                               {v[12], v[13], v[14]},
                               {v[15], v[0], v[6]},
                               {std::nextafter(p.x, 0.0), p.y, p.z},
                               {q.x, std::nextafter(q.y, 1.0), q.z},
                               {c.x + r1, c.y, c.z},
                               {e.x, e.y - r2, e.z},
                               {0, 0, 0}};
        const std::uint8_t pick = size > 0 ? data[0] : 0;
        batch_contracts(b1, std::span<const point3>(ps), pick);
        batch_contracts(b2, std::span<const point3>(ps), pick);
        batch_contracts(s1, std::span<const point3>(ps), pick);
        batch_contracts(s2, std::span<const point3>(ps), pick);
        // the solid batches: both boxes and both balls against boxes and balls built from the same doubles
        const aabb3 boxes[5] = {b1, b2, ordered(p, q), ordered(c, e), ordered(p, c)};
        const sphere3 balls[5] = {s1, s2, {p, r2}, {q, r1}, {c, std::fabs(r1) + std::fabs(r2)}};
        for (const aabb3& one : {b1, b2}) {
            batch_contracts(one, std::span<const aabb3>(boxes), pick);
            batch_contracts(one, std::span<const sphere3>(balls), pick);
        }
        for (const sphere3& one : {s1, s2}) {
            batch_contracts(one, std::span<const aabb3>(boxes), pick);
            batch_contracts(one, std::span<const sphere3>(balls), pick);
        }
        // the ray batches: the ray against the boxes and balls, and rays of the same doubles against each box and ball
        batch_contracts(ray, std::span<const aabb3>(boxes), pick);
        batch_contracts(ray, std::span<const sphere3>(balls), pick);
        first_hit_contracts(ray, std::span<const aabb3>(boxes));
        first_hit_contracts(ray, std::span<const sphere3>(balls));
        const ray3 rays[6] = {ray, {q, vec3{v[0], v[1], v[2]}}, {c, e - c}, {e, c - e}, {p, vec3{0, 0, 0}}, {q, vec3{v[12], v[13], v[14]}}};
        for (const aabb3& one : {b1, b2}) batch_contracts(one, std::span<const ray3>(rays), pick);
        for (const sphere3& one : {s1, s2}) batch_contracts(one, std::span<const ray3>(rays), pick);
    }
    // A ball against half-spaces: a frustum, a polyhedron of 1 to 6 planes (byte 1) and a 14-DOP
    // (each slab the two doubles i and i + 7 in order), every tier on any bits.
    frustum3 fr{};
    for (unsigned i = 0; i < 6; ++i)
        fr.planes[i] = plane3{{v[(4 * i) % 16], v[(4 * i + 1) % 16], v[(4 * i + 2) % 16]}, v[(4 * i + 3) % 16]};
    convex_polyhedron3 cp{};
    cp.count = size < 2 ? 1 : 1 + data[1] % 6;
    for (unsigned i = 0; i < static_cast<unsigned>(cp.count); ++i)
        cp.planes[i] = plane3{{v[(3 * i + 5) % 16], v[(3 * i + 6) % 16], v[(3 * i + 7) % 16]}, v[(5 * i + 2) % 16]};
    kdop<14> kd{};
    for (unsigned i = 0; i < 7; ++i) kd.min[i] = std::fmin(v[i], v[i + 7]), kd.max[i] = std::fmax(v[i], v[i + 7]);
    const obb3 ob{
        p, {vec3{v[3], v[4], v[5]}, vec3{v[9], v[10], v[11]}, vec3{v[13], v[14], v[15]}}, {std::fabs(v[12]), std::fabs(v[0]), v[7]}};
    {
        const sphere3 many[5] = {s1, s2, {p, r2}, {q, r1}, {c, std::fabs(r1) + std::fabs(r2)}};
        batch_contracts(fr, std::span<const sphere3>(many), size < 4 ? 0 : data[3]); // the culling batch
    }
    // a polygon (four vertices at one height, unchecked: make() may refuse them) and a mesh of the doubles
    const point3 quad[4] = {{v[0], v[1], v[2]}, {v[3], v[4], v[2]}, {v[9], v[10], v[2]}, {v[12], v[13], v[2]}};
    const polygon3 poly{quad, {}, {0, 1, 2}, 2};
    const point3 corners[4] = {p, q, c, e};
    const mesh3 tet{corners, tetrahedron_faces};
    for (const sphere3& s : {s1, s2}) {
        (void)intersects<approximate>(poly, s);
        (void)classify(s, tet);
        (void)intersects<conservative>(capsule3{p, e, s.radius}, poly);
        (void)intersects<aggressive>(tet, capsule3{q, {v[15], v[0], v[6]}, s.radius});
        (void)intersects<approximate>(fr, s);
        (void)intersects<conservative>(s, cp);
        (void)classify(kd, s);
        (void)contains<aggressive>(fr, s);
        (void)contains<approximate>(kd, s);
        (void)method::frustum_sphere_planes(fr, s);
        (void)intersects<approximate>(ob, s);
        (void)classify(s, ob);
        (void)intersects<approximate>(segment3{p, q}, s);
        (void)intersects<aggressive>(s, line3{q, vec3{v[0], v[1], v[2]}});
        (void)classify(plane3{vec3{v[9], v[10], v[11]}, v[15]}, s);
        (void)intersects<conservative>(s, triangle3{p, q, e});
        (void)intersects<approximate>(tetrahedron3{p, q, c, e}, s);
        const capsule3 cap{c, e, s.radius};
        (void)intersects<approximate>(cap, p);
        (void)intersects<conservative>(s, cap);
        (void)classify(cap, capsule3{p, q, r2});
        (void)intersects<aggressive>(segment3{p, q}, cap);
        (void)intersects<approximate>(cap, ray);
        (void)classify(cap, plane3{vec3{v[9], v[10], v[11]}, v[15]});
        (void)intersects<conservative>(triangle3{p, q, e}, cap);
        (void)intersects<aggressive>(cap, tetrahedron3{p, q, c, e});
        (void)intersects<approximate>(b1, cap);
        (void)classify(ob, cap);
        (void)contains<conservative>(cap, ob);
        (void)intersects<approximate>(cap, fr);
        (void)classify(cp, cap);
        (void)intersects<conservative>(cap, kd);
        (void)intersects<aggressive>(fr, cap);
    }
    // Every tier and every find must finish on any bits.
    (void)intersects<approximate>(ray, s1);
    (void)intersects<approximate>(b1, ray);
    (void)method::aabb_ray_woo(b1, ray);
    (void)method::ray_sphere_algebraic(ray, s1);
    (void)intersection(ray, s1);
    (void)intersection(b1, ray);
    (void)intersection<approximate>(b1, ray);
    (void)covers(b1, b2, b1);
    (void)squared_distance(b1, p);
    (void)max_squared_distance<conservative>(b1, p);
    (void)contains<aggressive>(s1, s2);
    const segment3 seg{p, q};
    const line3 line{p, vec3{v[3], v[4], v[5]}};
    (void)intersects<approximate>(b1, seg);
    (void)intersects<conservative>(seg, b1);
    (void)intersects<approximate>(line, b1);
    (void)intersects<aggressive>(b1, line);
    if (intersects(b1, seg) && !(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) && std::isfinite(v[3]) &&
                                 std::isfinite(v[4]) && std::isfinite(v[5])))
        std::abort();
    // the distances from a point to each solid of the doubles, every tier on any bits (a NaN or an
    // infinite number gives NaN, never a crash)
    const point3 far_point{v[12], v[13], v[14]};
    const auto distances = [&](const auto& solid, const point3& x) {
        (void)signed_distance(solid, x);
        (void)squared_distance<conservative>(x, solid);
    };
    for (const point3& x : {size % 2 == 0 ? p : far_point}) {
        distances(s1, x);
        distances(capsule3{c, e, r1}, x);
        distances(b1, x);
        distances(ob, x);
        distances(fr, x);
        distances(cp, x);
        distances(kd, x);
        distances(tetrahedron3{p, q, c, e}, x);
        distances(tet, x);
        (void)signed_distance<approximate>(x, tet);
        (void)signed_distance<aggressive>(cp, x);
    }
    bool finite = true;
    for (double x : v) finite = finite && std::isfinite(x);
    if (!finite) return 0;
    double P[3], Q[3], C[3], E[3];
    arr(p, P);
    arr(q, Q);
    arr(c, C);
    arr(e, E);
    // balls need r >= 0 (a checked make() refuses negative radii)
    const sphere3 a{c, std::fabs(r1)}, b{e, std::fabs(r2)};
    contracts(p, a, oracle::point_in_ball(P, C, a.radius));
    contracts(a, b, oracle::ball_ball(C, a.radius, E, b.radius));
    if (contains(a, b) != oracle::ball_contains_ball(C, a.radius, E, b.radius)) std::abort();
    // the ball against the flat shapes and the tetrahedron of the same doubles
    {
        const auto flat = [&](const auto& x) {
            for (const sphere3& s : {s1, a}) contracts(x, s, oracle::ball_flat(support::to_flat(x), support::a3(s.center), s.radius));
        };
        flat(segment3{p, q});
        flat(line3{p, vec3{v[3], v[4], v[5]}});
        flat(plane3{vec3{v[9], v[10], v[11]}, v[15]});
        flat(triangle3{p, q, e});
        flat(tetrahedron3{p, q, c, e});
    }
    // a capsule against one partner (byte 4): the exact QP between its segment and the partner's core
    {
        const capsule3 cap{c, e, std::fabs(r1)};
        const auto axis = support::lp(segment3{c, e});
        const auto within = [&](const auto& x, const oracle::convex_set& core, double r) {
            if (const auto t = oracle::qp_sets_within(axis, core, cap.radius, r)) contracts(cap, x, *t);
        };
        switch (size < 5 ? 0 : data[4] % 11) {
        case 0: within(p, support::lp(p), 0); break;
        case 1: within(sphere3{p, std::fabs(r2)}, support::lp(p), std::fabs(r2)); break;
        case 2: within(capsule3{p, q, std::fabs(r2)}, support::lp(segment3{p, q}), std::fabs(r2)); break;
        case 3: within(segment3{p, q}, support::lp(segment3{p, q}), 0); break;
        case 4: within(ray, support::lp(ray), 0); break;
        case 5: within(line, support::lp(line), 0); break;
        case 6:
            if (!(vec3{v[9], v[10], v[11]} == vec3{0, 0, 0}))
                within(plane3{vec3{v[9], v[10], v[11]}, v[15]}, support::lp(plane3{vec3{v[9], v[10], v[11]}, v[15]}), 0);
            break;
        case 7: within(triangle3{p, q, e}, support::lp(triangle3{p, q, e}), 0); break;
        case 8: within(tetrahedron3{p, q, c, e}, support::lp(tetrahedron3{p, q, c, e}), 0); break;
        case 9: within(ordered(p, q), support::lp(ordered(p, q)), 0); break;
        default:
            if (std::isfinite(ob.half_extents[2]) && ob.half_extents[2] >= 0) within(ob, support::lp(ob), 0);
            break;
        }
    }
    // a ball and a capsule against the polygon (where make() accepts it) and the tetrahedron's mesh
    {
        const point3 far{v[12], v[13], v[14]};
        const sphere3 ball{far, std::fabs(r1)};
        const capsule3 cap{far, {v[15], v[0], v[6]}, std::fabs(r2)};
        const auto made = polygon3::make(quad);
        if (made.has_value()) {
            if (const auto t = support::round_polygon_truth(made.value(), ball)) contracts(made.value(), ball, *t);
            if (const auto t = support::round_polygon_truth(made.value(), cap)) contracts(cap, made.value(), *t);
        }
        if (const auto t = support::round_mesh_truth(tet, ball)) contracts(tet, ball, *t);
        if (const auto t = support::round_mesh_truth(tet, cap)) contracts(cap, tet, *t);
    }
    // containment with a capsule: around a point, a segment, a triangle and a box (every vertex
    // within its radius of its segment), around a ball and a capsule (their centres within the
    // radii's difference), over Epeck; a ball around the capsule (both end balls, in rationals)
    {
        const capsule3 cap{c, e, std::fabs(r1)};
        const auto axis = support::to_flat(segment3{c, e});
        const auto held = [&](point3 x) { return oracle::ball_flat(axis, support::a3(x), cap.radius); };
        const auto ball_held = [&](point3 x, double r) { return oracle::flat_holds_ball(axis, support::a3(x), cap.radius, r); };
        contains_contracts_with(cap, p, held(p));
        contains_contracts_with(cap, segment3{p, q}, held(p) && held(q));
        contains_contracts_with(cap, triangle3{p, q, {v[12], v[13], v[14]}}, held(p) && held(q) && held({v[12], v[13], v[14]}));
        const aabb3 pq = ordered(p, q);
        bool box_held = true;
        for (int m = 0; m < 8; ++m)
            box_held = box_held && held({(m & 1) ? pq.max.x : pq.min.x, (m & 2) ? pq.max.y : pq.min.y, (m & 4) ? pq.max.z : pq.min.z});
        contains_contracts_with(cap, pq, box_held);
        if (std::isfinite(ob.half_extents[2]) && ob.half_extents[2] >= 0) {
            double oc[3], oa[9];
            arr(ob.center, oc);
            for (unsigned i = 0; i < 3; ++i) oa[3 * i] = ob.axes[i].x, oa[3 * i + 1] = ob.axes[i].y, oa[3 * i + 2] = ob.axes[i].z;
            contains_contracts_with(cap, ob, oracle::box_in_capsule(oc, oa, ob.half_extents.data(), C, E, cap.radius));
        }
        contains_contracts_with(cap, sphere3{p, r2}, ball_held(p, r2));
        contains_contracts_with(cap, capsule3{p, q, r2}, ball_held(p, r2) && ball_held(q, r2));
        const double around = std::fabs(r2);
        contains_contracts_with(sphere3{p, r2}, cap,
                                oracle::ball_contains_ball(P, around, C, cap.radius) &&
                                    oracle::ball_contains_ball(P, around, E, cap.radius));
    }
    // the ball against the half-spaces: the exact QP (one set per input, byte 2), the rows in rationals
    {
        const capsule3 cap{c, e, std::fabs(r1)};
        const auto ball = [&](const auto& set) {
            const auto rows = support::lp(set);
            for (const sphere3& s : {s1, a}) {
                if (const auto t = oracle::qp_ball_meets(rows, support::a3(s.center), s.radius)) contracts(set, s, *t);
                contains_contracts_with(set, s, oracle::ball_in_rows(rows, support::a3(s.center), s.radius));
            }
            contains_contracts_with(
                set, cap, oracle::ball_in_rows(rows, support::a3(c), cap.radius) && oracle::ball_in_rows(rows, support::a3(e), cap.radius));
            if (const auto t = oracle::qp_sets_within(support::lp(segment3{c, e}), rows, cap.radius)) contracts(cap, set, *t);
        };
        switch (size < 3 ? 0 : data[2] % 4) {
        case 0: ball(fr); break;
        case 1: ball(cp); break;
        case 2: ball(kd); break;
        default:
            for (const sphere3& s : {s1, a})
                if (const auto t = oracle::qp_ball_meets(support::lp(ob), support::a3(s.center), s.radius)) contracts(ob, s, *t);
        }
    }
    // one solid's signed or squared distance (byte 5) against the exact value: correctly rounded,
    // enclosed (one oracle call per input: the QP is most of a run's time)
    {
        const std::uint8_t pick = size < 6 ? 0 : data[5];
        const bool squared = (pick / 9) % 2 == 1;
        const auto check = [&](const auto& solid, const oracle::distance_solid& truth, const point3& x) {
            const double d = squared ? squared_distance(solid, x) : signed_distance(solid, x);
            const interval i = squared ? squared_distance<conservative>(solid, x) : signed_distance<aggressive>(solid, x);
            const auto k = oracle::check_distance(truth, support::a3(x), squared, d, i.lo, i.hi, d);
            if (k.known && (!k.rounded || !k.enclosed)) std::abort();
        };
        const oracle::mesh_data tet_data{{support::a3(p), support::a3(q), support::a3(c), support::a3(e)},
                                         {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
        switch (pick % 9) {
        case 0: check(s1, {oracle::distance_solid::capsule, {C[0], C[1], C[2], C[0], C[1], C[2], r1}, {}}, far_point); break;
        case 1: check(capsule3{c, e, r1}, {oracle::distance_solid::capsule, {C[0], C[1], C[2], E[0], E[1], E[2], r1}, {}}, p); break;
        case 2: check(fr, {oracle::distance_solid::rows, {}, support::lp(fr)}, p); break;
        case 3: check(cp, {oracle::distance_solid::rows, {}, support::lp(cp)}, q); break;
        case 4: check(kd, {oracle::distance_solid::rows, {}, support::lp(kd)}, p); break;
        case 5:
            check(tetrahedron3{p, q, c, e},
                  {oracle::distance_solid::tetrahedron, {P[0], P[1], P[2], Q[0], Q[1], Q[2], C[0], C[1], C[2], E[0], E[1], E[2]}, {}},
                  far_point);
            break;
        case 6: check(ordered(c, e), {oracle::distance_solid::rows, {}, support::lp(ordered(c, e))}, p); break;
        case 7:
            if (std::isfinite(ob.half_extents[2]) && ob.half_extents[2] >= 0)
                check(ob, {oracle::distance_solid::rows, {}, support::lp(ob)}, q);
            break;
        default: {
            oracle::distance_solid truth{oracle::distance_solid::mesh, {}, {}};
            truth.mesh_ptr = &tet_data;
            if (detail::solid_mesh::well_formed(tet)) check(tet, truth, far_point);
        }
        }
    }
    const aabb3 box = ordered(c, e), other = ordered(p, q);
    double mn[3], mx[3], omn[3], omx[3];
    arr(box.min, mn);
    arr(box.max, mx);
    arr(other.min, omn);
    arr(other.max, omx);
    contracts(box, p, oracle::point_in_box(P, mn, mx));
    contracts(box, other, oracle::box_box(mn, mx, omn, omx));
    if (contains(box, other) != oracle::box_contains_box(mn, mx, omn, omx)) std::abort();
    if (!oracle::is_rounded_point_box_sqdist(P, mn, mx, false, squared_distance(box, p)) && std::isfinite(squared_distance(box, p)))
        std::abort();
    contracts(box, seg, oracle::box_segment(mn, mx, P, Q));
    if (!(ray.direction == vec3{0, 0, 0})) contracts(box, plane3{ray.direction, r1}, oracle::box_plane(mn, mx, Q, r1));
    if (!(ray.direction == vec3{0, 0, 0})) {
        contracts(box, line, oracle::box_line(mn, mx, P, Q));
        contracts(box, ray, oracle::ray_box(P, Q, mn, mx));
        contracts(ray, a, oracle::ray_ball(P, Q, C, a.radius));
        if (const auto h = intersection(box, ray); h && !oracle::is_rounded_ray_box_t(P, Q, mn, mx, h->t_enter, h->t_exit)) std::abort();
        if (const auto h = intersection(ray, a); h && !oracle::is_rounded_ray_ball_t(P, Q, C, a.radius, h->t_enter)) std::abort();
    }
    return 0;
}
