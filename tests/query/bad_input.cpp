// Unchecked queries on NaN, infinite, huge, subnormal and zero-size inputs must finish without
// crashing and without undefined behaviour (this file runs under ASan + UBSan in the suite), and
// keep the tiers' promises on every input: aggressive => exact => conservative, classify never
// contradicts exact, intersection() has a hit exactly where intersects() says yes. The exact tier
// reports no intersection when an input is NaN or infinite, and classify answers uncertain.
#include <catch2/catch_test_macros.hpp>
#include <bit>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <typeinfo>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/mesh_fixtures.hpp"
#include "testkit/polygon_fixtures.hpp"

namespace test_query_bad_input { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
constexpr double nan_ = std::numeric_limits<double>::quiet_NaN();
constexpr double inf_ = std::numeric_limits<double>::infinity();
double special(support::rng& r) {
    static constexpr double values[] = {
        0.0,  -0.0, 1.0,   -1.0,     0x1p-1074, -0x1p-1074, 0x1p-1022, 0x1.fffffffffffffp1023, -0x1.fffffffffffffp1023,
        nan_, inf_, -inf_, 0x1p-537, 0x1p511};
    const int k = r.integer(0, 16);
    if (k < 14) return values[k];
    return std::bit_cast<double>(r.bits()); // raw bits: any NaN payload, subnormal, huge
}
std::string described(point3 p) {
    char b[96];
    std::snprintf(b, sizeof b, "(%a, %a, %a)", p.x, p.y, p.z);
    return b;
}
std::string described(vec3 v) { return described(point3{v.x, v.y, v.z}); }
template <class S>
std::string described(const S& s) {
    std::string out = typeid(S).name();
    if constexpr (requires {
                      s.origin;
                      s.direction;
                  })
        out += " " + described(s.origin) + described(s.direction);
    if constexpr (requires {
                      s.a;
                      s.b;
                  })
        out += " " + described(s.a) + described(s.b);
    if constexpr (requires { s.c; }) out += described(s.c);
    if constexpr (requires {
                      s.min;
                      s.max;
                  })
        out += " " + described(s.min) + described(s.max);
    if constexpr (requires {
                      s.center;
                      s.radius;
                  })
        out += " " + described(s.center) + " r " + std::to_string(s.radius);
    return out;
}
// Whether the shape is a point set: a polygon3 whose vertices are not coplanar is none (its queries
// answer for a procedure, shapes/polygon3.cppm), so intersects and intersection need not agree on it.
template <class S>
bool a_set(const S&) {
    return true;
}
bool a_set(const polygon3& g) {
    const auto made = polygon3::make(g.vertices, g.ring_ends);
    return made.has_value() || made.error().code != errc::non_planar_polygon;
}
// On every input, whatever it is: aggressive => exact => conservative, and classify never
// contradicts exact (yes => exact yes, no => exact no). Broken promises are counted here.
long contract_broken = 0;
void promise(bool agg, bool ex, bool con, certainty c, const char* what) {
    const bool ok = (!agg || ex) && (!ex || con) && (c != certainty::yes || ex) && (c != certainty::no || !ex);
    if (!ok && ++contract_broken <= 5)
        std::printf("  %s: aggressive %d, exact %d, conservative %d, classify %d\n", what, agg, ex, con, static_cast<int>(c));
}
template <class A, class B>
void every_tier(const A& a, const B& b, long& yes) {
    const bool ex = intersects<exact>(a, b), con = intersects<conservative>(a, b), agg = intersects<aggressive>(a, b);
    const certainty c = classify(a, b);
    promise(agg, ex, con, c, "intersects");
    yes += ex + con + agg + intersects<approximate>(a, b) + (c == certainty::uncertain);
    if constexpr (requires { intersection(a, b); }) { // the values: a hit in aggressive => in exact => in conservative
        const bool he = intersection<exact>(a, b).has_value(), hc = intersection<conservative>(a, b).has_value();
        const bool ha = intersection<aggressive>(a, b).has_value();
        (void)intersection<approximate>(a, b);
        promise(ha, he, hc, certainty::uncertain, "intersection");
        if (he != ex && a_set(a) && a_set(b) && ++contract_broken <= 5)
            std::printf("  intersection %d, intersects %d: %s %s\n", he, ex, described(a).c_str(), described(b).c_str());
    }
}
template <class A, class B>
void every_contains(const A& a, const B& b, long& yes) {
    const bool ex = contains<exact>(a, b), con = contains<conservative>(a, b), agg = contains<aggressive>(a, b);
    const certainty c = classify_contains(a, b);
    promise(agg, ex, con, c, "contains");
    yes += ex + con + agg + contains<approximate>(a, b) + (c == certainty::uncertain);
}
} // namespace

