// The OBB pairs (the separating-axis family): obb_point, aabb_obb, obb_obb, obb_segment, obb_ray,
// line_obb, obb_triangle and obb_plane, differential against the exact LP oracle on raw bit
// patterns, with the axes taken from the bits (any parallelepiped, flat or degenerate) or a unit
// frame. Exact answers must match; conservative/aggressive/classify keep their contracts; both
// argument orders agree. Every call must survive NaN, infinities, subnormals and negative
// extents. The k-DOP pairs too (kdop_point, kdop_segment, kdop_ray, kdop_line, kdop_plane, kdop_kdop with the
// same K and with a 14-DOP, aabb_kdop, contains(kdop, aabb | segment); K from byte 0 % 4,
// bounds from the same doubles, so inverted or jointly empty slabs occur), against the same LP
// with the k-DOP as its slab rows. The half-space pairs too (convex_polyhedron_point, _segment,
// _ray, _line with 1 to 6 planes from the same doubles, so empty, flat and unbounded sets occur;
// frustum_point, _segment, _ray, _line with six; aabb_convex_polyhedron and aabb_frustum;
// convex_polyhedron_plane and frustum_plane; convex_polyhedron_convex_polyhedron,
// convex_polyhedron_frustum, convex_polyhedron_kdop, frustum_kdop and frustum_frustum;
// convex_polyhedron_triangle, frustum_triangle and kdop_triangle; convex_polyhedron_tetrahedron,
// frustum_tetrahedron and kdop_tetrahedron; convex_polyhedron_obb, frustum_obb and kdop_obb;
// contains(., point | segment | triangle | tetrahedron | box | oriented box)), against the LP with the half-spaces as rows
// (an oriented box's containment: its corners in exact rationals). And the culling batch: ten
// boxes from the doubles against the frustum (batches.hpp: every lane the scalar answer in every
// tier, on a SIMD target byte 0 picks), and six oriented boxes (byte 1 picks the target and one
// tier), the six against the box p q or its ordered copy (byte 3; byte 2 picks the target and one
// tier), and the six against a ball (byte 4; byte 5 picks the target and one tier). Any finding
// aborts.
#include "testkit/oracle/cgal_oracle.hpp"
#include "replay.hpp"
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
import incidence;
import incidence.detail;
#include "contracts.hpp"
#include "batches.hpp"
#include "testkit/lp_shapes.hpp"

