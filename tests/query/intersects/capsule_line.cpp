// capsule3 x line3: fixtures (skew and parallel lines at distance 5; one ulp short; a zero
// direction); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the line, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic lines at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_line { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_line"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_line: fixtures", "[capsule_line]") {
    const capsule3 c{{0, 0, 0}, {10, 0, 0}, 5};
    CHECK(intersects(c, line3{{5, 7, 5}, {0, 1, 0}}));
    CHECK_FALSE(intersects(c, line3{{5, 7, 0x1.4000000000001p+2}, {0, 1, 0}}));
    CHECK(intersects(line3{{-100, 3, 4}, {1, 0, 0}}, c)); // parallel
    CHECK_FALSE(intersects(line3{{-100, 3, 0x1.0000000000001p+2}, {1, 0, 0}}, c));
    CHECK(intersects(c, line3{{13, 4, 0}, {0, 0, 0}})); // a point
    CHECK(intersects(c, line3{{20, 0, 5}, {-1, 0, 0}}));
}
TEST_CASE("capsule_line: oracle, random and near-degenerate", "[capsule_line][oracle]") {
    support::capsule_oracle<line3>("capsule_line", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_line
