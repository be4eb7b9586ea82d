// The filter's second try on a scaled scene (modules/query/scene_scale.cppm): normalized() scales
// lengths and keeps directions, exactly or not at all; and classify decides a random scene moved
// to 2^-480..2^480 exactly as it decides the same scene at scale 1, where the first filter pass
// alone gives up on many of them (the tests count those, so the retry is seen to work).
#include <catch2/catch_test_macros.hpp>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"

namespace test_query_scene_scale { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
namespace scene = incidence::detail::scene;

namespace {
// A copy with every length times 2^k (exact for the generators below: every length is a normal
// number far from both ends of the range), written apart from the code under test.
double times(double x, int k) { return std::ldexp(x, k); }
point3 times(point3 p, int k) { return {times(p.x, k), times(p.y, k), times(p.z, k)}; }
triangle3 times(const triangle3& t, int k) { return {times(t.a, k), times(t.b, k), times(t.c, k)}; }
segment3 times(const segment3& s, int k) { return {times(s.a, k), times(s.b, k)}; }
ray3 times(const ray3& r, int k) { return {times(r.origin, k), r.direction}; }
aabb3 times(const aabb3& b, int k) { return {times(b.min, k), times(b.max, k)}; }
obb3 times(const obb3& b, int k) {
    return {times(b.center, k), b.axes, {times(b.half_extents[0], k), times(b.half_extents[1], k), times(b.half_extents[2], k)}};
}
tetrahedron3 times(const tetrahedron3& t, int k) { return {times(t.a, k), times(t.b, k), times(t.c, k), times(t.d, k)}; }
sphere3 times(const sphere3& s, int k) { return {times(s.center, k), times(s.radius, k)}; }
convex_polyhedron3 times(convex_polyhedron3 c, int k) {
    for (int i = 0; i < c.count; ++i) c.planes[static_cast<unsigned>(i)].offset = times(c.planes[static_cast<unsigned>(i)].offset, k);
    return c;
}
template <int K>
kdop<K> times(kdop<K> d, int k) {
    for (double& x : d.min) x = times(x, k);
    for (double& x : d.max) x = times(x, k);
    return d;
}

point3 rp(support::rng& r) { return {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}; }
vec3 rv(support::rng& r) { return {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}; }
point3 near(support::rng& r, point3 c, double d) { return {c.x + r.uniform(-d, d), c.y + r.uniform(-d, d), c.z + r.uniform(-d, d)}; }
// Shapes of size about 0.5 around centres in [-1, 1]^3, so about half of the pairs meet.
triangle3 rtri(support::rng& r) {
    const point3 c = rp(r);
    return {near(r, c, 0.6), near(r, c, 0.6), near(r, c, 0.6)};
}
obb3 robb(support::rng& r) {
    const vec3 a = rv(r), b = rv(r); // a frame read exactly as given (not orthonormal)
    return {rp(r), {a, b, cross(a, b)}, {r.uniform(0.1, 0.5), r.uniform(0.1, 0.5), r.uniform(0.1, 0.5)}};
}
aabb3 rbox(support::rng& r) {
    const point3 c = rp(r);
    return {{c.x - r.uniform(0, 0.5), c.y - r.uniform(0, 0.5), c.z - r.uniform(0, 0.5)},
            {c.x + r.uniform(0, 0.5), c.y + r.uniform(0, 0.5), c.z + r.uniform(0, 0.5)}};
}
convex_polyhedron3 rpoly(support::rng& r) { // the supporting half-spaces of 6 random normals around a point
    convex_polyhedron3 c{};
    const point3 o = rp(r);
    c.count = 6;
    for (int i = 0; i < 6; ++i) {
        const vec3 n = rv(r);
        c.planes[static_cast<unsigned>(i)] = {n, dot(n, o - point3{0, 0, 0}) + r.uniform(0.1, 0.6)};
    }
    return c;
}
kdop<14> rkdop(support::rng& r) {
    const point3 c = rp(r);
    const point3 pts[4] = {near(r, c, 0.5), near(r, c, 0.5), near(r, c, 0.5), near(r, c, 0.5)};
    return bound::kdop_of<14>(pts).value();
}

struct tally {
    long cases = 0, first_pass_failed = 0, differ = 0;
};
// One pair at scale 1 and at 2^k: classify, the exact tier and the conservative and aggressive
// tiers must give the scale-1 answers (a certain classify at scale 1 stays certain).
template <class A, class B>
void check(tally& t, const A& a, const B& b, const A& as, const B& bs) {
    const certainty c = classify(a, b);
    if (c == certainty::uncertain) return;
    ++t.cases;
    arith::filter_kernel f;
    (void)detail::intersects(f, as, bs);
    t.first_pass_failed += f.failed();
    const bool yes = c == certainty::yes;
    if (classify(as, bs) != c || intersects(as, bs) != yes || intersects<conservative>(as, bs) != yes ||
        intersects<aggressive>(as, bs) != yes || classify(bs, as) != c)
        ++t.differ;
}
template <class Gen>
tally run(const char* name, Gen gen) {
    support::rng r(support::seed() + 17);
    tally t;
    for (long i = 0; i < support::cases(3000); ++i) {
        const int k = r.coin() ? r.integer(-480, -250) : r.integer(250, 480);
        gen(r, t, k);
    }
    std::printf("[cases] scene scale %s: %ld scenes certain at scale 1, moved to 2^+-250..480: first filter pass failed on %ld, "
                "answers differ %ld\n",
                name, t.cases, t.first_pass_failed, t.differ);
    CHECK(t.differ == 0);
    CHECK(t.cases > support::cases(3000) / 2);
    return t;
}
} // namespace

TEST_CASE("scene_scale: normalized scales lengths exactly and keeps directions", "[query][scene_scale]") {
    const double s = 0x1p-600;
    const ray3 r{{3 * s, -5 * s, 0.75 * s}, {1, 2, 3}};
    const plane3 p{{0, 0, 2}, 7 * s};
    const auto n = scene::normalized(r, p);
    REQUIRE(n.has_value());
    // the largest length is 7 s, in [4 s, 8 s): scaled by 1 / (4 s) into [1, 2)
    CHECK(n->a.origin == point3{0.75, -1.25, 0.1875});
    CHECK(n->a.direction == vec3{1, 2, 3});
    CHECK(n->b.normal == vec3{0, 0, 2});
    CHECK(n->b.offset == 1.75);
    const obb3 b{{0x1p700, 0, 0}, {vec3{1, 0, 0}, vec3{0, 3, 0}, vec3{0, 0, 1}}, {0x1p699, 1, 0.5}};
    const auto m = scene::normalized(b, sphere3{{0, 0x1p698, 0}, 0x1p697});
    REQUIRE(m.has_value());
    CHECK(m->a.center == point3{1, 0, 0});
    CHECK(m->a.axes[1] == vec3{0, 3, 0});
    CHECK(m->a.half_extents[0] == 0.5);
    CHECK(m->a.half_extents[1] == 0x1p-700);
    CHECK(m->b.radius == 0.125);
    // near scale 1: nothing to gain
    CHECK_FALSE(scene::normalized(segment3{{0, 0, 0}, {1e10, 0, 0}}, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).has_value());
    // a bit would be lost (the small length would leave the normal range), or a value is not finite
    CHECK_FALSE(scene::normalized(segment3{{0x1p900, 0, 0}, {0x1.8p-200, 0, 0}}, point3{0, 0, 0}).has_value());
    CHECK_FALSE(scene::normalized(segment3{{0x1p900, 0, 0}, {NAN, 0, 0}}, point3{0, 0, 0}).has_value());
    CHECK_FALSE(scene::normalized(point3{0, 0, 0}, point3{0, 0, 0}).has_value()); // all zero
    // the largest power: 2^1023 down to 1 takes two steps of the factor
    const auto big = scene::normalized(point3{0x1.8p1023, 0, 0}, point3{0, -0x1p1000, 0});
    REQUIRE(big.has_value());
    CHECK(big->a.x == 1.5);
    CHECK(big->b.y == -0x1p-23);
    static_assert(scene::normalized(point3{0x1p-700, 0, 0}, point3{0, 0x1p-701, 0})->b.y == 0.5);
}

TEST_CASE("scene_scale: classify decides a scene far from scale 1 as at scale 1", "[query][scene_scale]") {
    // Signs of degree 3 in the lengths (orient3d of four vertices) leave the filter's range there:
    // the retry is what decides most of these three. Shapes whose bounding boxes lie apart are
    // decided by comparisons before any sign, so the scenes here are drawn with boxes that meet.
    auto boxes_meet = [](const auto& a, const auto& b) { return detail::boxes_meet(detail::bounds(a), detail::bounds(b)); };
    const tally degree3[] = {
        run("triangle_triangle",
            [&](support::rng& r, tally& t, int k) {
                triangle3 a = rtri(r), b = rtri(r);
                while (!boxes_meet(a, b)) a = rtri(r), b = rtri(r);
                check(t, a, b, times(a, k), times(b, k));
            }),
        run("segment_triangle",
            [&](support::rng& r, tally& t, int k) {
                segment3 a;
                triangle3 b;
                do {
                    const point3 c = rp(r);
                    a = segment3{near(r, c, 0.8), near(r, c, 0.8)};
                    b = rtri(r);
                } while (!boxes_meet(a, b));
                check(t, a, b, times(a, k), times(b, k));
            }),
        run("tetrahedron_tetrahedron",
            [](support::rng& r, tally& t, int k) {
                const tetrahedron3 a{rp(r), rp(r), rp(r), rp(r)}, b{rp(r), rp(r), rp(r), rp(r)};
                check(t, a, b, times(a, k), times(b, k));
            }),
    };
    for (const tally& t : degree3) CHECK(t.first_pass_failed > t.cases / 2);
    // The others mix unscaled directions or axes into their signs, so fewer of their signs leave
    // the range; every answer must still be the scale-1 one.
    run("ray_triangle", [](support::rng& r, tally& t, int k) {
        const ray3 a{rp(r), rv(r)};
        const triangle3 b = rtri(r);
        check(t, a, b, times(a, k), times(b, k));
    });
    run("obb_obb", [](support::rng& r, tally& t, int k) {
        const obb3 a = robb(r), b = robb(r);
        check(t, a, b, times(a, k), times(b, k));
    });
    run("aabb_triangle", [](support::rng& r, tally& t, int k) {
        const aabb3 a = rbox(r);
        const triangle3 b = rtri(r);
        check(t, a, b, times(a, k), times(b, k));
    });
    run("convex_polyhedron_triangle", [](support::rng& r, tally& t, int k) {
        const convex_polyhedron3 a = rpoly(r);
        const triangle3 b = rtri(r);
        check(t, a, b, times(a, k), times(b, k));
    });
    run("kdop_obb", [](support::rng& r, tally& t, int k) {
        const kdop<14> a = rkdop(r);
        const obb3 b = robb(r);
        check(t, a, b, times(a, k), times(b, k));
    });
    run("aabb_sphere", [](support::rng& r, tally& t, int k) {
        const aabb3 a = rbox(r);
        const sphere3 b{rp(r), r.uniform(0, 0.5)};
        check(t, a, b, times(a, k), times(b, k));
    });
}

namespace {
// A planar polygon (a star of 5..9 vertices around a grid point, in the plane spanned by two
// small integer vectors, every coordinate exact) and the same polygon with every coordinate
// times 2^k: views of two vertex arrays.
struct star_polygon {
    std::vector<point3> v, vs;
    polygon3 g{}, gs{};
    bool make(support::rng& r, int k) {
        auto grid = [&] { return std::ldexp(double(r.integer(-1024, 1024)), -10); };
        auto small_vec = [&] { return vec3{double(r.integer(-2, 2)), double(r.integer(-2, 2)), double(r.integer(-2, 2))}; };
        const point3 c{grid(), grid(), grid()};
        const vec3 e1 = small_vec(), e2 = small_vec();
        const int n = r.integer(5, 9);
        v.clear();
        for (int i = 0; i < n; ++i) { // u, v multiples of 1/32: every sum below is exact
            const double a = 6.283185307179586 * i / n, rad = r.uniform(0.2, 0.7);
            const double u = std::round(32 * rad * std::cos(a)) / 32, w = std::round(32 * rad * std::sin(a)) / 32;
            v.push_back(c + e1 * u + e2 * w);
        }
        vs.clear();
        for (const point3& p : v) vs.push_back(times(p, k));
        const auto a = polygon3::make(v), b = polygon3::make(vs);
        if (!a.has_value() || !b.has_value()) return false;
        g = a.value(), gs = b.value();
        return true;
    }
};
} // namespace

TEST_CASE("scene_scale: a pair with a view is filtered again with every input scaled", "[query][scene_scale]") {
    // polygon3 and mesh3 are views, not copied: the retry scales every input (directions too) as
    // the filter lifts it (arith::scaled_filter_kernel). The directions of the rays are scaled
    // here as well, as a scene's directions (differences of its points) would be.
    const tally t1 = run("polygon_segment", [](support::rng& r, tally& t, int k) {
        star_polygon p;
        if (!p.make(r, k)) return;
        const point3 c = rp(r);
        const segment3 s{near(r, c, 0.8), near(r, c, 0.8)};
        check(t, p.g, s, p.gs, times(s, k));
    });
    const tally t2 = run("polygon_triangle", [](support::rng& r, tally& t, int k) {
        star_polygon p;
        if (!p.make(r, k)) return;
        const triangle3 b = rtri(r);
        check(t, p.g, b, p.gs, times(b, k));
    });
    const tally t3 = run("polygon_ray", [](support::rng& r, tally& t, int k) {
        star_polygon p;
        if (!p.make(r, k)) return;
        const ray3 a{rp(r), rv(r)};
        check(t, p.g, a, p.gs, ray3{times(a.origin, k), vec3{times(a.direction.x, k), times(a.direction.y, k), times(a.direction.z, k)}});
    });
    const tally t4 = run("mesh_segment", [](support::rng& r, tally& t, int k) {
        const tetrahedron3 q{rp(r), rp(r), rp(r), rp(r)};
        const point3 pts[4] = {q.a, q.b, q.c, q.d};
        point3 spts[4];
        for (int i = 0; i < 4; ++i) spts[i] = times(pts[i], k);
        const std::array<std::uint32_t, 3> tri[4] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}; // closed (inside by parity)
        const auto m = mesh3::make(pts, tri), ms = mesh3::make(spts, tri);
        if (!m.has_value() || !ms.has_value()) return;
        const point3 c = rp(r);
        const segment3 s{near(r, c, 0.8), near(r, c, 0.8)};
        check(t, m.value(), s, ms.value(), times(s, k));
    });
    for (const tally& t : {t1, t2, t3, t4}) CHECK(t.first_pass_failed > t.cases / 4);
}

TEST_CASE("scene_scale: the scaled retry never trusts an input that scaling would lose", "[query][scene_scale]") {
    // A square at 2^600 in the plane z = 0 and a segment above it, at heights 2^-1000 and
    // 2^-1001: scaled by 2^-600 for the filter, both heights would fall to zero and the segment
    // would lie in the square. They are lifted as NaN instead, and the exact tier decides.
    const double far = 0x1p600;
    const point3 sq[4] = {{-far, -far, 0}, {far, -far, 0}, {far, far, 0}, {-far, far, 0}};
    const polygon3 g = polygon3::make(sq).value();
    const segment3 above{{0, 0, 0x1p-1000}, {1, 1, 0x1p-1001}};
    const segment3 through{{0, 0, 0x1p-1000}, {1, 1, -0x1p-1001}};
    CHECK(classify(g, above) != certainty::yes);
    CHECK_FALSE(intersects(g, above));
    CHECK_FALSE(intersects<aggressive>(g, above));
    CHECK(intersects(g, through));
    CHECK(intersects<conservative>(g, through));
    CHECK(classify(g, through) != certainty::no);
}

} // namespace test_query_scene_scale
