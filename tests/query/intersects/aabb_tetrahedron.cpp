// aabb3 x tetrahedron3: fixtures (a box corner on a face, one ulp off it, the box inside, the
// tetrahedron inside, flat boxes, coplanar tetrahedra, NaN and inverted boxes); the CGAL Epeck
// oracle (Iso_cuboid_3 and Tetrahedron_3; the exact LP for flat boxes and coplanar tetrahedra) on
// 20,000 random and 20,000 near-degenerate cases (a box corner, edge or face point at a vertex,
// an edge or face point of the tetrahedron, inside or just outside; faces in one plane; then a
// random exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and
// reflected vertex orders, exact translations; the rounded 25-axis stage against the oracle on
// 40,000 cases, the integer grid {-2..2}^3 among them.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_aabb_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("aabb_tetrahedron: fixtures", "[aabb_tetrahedron]") {
    CHECK(intersects(aabb3{{0.5, 0.5, -1}, {2, 2, 1}}, T)); // a box edge through an edge point
    CHECK_FALSE(intersects(aabb3{{0.5, 0x1.0000000000001p-1, -1}, {2, 2, 1}}, T));
    CHECK_FALSE(intersects(aabb3{{1, 1, 1}, {2, 2, 2}}, T));
    CHECK(intersects(aabb3{{0.25, 0.25, 0.5}, {2, 2, 2}}, T)); // a corner on the slanted face
    CHECK_FALSE(intersects(aabb3{{0.25, 0.25, 0x1.0000000000001p-1}, {2, 2, 2}}, T));
    CHECK(intersects(aabb3{{0.1, 0.1, 0.1}, {0.2, 0.2, 0.2}}, T)); // inside
    CHECK(intersects(T, aabb3{{-1, -1, -1}, {2, 2, 2}}));          // around it
    CHECK(intersects(aabb3{{0.2, 0.2, 0}, {3, 3, 0}}, T));         // a flat box on the face z = 0
    CHECK_FALSE(intersects(aabb3{{0.2, 0.2, -0x1p-1074}, {3, 3, -0x1p-1074}}, T));
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(aabb3{{1, 1, -1}, {2, 2, 1}}, flat));
    CHECK_FALSE(intersects(aabb3{{1, 0x1.0000000000001p0, -1}, {2, 2, 1}}, flat));
    CHECK_FALSE(intersects(aabb3{{-1, -1, -1}, {2, 2, 2}}, tetrahedron3{T.a, T.b, T.c, {0, 0, std::nan("")}}));
    CHECK_FALSE(intersects(aabb3{{-1, -1, -1}, {2, 2, HUGE_VAL}}, T));
    CHECK_FALSE(intersects(aabb3{{2, 2, 2}, {-1, -1, -1}}, T)); // inverted: empty
}
TEST_CASE("aabb_tetrahedron: oracle, random and near-degenerate", "[aabb_tetrahedron][oracle]") {
    support::flat_oracle<aabb3, tetrahedron3>("aabb_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("aabb_tetrahedron: the rounded axes never decide against the oracle", "[aabb_tetrahedron][oracle]") {
    // Random cases at every scale and at scale 1, near-degenerate cases (flat boxes and coplanar
    // tetrahedra included), the integer grid {-2..2}^3 and a few non-finite coordinates.
    support::rng r(support::seed() + 11);
    long n = 0, decided = 0, one_n = 0, one_decided = 0, wrong = 0;
    constexpr int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    constexpr int faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    for (long i = 0; i < support::cases(40000); ++i) {
        const int kind = int(i % 4);
        auto [b, t] = kind == 0   ? support::flat_random<aabb3, tetrahedron3>(r)
                      : kind == 1 ? support::flat_random<aabb3, tetrahedron3>(r, false)
                      : kind == 2 ? support::flat_near<aabb3, tetrahedron3>(r)
                                  : [&] {
                                        auto g = [&] { return double(r.integer(-2, 2)); };
                                        auto p = [&] { return point3{g(), g(), g()}; };
                                        return std::pair{support::ordered(aabb3{p(), p()}), tetrahedron3{p(), p(), p(), p()}};
                                    }();
        const bool finite_input = r.integer(0, 199) != 0;
        if (!finite_input) t.c.y = r.coin() ? std::nan("") : (r.coin() ? 1.0 : -1.0) * INFINITY;
        const point3 v[4] = {t.a, t.b, t.c, t.d};
        const certainty fast = detail::box_triangle::rounded_hull_axes_decide(b, v, edges, faces);
        ++n;
        one_n += kind == 1;
        if (fast == certainty::uncertain) continue;
        ++decided;
        one_decided += kind == 1;
        if (!finite_input) { // no shape: never a yes (the exact tier says no)
            wrong += fast == certainty::yes;
            continue;
        }
        if ((fast == certainty::yes) != support::flat_truth(b, t)) {
            if (++wrong <= 5) std::printf("  rounded axes wrong: %s %s\n", support::shape_str(b).c_str(), support::shape_str(t).c_str());
        }
    }
    std::printf("[cases] aabb_tetrahedron rounded axes: %ld cases, %ld decided (%ld of %ld random at scale 1), wrong %ld\n", n, decided,
                one_decided, one_n, wrong);
    CHECK(wrong == 0);
    CHECK(one_decided > one_n * 9 / 10);
}
TEST_CASE("aabb_tetrahedron: rewrites of either shape and exact translations give the same answer", "[aabb_tetrahedron]") {
    support::flat_symmetries<aabb3, tetrahedron3>("aabb_tetrahedron", support::cases(20000));
}

} // namespace test_query_aabb_tetrahedron
