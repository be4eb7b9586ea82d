// ray3 x tetrahedron3: fixtures (from inside, from outside towards and away from it, grazing an
// edge, one ulp beside it, coplanar tetrahedra, NaN); the CGAL Epeck oracle (Tetrahedron_3; the
// exact LP for coplanar tetrahedra) on 20,000 random and 20,000 near-degenerate cases (origin or
// a point ahead or behind at a vertex, an edge or face point, inside or just outside; rays in and
// parallel to a face's plane; zero directions and coplanar tetrahedra; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, doubled directions,
// rotated and reflected vertex orders, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_ray_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("ray_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("ray_tetrahedron: fixtures", "[ray_tetrahedron]") {
    CHECK(intersects(ray3{{0.1, 0.1, 0.1}, {1, 2, 3}}, T));       // from inside
    CHECK(intersects(ray3{{-1, 0.2, 0.2}, {1, 0, 0}}, T));        // towards it
    CHECK_FALSE(intersects(ray3{{-1, 0.2, 0.2}, {-1, 0, 0}}, T)); // away from it
    CHECK(intersects(T, ray3{{2, 0, 0}, {-1, 0, 0}}));            // along an edge line, towards
    CHECK_FALSE(intersects(T, ray3{{2, 0, 0}, {1, 0, 0}}));       // along it, away
    CHECK(intersects(ray3{{0.5, 0.5, 5}, {0, 0, -1}}, T));        // down onto an edge point
    CHECK_FALSE(intersects(ray3{{0.5, 0x1.0000000000001p-1, 5}, {0, 0, -1}}, T));
    CHECK(intersects(ray3{{0.25, 0.25, 0.25}, {0, 0, 0}}, T)); // a zero direction: a point inside
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(ray3{{-1, 0.5, 0}, {1, 0, 0}}, flat)); // in its plane
    CHECK_FALSE(intersects(ray3{{-1, 0.5, 0x1p-1000}, {1, 0, 0}}, flat));
    CHECK_FALSE(intersects(ray3{{-1, 0.2, 0.2}, {1, 0, std::nan("")}}, T));
}
TEST_CASE("ray_tetrahedron: oracle, random and near-degenerate", "[ray_tetrahedron][oracle]") {
    support::flat_oracle<ray3, tetrahedron3>("ray_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("ray_tetrahedron: rewrites of either shape and exact translations give the same answer", "[ray_tetrahedron]") {
    support::flat_symmetries<ray3, tetrahedron3>("ray_tetrahedron", support::cases(20000));
}

} // namespace test_query_ray_tetrahedron