TEST_CASE("bad input: unchecked queries survive NaN, infinities, subnormals and extremes", "[bad_input]") {
    support::rng r(support::seed());
    long yes = 0, n = 0;
    auto p = [&] { return point3{special(r), special(r), special(r)}; };
    auto v = [&] { return vec3{special(r), special(r), special(r)}; };
    for (long i = 0; i < support::cases(3000); ++i) {
        const ray3 ray{p(), v()};
        const triangle3 t{p(), p(), p()};
        const sphere3 s{p(), special(r)};
        const aabb3 b{p(), p()};
        const segment3 seg{p(), p()};
        every_tier(ray, t, yes);
        every_tier(seg, t, yes);
        every_tier(ray, s, yes);
        every_tier(b, ray, yes);
        every_tier(p(), s, yes);
        every_tier(s, s, yes);
        every_tier(b, p(), yes);
        every_tier(b, b, yes);
        yes += contains(s, s) + contains(b, b) + covers(b, b, b);
        yes += intersection(ray, t).has_value() + intersection(ray, s).has_value() + intersection(b, ray).has_value();
        yes += intersection<approximate>(ray, t).has_value() + intersection<approximate>(ray, s).has_value();
        yes += static_cast<long>(std::isnan(squared_distance(b, p())) + std::isnan(max_squared_distance<approximate>(b, p())));
        yes += orient3d(p(), p(), p(), p()) == sign::zero;
        yes += insphere(p(), p(), p(), p(), p()) == sign::zero;
        n += 30;
        // the flat pairs: every combination of point, line, ray, segment, plane and triangle
        const line3 line{p(), v()};
        const plane3 pl{v(), special(r)};
        const point3 q = p();
        every_tier(seg, seg, yes);
        every_tier(ray, ray, yes);
        every_tier(line, line, yes);
        every_tier(line, ray, yes);
        every_tier(seg, line, yes);
        every_tier(ray, seg, yes);
        every_tier(q, q, yes);
        every_tier(q, line, yes);
        every_tier(ray, q, yes);
        every_tier(q, seg, yes);
        every_tier(q, t, yes);
        every_tier(line, t, yes);
        every_tier(pl, q, yes);
        every_tier(line, pl, yes);
        every_tier(pl, ray, yes);
        every_tier(pl, pl, yes);
        n += 16 * 5;
        // the tetrahedron pairs, and containment
        const tetrahedron3 te{p(), p(), p(), p()};
        const obb3 ob{p(), {v(), v(), v()}, {special(r), special(r), special(r)}};
        every_tier(q, te, yes);
        every_tier(seg, te, yes);
        every_tier(te, ray, yes);
        every_tier(line, te, yes);
        every_tier(pl, te, yes);
        every_tier(te, t, yes);
        every_tier(te, te, yes);
        every_tier(b, te, yes);
        every_tier(ob, te, yes);
        yes += contains(te, q) + contains(te, seg) + contains(te, t) + contains(te, te) + contains(te, b) + contains(b, te);
        yes += contains<approximate>(te, te) + contains<conservative>(te, b) + contains<aggressive>(b, te);
        n += 9 * 5 + 9;
        // the boxes' and the ball's containment
        const sphere3 ball{p(), special(r)};
        every_tier(b, ball, yes);
        every_contains(ob, q, yes);
        every_contains(ob, seg, yes);
        every_contains(ob, t, yes);
        every_contains(ob, te, yes);
        every_contains(ob, b, yes);
        every_contains(b, ob, yes);
        every_contains(ob, ob, yes);
        every_contains(b, seg, yes);
        every_contains(b, t, yes);
        every_contains(b, ball, yes);
        every_contains(ball, b, yes);
        every_contains(ob, ball, yes);
        every_contains(ball, ob, yes);
        every_contains(te, ob, yes);
        n += 15 * 5;
        // the mesh pairs: special vertices on the cube's triangles, and a triangle naming a vertex
        // that does not exist
        std::array<point3, 8> mv;
        for (auto& x : mv) x = p();
        const mesh3 me{mv, support::cube_triangles};
        const mesh3 holey{std::span<const point3>(mv.data(), 5), support::cube_triangles};
        every_tier(me, q, yes);
        every_tier(me, seg, yes);
        every_tier(me, ray, yes);
        every_tier(line, me, yes);
        every_tier(me, pl, yes);
        every_tier(me, t, yes);
        every_tier(me, te, yes);
        every_tier(b, me, yes);
        every_tier(me, ob, yes);
        every_tier(me, me, yes);
        every_tier(holey, q, yes);
        yes += contains(me, q) + contains(holey, q);
        every_contains(me, b, yes);
        every_contains(holey, b, yes);
        n += 13 * 5 + 2;
        // the k-DOP pairs: special bounds (inverted, jointly empty, NaN as they come)
        kdop<14> kd{};
        for (unsigned slab = 0; slab < 7; ++slab) kd.min[slab] = special(r), kd.max[slab] = special(r);
        every_tier(kd, q, yes);
        every_tier(kd, seg, yes);
        every_tier(kd, ray, yes);
        every_tier(kd, line, yes);
        kdop<26> kd2{};
        for (unsigned slab = 0; slab < 13; ++slab) kd2.min[slab] = special(r), kd2.max[slab] = special(r);
        every_tier(kd, kd, yes);
        every_tier(kd, kd2, yes);
        every_tier(b, kd, yes);
        every_tier(kd2, pl, yes);
        yes += contains(kd, q) + contains(kd, b) + contains(kd2, seg);
        n += 8 * 5 + 3;
        // the half-space pairs: special planes (zero, NaN and infinite normals and offsets), and a
        // count outside [0, capacity]
        frustum3 fr{};
        for (auto& h : fr.planes) h = plane3{{special(r), special(r), special(r)}, special(r)};
        convex_polyhedron3 cp{};
        cp.count = r.integer(-2, convex_polyhedron3::capacity + 2);
        for (auto& h : cp.planes) h = plane3{{special(r), special(r), special(r)}, special(r)};
        every_tier(fr, q, yes);
        every_tier(fr, seg, yes);
        every_tier(fr, ray, yes);
        every_tier(fr, line, yes);
        every_tier(cp, q, yes);
        every_tier(cp, seg, yes);
        every_tier(cp, ray, yes);
        every_tier(cp, line, yes);
        every_tier(b, fr, yes);
        every_tier(b, cp, yes);
        every_tier(cp, pl, yes);
        every_tier(pl, fr, yes);
        every_tier(cp, cp, yes);
        every_tier(fr, cp, yes);
        every_tier(fr, fr, yes);
        every_tier(cp, t, yes);
        every_tier(t, fr, yes);
        every_tier(kd, t, yes);
        every_tier(cp, kd, yes);
        every_tier(kd2, fr, yes);
        yes += contains(fr, q) + contains(fr, seg) + contains(cp, q) + contains(cp, seg) + contains(fr, b) + contains(cp, b);
        // the 3D polygon pairs: special vertices (a planar square's with one replaced, or all), ring
        // ends that may not increase or reach past the end, plane vertices that may not exist, an axis
        // outside 0..2
        {
            std::array<point3, 8> gv{{{0, 0, 1}, {4, 0, 1}, {4, 4, 1}, {0, 4, 1}, {1, 1, 1}, {1, 3, 1}, {3, 3, 1}, {3, 1, 1}}};
            if (r.coin()) gv[static_cast<unsigned>(r.integer(0, 7))] = p();
            else
                for (auto& x : gv) x = p();
            const std::array<std::uint32_t, 2> gends{static_cast<std::uint32_t>(r.integer(0, 9)),
                                                     static_cast<std::uint32_t>(r.integer(0, 9))};
            const polygon3 pg{gv, gends, {static_cast<std::uint32_t>(r.integer(0, 9)), 2, 1}, r.integer(-1, 3)};
            const polygon3 pg2{gv, {}, {0, 2, 1}, 2};
            every_tier(q, pg, yes);
            every_tier(pg, seg, yes);
            every_tier(pg, ray, yes);
            every_tier(line, pg2, yes);
            every_tier(pl, pg, yes);
            every_tier(pg2, t, yes);
            every_tier(pg, pg2, yes);
            every_tier(b, pg2, yes);
            every_tier(ob, pg, yes);
            every_tier(pg2, te, yes);
            every_tier(me, pg, yes);
            every_tier(cp, pg2, yes);
            every_tier(fr, pg, yes);
            every_tier(kd2, pg2, yes);
            every_tier(pg, ball, yes);
            every_tier(ball, pg2, yes);
            every_tier(capsule3{q, seg.a, ball.radius}, pg, yes);
            every_tier(pg2, capsule3{seg.b, q, ball.radius}, yes);
            yes += contains(pg, q) + contains(pg2, q);
            (void)polygon3::make(gv, gends);
            n += 18 * 5 + 2;
        }
        every_tier(cp, te, yes);
        every_tier(te, fr, yes);
        every_tier(kd2, te, yes);
        every_tier(cp, me, yes);
        every_tier(me, fr, yes);
        every_tier(kd, me, yes);
        yes += contains(fr, t) + contains(cp, t) + contains(kd, t) + contains(fr, te) + contains(cp, te) + contains(kd2, te);
        every_tier(cp, ob, yes);
        every_tier(ob, fr, yes);
        every_tier(kd2, ob, yes);
        yes += contains(cp, ob) + contains(fr, ob) + contains(kd, ob);
        n += 29 * 5 + 15;
        // a ball against the half-space sets
        every_tier(cp, ball, yes);
        every_tier(ball, fr, yes);
        every_tier(kd2, ball, yes);
        every_contains(cp, ball, yes);
        every_contains(fr, ball, yes);
        every_contains(kd, ball, yes);
        yes += method::frustum_sphere_planes(fr, ball);
        every_tier(ob, ball, yes);
        every_tier(ball, ob, yes);
        yes += method::obb_sphere_closest_point(ob, ball);
        n += 8 * 5 + 2;
        // a ball against the flat shapes and the tetrahedron, and a capsule against every partner
        const capsule3 cap{p(), p(), special(r)};
        every_tier(seg, ball, yes);
        every_tier(ball, pl, yes);
        every_tier(t, ball, yes);
        every_tier(ball, te, yes);
        every_tier(cap, q, yes);
        every_tier(ball, cap, yes);
        every_tier(cap, cap, yes);
        every_tier(seg, cap, yes);
        every_tier(cap, pl, yes);
        every_tier(t, cap, yes);
        every_tier(cap, te, yes);
        every_tier(b, cap, yes);
        every_contains(ball, seg, yes);
        every_contains(ball, t, yes);
        every_contains(ball, te, yes);
        every_contains(cap, q, yes);
        every_contains(cap, seg, yes);
        every_contains(cap, t, yes);
        every_contains(cap, te, yes);
        every_contains(cap, b, yes);
        every_contains(b, cap, yes);
        every_contains(ob, cap, yes);
        every_tier(me, ball, yes);
        every_tier(ball, holey, yes);
        every_tier(cap, me, yes);
        every_tier(holey, cap, yes);
        every_contains(cap, ball, yes);
        every_contains(ball, cap, yes);
        every_contains(cap, cap, yes);
        every_contains(cp, cap, yes);
        every_contains(fr, cap, yes);
        every_contains(kd, cap, yes);
        every_contains(kd2, cap, yes);
        every_tier(cap, cp, yes);
        every_tier(fr, cap, yes);
        every_tier(cap, kd, yes);
        every_tier(kd2, cap, yes);
        n += 20 * 5 + 17 * 5;
        // in the plane
        auto p2 = [&] { return point2{special(r), special(r)}; };
        auto v2 = [&] { return vec2{special(r), special(r)}; };
        const segment2 s2{p2(), p2()};
        const ray2 r2{p2(), v2()};
        const line2 l2{p2(), v2()};
        const point2 q2 = p2();
        every_tier(s2, s2, yes);
        every_tier(r2, r2, yes);
        every_tier(l2, l2, yes);
        every_tier(l2, r2, yes);
        every_tier(s2, l2, yes);
        every_tier(r2, s2, yes);
        every_tier(q2, q2, yes);
        every_tier(q2, l2, yes);
        every_tier(r2, q2, yes);
        every_tier(q2, s2, yes);
        n += 10 * 5;
        // the polygon pairs: special vertices in a ring of five (self-intersecting, repeated or
        // collinear as they come), a hole of three; and ring ends past the vertices
        std::array<point2, 8> pv;
        for (auto& x : pv) x = p2();
        const std::array<std::uint32_t, 2> ends{{5, 8}}, past{{5, 9}};
        const polygon2 pg{pv, ends}, bad_ends{pv, past};
        every_tier(q2, pg, yes);
        every_tier(pg, s2, yes);
        every_tier(pg, r2, yes);
        every_tier(l2, pg, yes);
        every_tier(pg, pg, yes);
        every_tier(q2, bad_ends, yes);
        yes += contains(pg, q2) + contains(bad_ends, q2);
        n += 6 * 5 + 2;
    }
    std::printf("[cases] bad input: %ld query calls on special values completed (%ld yes), %ld broken promises of the tiers\n", n, yes,
                contract_broken);
    CHECK(contract_broken == 0);
    // The exact tier says no for NaN input.
    CHECK_FALSE(intersects(ray3{{nan_, 0, 0}, {1, 0, 0}}, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    CHECK(classify(ray3{{nan_, 0, 0}, {1, 0, 0}}, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}) == certainty::uncertain);
    CHECK_FALSE(intersects(sphere3{{inf_, 0, 0}, 1}, sphere3{{0, 0, 0}, 1}));
    CHECK_FALSE(intersects(segment3{{nan_, 0, 0}, {1, 0, 0}}, segment3{{0, 0, 0}, {1, 0, 0}}));
    CHECK_FALSE(intersects(point3{inf_, 0, 0}, point3{inf_, 0, 0}));
    CHECK_FALSE(intersects(segment2{{nan_, 0}, {1, 0}}, segment2{{0, 0}, {1, 0}}));
    // a point triangle reads the box only through comparisons (found by the ray_triangle fuzzer)
    CHECK_FALSE(intersects(aabb3{{-inf_, -1, -inf_}, {1, 0, 0}}, triangle3{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}));
    // a NaN in the one coordinate the other two vertices' equal ones leave out of every normal
    // component the box test computes (found by the ray_triangle fuzzer's corpus replay)
    CHECK_FALSE(intersects(aabb3{{-1, -1, -1}, {1, 1, 1}}, triangle3{{nan_, 0, 0}, {0, 0, 0}, {0, 0, 0}}));
    CHECK_FALSE(intersects(line2{{0, 0}, {inf_, 1}}, point2{0, 0}));
    CHECK_FALSE(intersects(line3{{0, 0, 0}, {inf_, 0, 0}}, plane3{{1, 0, 0}, 1}));
    CHECK_FALSE(intersects(plane3{{0, 0, 0}, nan_}, plane3{{0, 0, 1}, 0}));
    const tetrahedron3 unit{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    CHECK_FALSE(intersects(point3{0.25, 0.25, 0.25}, tetrahedron3{unit.a, unit.b, unit.c, {0, 0, nan_}}));
    CHECK_FALSE(intersects(aabb3{{-1, -1, -1}, {inf_, 1, 1}}, unit));
    CHECK_FALSE(intersects(segment3{{0.1, 0.1, 0.1}, {nan_, 0, 0}}, unit)); // one end inside, the other unread
    CHECK_FALSE(contains(unit, segment3{{0.1, 0.1, 0.1}, {inf_, 0, 0}}));
    CHECK_FALSE(contains(aabb3{{-inf_, -1, -1}, {1, 1, 1}}, unit));
    std::array<point3, 8> cv;
    for (unsigned i = 0; i < 8; ++i) cv[i] = support::cube.vertices[i];
    cv[7].z = nan_; // a NaN vertex the queries below would otherwise not need
    CHECK_FALSE(intersects(mesh3{cv, support::cube_triangles}, point3{0.3, 0.3, 0.3}));
    CHECK_FALSE(intersects(mesh3{cv, support::cube_triangles}, plane3{{0, 0, 1}, 0}));
    CHECK_FALSE(intersects(mesh3{std::span<const point3>(cv.data(), 7), support::cube_triangles}, point3{0.3, 0.3, 0.3}));
    CHECK_FALSE(intersects(support::cube, segment3{{0.3, 0.3, 0.3}, {inf_, 0, 0}}));
    CHECK_FALSE(contains(mesh3{cv, support::cube_triangles}, aabb3{{0.25, 0.25, 0.25}, {0.5, 0.5, 0.5}}));
    CHECK_FALSE(contains(support::cube, aabb3{{0.25, 0.25, 0.25}, {0.5, 0.5, inf_}}));
    CHECK(classify(line3{{nan_, 0, 0}, {1, 0, 0}}, line3{{0, 0, 0}, {0, 1, 0}}) == certainty::uncertain);
    std::array<point2, 8> fv;
    for (unsigned i = 0; i < 8; ++i) fv[i] = support::frame.vertices[i];
    fv[6].y = nan_; // a NaN hole vertex: the point (0.5, 0.5) would not need it
    CHECK_FALSE(intersects(point2{0.5, 0.5}, polygon2{fv, support::frame_ends}));
    CHECK_FALSE(intersects(support::frame, segment2{{0.5, 0.5}, {inf_, 0.5}}));
    CHECK_FALSE(intersects(support::frame, polygon2{fv, support::frame_ends}));
    CHECK_FALSE(intersects(kdop<6>{{0, 0, 0}, {1, 1, inf_}}, point3{0.5, 0.5, 0.5}));
    CHECK_FALSE(intersects(kdop<6>{{0, 0, 0}, {1, 1, 1}}, segment3{{0.5, 0.5, 0.5}, {nan_, 0, 0}})); // one end inside
    CHECK_FALSE(intersects(kdop<6>{{0, 0, 0}, {1, 1, 1}}, ray3{{0.5, 0.5, 0.5}, {inf_, 0, 0}}));
    const convex_polyhedron3 cube{{plane3{{1, 0, 0}, 1}, plane3{{-1, 0, 0}, 0}, plane3{{0, 1, 0}, 1}, plane3{{0, -1, 0}, 0},
                                   plane3{{0, 0, 1}, 1}, plane3{{0, 0, -1}, 0}},
                                  6};
    CHECK(intersects(cube, point3{0.5, 0.5, 0.5}));
    CHECK_FALSE(intersects(convex_polyhedron3{cube.planes, 40}, point3{0.5, 0.5, 0.5})); // count beyond the capacity: no set
    CHECK_FALSE(intersects(convex_polyhedron3{cube.planes, -1}, point3{0.5, 0.5, 0.5}));
    CHECK_FALSE(intersects(cube, segment3{{0.5, 0.5, 0.5}, {nan_, 0, 0}})); // one end inside
    CHECK_FALSE(intersects(cube, ray3{{0.5, 0.5, 0.5}, {inf_, 0, 0}}));
    auto with = [&](unsigned i, plane3 p) {
        auto c = cube;
        c.planes[i] = p;
        return c;
    };
    CHECK_FALSE(intersects(with(2, plane3{{0, nan_, 0}, 1}), point3{0.5, 0.5, 0.5}));
    CHECK_FALSE(intersects(with(2, plane3{{0, 1, 0}, inf_}), point3{0.5, 0.5, 0.5}));
    CHECK(intersects(with(2, plane3{{0, 0, 0}, 0}), point3{0.5, 7, 0.5}));          // 0 <= 0: all of space
    CHECK_FALSE(intersects(with(2, plane3{{0, 0, 0}, -1}), point3{0.5, 0.5, 0.5})); // 0 <= -1: nothing
    frustum3 fr{};
    for (unsigned i = 0; i < 6; ++i) fr.planes[i] = cube.planes[i];
    CHECK(intersects(fr, line3{{0.5, 0.5, 0.5}, {1, 1, 1}}));
    fr.planes[5].offset = nan_;
    CHECK_FALSE(intersects(fr, line3{{0.5, 0.5, 0.5}, {1, 1, 1}}));
}

} // namespace test_query_bad_input
