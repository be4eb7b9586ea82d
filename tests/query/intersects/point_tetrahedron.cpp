// point3 x tetrahedron3, and contains(tetrahedron, point | segment | triangle | tetrahedron):
// fixtures (inside, on a face, an edge or a vertex, one ulp outside, a subnormal offset, coplanar
// tetrahedra, NaN); the CGAL Epeck oracle (Tetrahedron_3; the exact LP for coplanar tetrahedra) on
// 20,000 random and 20,000 near-degenerate cases (the point at a vertex, an edge, face or inside
// point of the tetrahedron or just outside; coplanar tetrahedra; then a random exact-or-nudged
// scale 2^-500..2^500 and translation); both argument orders, rotated and reflected vertex orders,
// exact translations; the rounded stage (tetra::rounded_locate, rounded_crossing,
// rounded_edge_axes_apart) against exact orient3d signs and the oracle on 40,000 cases, the
// integer grid {-2..2}^3 among them.
#include <catch2/catch_test_macros.hpp>
#include <type_traits>
#include <vector>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_point_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("point_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("point_tetrahedron: fixtures", "[point_tetrahedron]") {
    CHECK(intersects(point3{0.25, 0.25, 0.25}, T));
    CHECK(intersects(T, point3{0, 0, 1}));                                         // a vertex
    CHECK(intersects(point3{0.5, 0.5, 0}, T));                                     // an edge
    CHECK(intersects(point3{0.5, 0.25, 0.25}, T));                                 // the slanted face
    CHECK_FALSE(intersects(point3{0.5, 0.25, 0x1.0000000000001p-2}, T));           // one ulp beyond it
    CHECK(intersects(point3{0, 0.1, 0.1}, T));                                     // the face x = 0
    CHECK_FALSE(intersects(point3{-0x1p-1074, 0.1, 0.1}, T));                      // a subnormal outside it
    CHECK(intersects(point3{0.25, 0.25, 0.25}, tetrahedron3{T.b, T.a, T.c, T.d})); // the other orientation
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};           // coplanar: the triangle's hull
    CHECK(intersects(point3{0.5, 0.5, 0}, flat));
    CHECK_FALSE(intersects(point3{0.5, 0.5, 0x1p-1000}, flat));
    CHECK_FALSE(intersects(point3{std::nan(""), 0.25, 0.25}, T));
    CHECK_FALSE(intersects(point3{0.25, 0.25, 0.25}, tetrahedron3{T.a, T.b, T.c, {0, 0, HUGE_VAL}}));
    CHECK_FALSE(tetrahedron3::make(flat.a, flat.b, flat.c, flat.d).has_value());
    CHECK(tetrahedron3::make(T.a, T.b, T.c, T.d).has_value());
}
TEST_CASE("point_tetrahedron: contains, fixtures", "[point_tetrahedron]") {
    CHECK(contains(T, point3{0.5, 0.25, 0.25}));
    CHECK(contains(T, segment3{{0, 0, 0}, {0.5, 0.25, 0.25}}));
    CHECK_FALSE(contains(T, segment3{{0, 0, 0}, {0.5, 0.25, 0x1.0000000000001p-2}}));
    CHECK(contains(T, triangle3{T.b, T.c, T.d}));
    CHECK(contains(T, T));
    CHECK(contains(T, tetrahedron3{T.a, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}}));
    CHECK_FALSE(contains(tetrahedron3{T.a, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}}, T));
    CHECK(contains(T, aabb3{{0, 0, 0}, {0.25, 0.25, 0.5}}));
    CHECK_FALSE(contains(T, aabb3{{0, 0, 0}, {0.25, 0.25, 0x1.0000000000001p-1}}));
    CHECK(contains(aabb3{{0, 0, 0}, {1, 1, 1}}, T));
    CHECK_FALSE(contains(aabb3{{0, 0, 0}, {1, 1, 0x1.fffffffffffffp-1}}, T));
}
TEST_CASE("point_tetrahedron: oracle, random and near-degenerate", "[point_tetrahedron][oracle]") {
    support::flat_oracle<point3, tetrahedron3>("point_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("point_tetrahedron: contains against the oracle", "[point_tetrahedron][oracle]") {
    support::flat_contains_oracle<tetrahedron3, point3>("tetrahedron_point", support::cases(20000), approx_bound);
    support::flat_contains_oracle<tetrahedron3, segment3>("tetrahedron_segment", support::cases(20000), approx_bound);
    support::flat_contains_oracle<tetrahedron3, triangle3>("tetrahedron_triangle", support::cases(20000), approx_bound);
    support::flat_contains_oracle<tetrahedron3, tetrahedron3>("tetrahedron_tetrahedron", support::cases(20000), approx_bound);
    support::flat_contains_oracle<tetrahedron3, aabb3>("tetrahedron_aabb", support::cases(20000), approx_bound);
    support::flat_contains_oracle<aabb3, tetrahedron3>("aabb_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("point_tetrahedron: the rounded stage never claims what the exact signs deny", "[point_tetrahedron][oracle]") {
    // tetra::rounded_locate on a tetrahedron and the vertices of another shape (a point, a
    // segment, a triangle or a tetrahedron): random cases at every scale and at scale 1,
    // near-degenerate ones (touching, coplanar, nudged by an ulp), the integer grid {-2..2}^3. Each
    // claim is checked against CGAL Epeck's orient3d signs: a point clearly inside has every one of
    // the four signs equal to orient3d(a, b, c, d) (nonzero), clearly beyond has one of them
    // opposite, and `apart` has one face whose sign is opposite for every point. A clear crossing
    // (tetra::rounded_crossing) is checked against the oracle's segment-tetrahedron answer, a clear
    // edge axis (tetra::rounded_edge_axes_apart) against its answer for the points' hull.
    support::rng r(support::seed() + 13);
    long n = 0, decided = 0, one_n = 0, one_decided = 0, wrong = 0, crossing = 0, crossing_wrong = 0, axes = 0, axes_wrong = 0;
    auto o3 = [](point3 a, point3 b, point3 c, point3 d) {
        double A[3], B[3], C[3], D[3];
        support::arr(a, A), support::arr(b, B), support::arr(c, C), support::arr(d, D);
        return oracle::orient3d(A, B, C, D);
    };
    for (long i = 0; i < support::cases(40000); ++i) {
        const int kind = int(i % 5);
        tetrahedron3 t{};
        std::vector<point3> pts;
        auto take = [&](const auto& pair) {
            const auto& [x, y] = pair;
            using X = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<X, tetrahedron3>) t = x, pts = {y.a, y.b, y.c, y.d};
            else if constexpr (std::is_same_v<X, point3>) t = y, pts = {x};
            else t = y, pts = {x.a, x.b};
        };
        if (kind == 0) take(support::flat_random<tetrahedron3, tetrahedron3>(r));
        else if (kind == 1) take(support::flat_random<tetrahedron3, tetrahedron3>(r, false));
        else if (kind == 2) take(support::flat_near<tetrahedron3, tetrahedron3>(r));
        else if (kind == 3) {
            if (r.coin()) take(support::flat_near<point3, tetrahedron3>(r));
            else take(support::flat_near<segment3, tetrahedron3>(r));
        } else {
            auto g = [&] { return double(r.integer(-2, 2)); };
            auto p = [&] { return point3{g(), g(), g()}; };
            t = tetrahedron3{p(), p(), p(), p()};
            pts = {p(), p(), p()};
        }
        const auto got = detail::tetra::rounded_locate(t, pts.data(), int(pts.size()));
        // An edge between two of the points clearly through a face: that segment meets t.
        for (std::size_t p = 0; p < pts.size(); ++p)
            for (std::size_t q = p + 1; q < pts.size(); ++q)
                if (detail::tetra::rounded_crossing(got, int(p), int(q))) {
                    ++crossing;
                    if (!support::flat_truth(segment3{pts[p], pts[q]}, t) && ++crossing_wrong <= 5)
                        std::printf("  rounded crossing wrong: %s\n", support::shape_str(t).c_str());
                }
        // A clearly separating edge axis: the points' hull misses t.
        const point3 tv[4] = {t.a, t.b, t.c, t.d};
        if (detail::tetra::rounded_edge_axes_apart(pts.data(), int(pts.size()), tv, 4)) {
            ++axes;
            const std::size_t m = pts.size();
            const bool meets = m == 1   ? support::flat_truth(pts[0], t)
                               : m == 2 ? support::flat_truth(segment3{pts[0], pts[1]}, t)
                               : m == 3 ? support::flat_truth(triangle3{pts[0], pts[1], pts[2]}, t)
                                        : support::flat_truth(tetrahedron3{pts[0], pts[1], pts[2], pts[3]}, t);
            if (meets && ++axes_wrong <= 5) std::printf("  rounded edge axes wrong: %s\n", support::shape_str(t).c_str());
        }
        ++n;
        one_n += kind == 1;
        bool any = got.apart;
        for (std::size_t j = 0; j < pts.size(); ++j) any = any || got.status[j] != 0;
        if (!any) continue;
        ++decided;
        one_decided += kind == 1;
        const point3 v[4] = {t.a, t.b, t.c, t.d};
        const int o = o3(t.a, t.b, t.c, t.d);
        auto side = [&](int f, point3 p) {
            point3 w[4] = {v[0], v[1], v[2], v[3]};
            w[f] = p;
            return o3(w[0], w[1], w[2], w[3]);
        };
        bool ok = o != 0;
        for (std::size_t j = 0; j < pts.size() && ok; ++j) {
            int same = 0, opposite = 0;
            for (int f = 0; f < 4; ++f) same += side(f, pts[j]) == o, opposite += side(f, pts[j]) == -o;
            if (got.status[j] == 1) ok = same == 4;
            if (got.status[j] == -1) ok = opposite > 0;
        }
        if (ok && got.apart) {
            bool some_face = false;
            for (int f = 0; f < 4; ++f) {
                bool all = true;
                for (const point3& p : pts) all = all && side(f, p) == -o;
                some_face = some_face || all;
            }
            ok = some_face;
        }
        if (!ok && ++wrong <= 5) std::printf("  rounded face planes wrong: %s\n", support::shape_str(t).c_str());
    }
    // Edges that touch: two tetrahedra on the integer grid |x| < 2^20 (projections near 2^62, so
    // they round), one's edge through the exact midpoint of the other's, their other vertices on
    // opposite sides of the plane of the two edges. Only that edge axis could separate them, and
    // it cannot: they share the midpoint. Any claim is wrong.
    long touching = 0;
    while (touching < support::cases(2000)) {
        using i128 = __int128;
        auto g = [&] { return double(r.integer(-(1 << 19), 1 << 19)); };
        auto p = [&] { return point3{g(), g(), g()}; };
        const point3 a = p(), w = p(), c = p(), d = p(), u = p(), e3 = p(), e4 = p();
        const point3 b{a.x + 2 * w.x, a.y + 2 * w.y, a.z + 2 * w.z}, x{a.x + w.x, a.y + w.y, a.z + w.z};
        auto side = [&](point3 q) { // sign of (w x u) . (q - x), exactly
            const i128 wx = i128(w.x), wy = i128(w.y), wz = i128(w.z), ux = i128(u.x), uy = i128(u.y), uz = i128(u.z);
            const i128 nx = wy * uz - wz * uy, ny = wz * ux - wx * uz, nz = wx * uy - wy * ux;
            const i128 v = nx * i128(q.x - x.x) + ny * i128(q.y - x.y) + nz * i128(q.z - x.z);
            return v > 0 ? 1 : (v < 0 ? -1 : 0);
        };
        const int sc = side(c), sd = side(d);
        if (sc == 0 || sc != sd) continue;
        auto away = [&](point3 q) { return side(q) == -sc ? q : point3{2 * x.x - q.x, 2 * x.y - q.y, 2 * x.z - q.z}; };
        const point3 f3 = away(e3), f4 = away(e4);
        if (side(f3) != -sc || side(f4) != -sc) continue;
        const point3 tv[4] = {a, b, c, d};
        const point3 ov[4] = {point3{x.x - u.x, x.y - u.y, x.z - u.z}, point3{x.x + u.x, x.y + u.y, x.z + u.z}, f3, f4};
        ++touching;
        if (detail::tetra::rounded_edge_axes_apart(ov, 4, tv, 4)) {
            ++axes;
            if (++axes_wrong <= 5) std::printf("  rounded edge axes wrong on touching edges\n");
        }
    }
    std::printf("[cases] tetrahedron rounded face planes: %ld cases, %ld decided (%ld of %ld random at scale 1), wrong %ld\n", n, decided,
                one_decided, one_n, wrong);
    std::printf("[cases] tetrahedron rounded crossings: %ld claimed, wrong %ld; rounded edge axes: %ld claimed, wrong %ld\n", crossing,
                crossing_wrong, axes, axes_wrong);
    CHECK(wrong == 0);
    CHECK(crossing_wrong == 0);
    CHECK(axes_wrong == 0);
    CHECK(one_decided > one_n * 9 / 10);
    CHECK(crossing > n / 20);
    CHECK(axes > n / 100);
}
TEST_CASE("point_tetrahedron: rewrites of either shape and exact translations give the same answer", "[point_tetrahedron]") {
    support::flat_symmetries<point3, tetrahedron3>("point_tetrahedron", support::cases(20000));
}

} // namespace test_query_point_tetrahedron
