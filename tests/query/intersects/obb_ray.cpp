// obb3 x ray3: generalised slabs as six separating axes in every tier; the exact LP oracle on
// 20,000 random and 20,000 near-degenerate cases (rays aimed at or starting on a corner, edge or
// face point, flat boxes, skew frames, ulp nudges, 2^+-500), and rewritten axes.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"

namespace test_query_obb_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_ray"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<obb3, ray3> near_case(support::rng& r) { return support::obb_case<obb3, ray3>::near(r); }
std::pair<obb3, ray3> random_case(support::rng& r) { return support::obb_case<obb3, ray3>::random(r); }
std::vector<std::pair<obb3, ray3>> variants(const obb3& a, const ray3& b, support::rng& r) {
    (void)r;
    return {{support::rewritten(a, 0), b}, {support::rewritten(a, 1), b}};
}
} // namespace

TEST_CASE("obb_ray: fixtures", "[obb_ray]") {
    const obb3 D{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(D, ray3{{3, 0, 0}, {-1, 0, 0}}));      // reaches the corner (2, 0, 0)
    CHECK_FALSE(intersects(D, ray3{{3, 0, 0}, {1, 0, 0}})); // pointing away
    CHECK(intersects(D, ray3{{3, 1, 0}, {-1, 0, 0}}));      // along the face x + y = 2, through the corner (1, 1, 0)
    CHECK(intersects(ray3{{0, 0, 0}, {0, 0, 0}}, D));       // a zero direction is its origin, inside
}
TEST_CASE("obb_ray: oracle", "[obb_ray][oracle]") {
    support::run_obb_pair<obb3, ray3>("obb_ray", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("obb_ray: rewritten shapes give the same answer", "[obb_ray]") {
    support::run_rewritten<obb3, ray3>("obb_ray", support::cases(20000), near_case, random_case, variants);
}

} // namespace test_query_obb_ray
