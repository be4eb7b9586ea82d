// point3 x polygon3 and contains(polygon, point): fixtures (inside, in the hole, on the hole's edge,
// one ulp above, a tilted non-convex polygon, make() refusing non-planar, collinear and self-crossing
// input with the deviation measured); the oracle (the polygon's CGAL constrained triangulation, each
// triangle against the other shape by CGAL Epeck, the exact LP or the mesh oracle) on 20,000 random
// and 20,000 near-degenerate cases (support/polygon3_cases.hpp: exactly planar star polygons with
// holes at scales 2^-500..2^500, the other shape at a vertex, an edge point or inside, along the edge,
// in the plane or across it, nudged by ulps or not); both argument orders, rotated and reversed rings,
// rewritten partners, exact translations; the rounded crossing stage (polygon3d::rounded_crossing, for
// segments, rays and lines across the plane) against the oracle.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/mesh_checks.hpp"
#include "testkit/polygon3_cases.hpp"
#include "testkit/polygon3_checks.hpp"
#include "testkit/polygon3_fixtures.hpp"
#include "testkit/polyhedron_fixtures.hpp"
#include "testkit/kdop_fixtures.hpp"
#include "testkit/mesh_fixtures.hpp"

namespace test_query_point_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("point_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point_polygon: fixtures", "[point_polygon]") {
    CHECK(intersects(point3{0.5, 0.5, 1}, holed));
    CHECK_FALSE(intersects(point3{2, 2, 1}, holed));                       // in the hole
    CHECK(intersects(holed, point3{1, 2, 1}));                             // on the hole's edge
    CHECK(contains(holed, point3{3, 3, 1}));                               // a hole corner
    CHECK_FALSE(intersects(point3{0.5, 0.5, 0x1.0000000000001p0}, holed)); // one ulp above
    CHECK(intersects(point3{1.5, 0.5, 0.5}, tilted_l));                    // x + z = 2 inside the L
    CHECK_FALSE(intersects(point3{1.5, 1.5, 0.5}, tilted_l));              // in the L's notch
    CHECK(intersects(point3{1, 1.5, 1}, tilted_l));                        // on its inner edge
    const auto made = polygon3::make(holed_vertices, holed_ends);
    REQUIRE(made.has_value());
    CHECK(intersects(point3{0.5, 0.5, 1}, made.value()));
    const std::array<point3, 4> bent{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0x1p-40}}};
    const auto refused = polygon3::make(bent);
    REQUIRE_FALSE(refused.has_value());
    CHECK(refused.error().code == errc::non_planar_polygon);
    CHECK(refused.error().measured > 0x1p-42);
    CHECK(refused.error().measured <= 0x1p-40); // the vertex off the plane of the other three: 2^-40 at most
    CHECK(refused.error().what().find("off the plane") != std::string::npos);
    const std::array<point3, 3> line{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}};
    CHECK(polygon3::make(line).error().code == errc::degenerate_polygon);
    const std::array<point3, 4> bow{{{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}};
    CHECK(polygon3::make(bow).error().code == errc::self_intersecting_polygon);
    const std::array<point3, 3> bad{{{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}};
    CHECK(polygon3::make(bad).error().code == errc::not_finite);
    CHECK_FALSE(intersects(point3{0.5, 0.5, 1}, polygon3{holed_vertices, holed_ends, {0, 2, 9}, 2})); // bad plane index: no set
    CHECK_FALSE(intersects(point3{0.5, 0.5, 1}, polygon3{holed_vertices, holed_ends, {0, 2, 1}, 0})); // n has no x component: no set
}
TEST_CASE("point_polygon: oracle, random and near-degenerate", "[point_polygon][oracle]") {
    support::polygon3_oracle<point3>("point_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("point_polygon: the rounded crossing stage never claims what the oracle denies", "[point_polygon][polygon_segment][oracle]") {
    // polygon3d::rounded_crossing, the filter pass's stage of every pair that crosses a polygon's
    // plane with a segment, ray or line (crossing_inside, linear_meets): for random cases at every
    // scale and at scale 1 and near-degenerate ones (through a vertex or an edge point, inside or
    // just outside, nudged by ulps), each that crosses the plane within its range (plane_contact,
    // exact), its claim (meets, misses) against the oracle.
    support::rng r(support::seed() + 23);
    long n = 0, claimed = 0, one_n = 0, one_claimed = 0, wrong = 0;
    auto check = [&]<class B>(B*, int kind) {
        support::polygon3_store g, other;
        support::mesh_store unused;
        r.at_scale_one = kind == 1;
        const auto b = kind == 2 ? support::polygon3_near<B>(r, g, other, unused) : support::polygon3_random<B>(r, g, other, unused);
        r.at_scale_one = false;
        if (!b || !support::finite_partner(*b)) return;
        const detail::linear3 x = detail::as_linear(*b);
        arith::exact_kernel k;
        sign w = sign::zero;
        if (!detail::polygon3d::usable(k, g.g) || detail::polygon3d::plane_contact(k, g.g, x, w) != detail::polygon3d::contact::crosses)
            return;
        ++n;
        one_n += kind == 1;
        const certainty got = detail::polygon3d::rounded_crossing(g.g, x);
        if (got == certainty::uncertain) return;
        ++claimed;
        one_claimed += kind == 1;
        if ((got == certainty::yes) != support::polygon3_truth(g.g, *b) && ++wrong <= 5)
            std::printf("  rounded crossing stage wrong: %s\n", support::shape_str(*b).c_str());
    };
    for (long i = 0; i < support::cases(30000); ++i) {
        const int kind = int(i % 3);
        switch ((i / 3) % 3) {
        case 0: check(static_cast<segment3*>(nullptr), kind); break;
        case 1: check(static_cast<ray3*>(nullptr), kind); break;
        default: check(static_cast<line3*>(nullptr), kind); break;
        }
    }
    std::printf("[cases] polygon rounded crossing stage: %ld crossing cases, %ld claimed (%ld of %ld random at scale 1), wrong %ld\n", n,
                claimed, one_claimed, one_n, wrong);
    CHECK(wrong == 0);
    CHECK(one_claimed > one_n * 9 / 10);
}
TEST_CASE("point_polygon: rewritten shapes and exact translations give the same answer", "[point_polygon]") {
    support::polygon3_symmetries<point3>("point_polygon", support::cases(5000));
}

} // namespace test_query_point_polygon