using namespace incidence;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    double v[24] = {};
    std::memcpy(v, data, size < sizeof v ? size : sizeof v);
    const bool unit_frame = size == 0 || (data[size - 1] & 1) == 0;
    const point3 p{v[0], v[1], v[2]}, q{v[3], v[4], v[5]}, c{v[6], v[7], v[8]};
    const vec3 d{v[3], v[4], v[5]};
    const std::array<vec3, 3> unit{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
    const std::array<vec3, 3> bits{vec3{v[9], v[10], v[11]}, vec3{v[12], v[13], v[14]}, vec3{v[15], v[16], v[17]}};
    const obb3 o{c, unit_frame ? unit : bits, {v[18], v[19], v[20]}}; // unchecked: anything goes
    const obb3 o2{p, unit_frame ? bits : unit, {v[21], v[22], v[23]}};
    const segment3 seg{p, q};
    const ray3 ray{p, d};
    const line3 line{p, d};
    const triangle3 tri{p, q, point3{v[12], v[13], v[14]}};
    const tetrahedron3 tet{p, q, point3{v[12], v[13], v[14]}, point3{v[15], v[16], v[17]}};
    const aabb3 box{p, q}; // may be inverted: empty
    const plane3 pl{d, v[21]};
    // Every tier must finish on any bits.
    (void)intersects<approximate>(o, o2);
    (void)intersects<conservative>(o, seg);
    (void)intersects<aggressive>(line, o);
    (void)intersects<approximate>(o, tri);
    (void)classify(o, pl);
    (void)method::obb_obb_gottschalk(o, o2);
    {
        kdop<26> kd{};
        for (unsigned i = 0; i < 13; ++i) kd.min[i] = v[i], kd.max[i] = v[i + 11];
        (void)intersects<approximate>(kd, seg);
        (void)intersects<conservative>(ray, kd);
        (void)intersects<aggressive>(kd, line);
        (void)intersects<exact>(kd, p);
        (void)classify(kd, ray);
        (void)intersects<exact>(kd, kd);
        (void)intersects<conservative>(box, kd);
        (void)contains<aggressive>(kd, box);
        (void)intersects<approximate>(pl, kd);
        const frustum3 fr{{plane3{{v[0], v[1], v[2]}, v[3]}, plane3{{v[4], v[5], v[6]}, v[7]}, plane3{{v[8], v[9], v[10]}, v[11]},
                           plane3{{v[12], v[13], v[14]}, v[15]}, plane3{{v[16], v[17], v[18]}, v[19]},
                           plane3{{v[20], v[21], v[22]}, v[23]}}};
        convex_polyhedron3 cp{};
        cp.count = size == 0 ? 0 : data[0] % 40 - 4; // outside [0, 32] too: no set
        for (unsigned i = 0; i < 32; ++i) cp.planes[i] = plane3{{v[i % 24], v[(i + 1) % 24], v[(i + 2) % 24]}, v[(i + 3) % 24]};
        (void)intersects<approximate>(fr, seg);
        (void)intersects<conservative>(ray, fr);
        (void)classify(fr, line);
        (void)contains<aggressive>(fr, seg);
        (void)intersects<exact>(cp, p);
        (void)intersects<aggressive>(line, cp);
        (void)classify(cp, ray);
        (void)contains<approximate>(cp, seg);
        (void)intersects<exact>(box, cp);
        (void)intersects<conservative>(fr, box);
        (void)classify(box, fr);
        (void)contains<approximate>(fr, box);
        (void)contains<aggressive>(cp, box);
        (void)intersects<exact>(cp, pl);
        (void)intersects<approximate>(pl, fr);
        (void)classify(cp, pl);
        (void)intersects<aggressive>(fr, pl);
        (void)intersects<exact>(cp, cp);
        (void)intersects<conservative>(fr, cp);
        (void)classify(cp, fr);
        (void)intersects<approximate>(fr, fr);
        (void)intersects<aggressive>(tri, cp);
        (void)classify(fr, tri);
        (void)contains<conservative>(cp, tri);
    }
    for (double x : v)
        if (!std::isfinite(x)) return 0;
    // The oracle needs ordered numbers: extents as magnitudes (a negative extent is an empty box,
    // which the LP's bounds would also say, but the oracle's inputs stay in its domain).
    const obb3 w{o.center, o.axes, {std::fabs(v[18]), std::fabs(v[19]), std::fabs(v[20])}};
    const obb3 w2{o2.center, o2.axes, {std::fabs(v[21]), std::fabs(v[22]), std::fabs(v[23])}};
    // The oracle's answer counts once CGAL's certificate check accepts it (it declines some inputs
    // spanning the whole exponent range at once; those cases only check that nothing crashes).
    auto check = [](const auto& a, const auto& b) {
        if (const auto t = oracle::lp_intersect_verified(support::lp(a), support::lp(b))) contracts(a, b, *t);
    };
    check(w, p);
    check(w, w2);
    // an inverted box is empty: no LP (its bounds would be out of order), the library says no
    if (box.min.x <= box.max.x && box.min.y <= box.max.y && box.min.z <= box.max.z) check(box, w);
    else if (intersects(box, w)) std::abort();
    check(w, seg);
    check(w, ray);
    check(line, w);
    check(w, tri);
    check(w, pl);
    // 1 to 6 planes (from byte 1), and a frustum of six, from the doubles.
    convex_polyhedron3 cp{};
    cp.count = size < 2 ? 1 : 1 + data[1] % 6;
    for (unsigned i = 0; i < static_cast<unsigned>(cp.count); ++i)
        cp.planes[i] = plane3{{v[(4 * i + 6) % 24], v[(4 * i + 7) % 24], v[(4 * i + 8) % 24]}, v[(4 * i + 9) % 24]};
    frustum3 fr{};
    for (unsigned i = 0; i < 6; ++i) fr.planes[i] = plane3{{v[(4 * i + 1) % 24], v[(4 * i + 2) % 24], v[(4 * i + 3) % 24]}, v[4 * i % 24]};
    // The k-DOP pairs (the slab family): K from byte 0, bounds from the doubles (maybe inverted or
    // jointly empty, both of which the LP's slab rows express exactly).
    auto kdops = [&]<int K>() {
        kdop<K> kd{};
        for (unsigned i = 0; i < K / 2; ++i) kd.min[i] = v[i % 24], kd.max[i] = v[(i + 13) % 24];
        check(kd, p);
        check(kd, seg);
        check(kd, ray);
        check(kd, line);
        check(kd, pl);
        check(kd, tri);
        if (contains(kd, tri) != (intersects(kd, tri.a) && intersects(kd, tri.b) && intersects(kd, tri.c))) std::abort();
        check(kd, tet);
        if (contains(kd, tet) != (intersects(kd, tet.a) && intersects(kd, tet.b) && intersects(kd, tet.c) && intersects(kd, tet.d)))
            std::abort();
        if (contains(kd, p) != intersects(kd, p)) std::abort();
        // two k-DOPs (the same K, and a 14-DOP), a box: slab overlap and the Farkas certificates
        kdop<K> kd2{};
        for (unsigned i = 0; i < K / 2; ++i) kd2.min[i] = v[(i + 5) % 24], kd2.max[i] = v[(i + 19) % 24];
        kdop<14> kd14{};
        for (unsigned i = 0; i < 7; ++i) kd14.min[i] = v[(i + 3) % 24], kd14.max[i] = v[(i + 16) % 24];
        check(kd, kd2);
        check(kd14, kd);
        // a half-space set against the k-DOP (its slab rows): the polyhedron of 1 to 6 planes, the frustum
        check(cp, kd);
        check(kd, fr);
        if (box.min.x <= box.max.x && box.min.y <= box.max.y && box.min.z <= box.max.z) {
            check(box, kd);
            bool all = true;
            for (int j = 0; j < 8; ++j) all = all && intersects(kd, point3{(j & 1) ? q.x : p.x, (j & 2) ? q.y : p.y, (j & 4) ? q.z : p.z});
            if (contains(kd, box) != all) std::abort();
        }
        if (contains(kd, seg) != (intersects(kd, seg.a) && intersects(kd, seg.b))) std::abort();
        check(kd, w); // the box's own frame, then the vertex search
        if (contains(kd, w) != support::contained_truth(kd, w)) std::abort();
    };
    // The half-space pairs, on cp and fr above.
    auto halfspaces = [&](const auto& h) {
        check(h, p);
        check(h, seg);
        check(h, ray);
        check(h, line);
        check(h, pl);  // the feasibility test of possibly unbounded sets
        check(h, tri); // the triangle's edges, then the set's edges across its plane
        if (contains(h, tri) != (intersects(h, tri.a) && intersects(h, tri.b) && intersects(h, tri.c))) std::abort();
        check(h, tet); // its faces, then a vertex of the set inside it
        if (contains(h, tet) != (intersects(h, tet.a) && intersects(h, tet.b) && intersects(h, tet.c) && intersects(h, tet.d)))
            std::abort();
        if (contains(h, p) != intersects(h, p)) std::abort();
        if (contains(h, seg) != (intersects(h, seg.a) && intersects(h, seg.b))) std::abort();
        if (box.min.x <= box.max.x && box.min.y <= box.max.y && box.min.z <= box.max.z) { // the vertex test
            check(box, h);
            bool all = true;
            for (int j = 0; j < 8; ++j) all = intersects(h, point3{(j & 1) ? q.x : p.x, (j & 2) ? q.y : p.y, (j & 4) ? q.z : p.z}) && all;
            if (contains(h, box) != all) std::abort();
        } else if (intersects(box, h)) std::abort();
        check(h, w); // the box's own frame, then the vertex search
        if (contains(h, w) != support::contained_truth(h, w)) std::abort();
    };
    {
        halfspaces(cp);
        halfspaces(fr);
        // the culling batch: seven boxes of consecutive doubles (maybe inverted), p alone, p q ordered, q p
        std::array<aabb3, 10> boxes{};
        for (unsigned i = 0; i < 7; ++i) {
            const unsigned k = 3 * i;
            boxes[i] = aabb3{{v[k], v[k + 1], v[k + 2]}, {v[(k + 3) % 24], v[(k + 4) % 24], v[(k + 5) % 24]}};
        }
        boxes[7] = aabb3{p, p};
        boxes[8] = aabb3{{std::fmin(p.x, q.x), std::fmin(p.y, q.y), std::fmin(p.z, q.z)},
                         {std::fmax(p.x, q.x), std::fmax(p.y, q.y), std::fmax(p.z, q.z)}};
        boxes[9] = aabb3{q, p};
        batch_contracts(fr, std::span<const aabb3>(boxes), size == 0 ? 0 : data[0]);
        // and oriented boxes: o, o2, w, w2 (the extents made non-negative) and two of o's frame about p and q
        const obb3 obbs[6] = {o, o2, w, w2, obb3{p, o.axes, w.half_extents}, obb3{q, o2.axes, w2.half_extents}};
        batch_contracts_one_tier(fr, std::span<const obb3>(obbs), size < 2 ? 0 : data[1]);
        // the same against one box: box (maybe inverted) or p q ordered, byte 3 says which
        batch_contracts_one_tier(size < 4 || data[3] % 2 == 0 ? box : boxes[8], std::span<const obb3>(obbs), size < 3 ? 0 : data[2]);
        // and against one ball: centre c and radius v[9], or centre p and radius v[10] (byte 4 says
        // which; byte 5 picks the target and one tier)
        const sphere3 ball = size < 5 || data[4] % 2 == 0 ? sphere3{c, v[9]} : sphere3{p, v[10]};
        batch_contracts_one_tier(ball, std::span<const obb3>(obbs), size < 6 ? 0 : data[5]);
        (void)method::frustum_obb_sat(fr, o);
        (void)method::frustum_obb_decomposition(fr, o);
        // two half-space sets: a second polyhedron of 1 to 6 planes from other doubles (byte 2)
        convex_polyhedron3 cp2{};
        cp2.count = size < 3 ? 1 : 1 + data[2] % 6;
        for (unsigned i = 0; i < static_cast<unsigned>(cp2.count); ++i)
            cp2.planes[i] = plane3{{v[(4 * i + 13) % 24], v[(4 * i + 14) % 24], v[(4 * i + 15) % 24]}, v[(4 * i + 3) % 24]};
        check(cp, cp2);
        check(cp2, fr);
        // a second frustum: the planes of fr in another order of the doubles
        frustum3 fr2{};
        for (unsigned i = 0; i < 6; ++i)
            fr2.planes[i] = plane3{{v[(4 * i + 5) % 24], v[(4 * i + 22) % 24], v[(4 * i + 11) % 24]}, v[(4 * i + 2) % 24]};
        check(fr, fr2);
    }
    switch (size == 0 ? 0 : data[0] % 4) {
    case 0: kdops.template operator()<6>(); break;
    case 1: kdops.template operator()<14>(); break;
    case 2: kdops.template operator()<18>(); break;
    default: kdops.template operator()<26>(); break;
    }
    // A negative extent is the empty box.
    if (intersects(obb3{w.center, w.axes, {-1.0, w.half_extents[1], w.half_extents[2]}}, p)) std::abort();
    return 0;
}
