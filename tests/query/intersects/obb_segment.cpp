// obb3 x segment3: the six separating axes in every tier; the exact LP oracle on 20,000 random
// and 20,000 near-degenerate cases (segments ending on, starting at, or passing through a corner,
// edge or face point, flat boxes, skew frames, ulp nudges, 2^+-500), reversed end points and
// rewritten axes.
// contains(obb, segment) against exact rationals (the vertices or the inner box's corners by
// Cramer's rule in the box's frame) on 10,000 random and 10,000 cases inside, on the boundary from
// inside or just beyond it.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_obb_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_segment"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<obb3, segment3> near_case(support::rng& r) { return support::obb_case<obb3, segment3>::near(r); }
std::pair<obb3, segment3> random_case(support::rng& r) { return support::obb_case<obb3, segment3>::random(r); }
std::vector<std::pair<obb3, segment3>> variants(const obb3& a, const segment3& b, support::rng& r) {
    (void)r;
    return {{support::rewritten(a, 0), b}, {support::rewritten(a, 1), segment3{b.b, b.a}}};
}
} // namespace

TEST_CASE("obb_segment: fixtures", "[obb_segment]") {
    const obb3 D{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(D, segment3{{2, 0, 0}, {3, 0, 0}})); // starts at a corner
    CHECK_FALSE(intersects(D, segment3{{2.0000000000000004, 0, 0}, {3, 0, 0}}));
    CHECK(intersects(D, segment3{{2, 0, -5}, {2, 0, 5}})); // along the vertical edge at x = 2
    CHECK(intersects(D, segment3{{-3, 0, 0}, {3, 0, 0}})); // through the box
    CHECK(intersects(segment3{{0, 0, 0}, {0, 0, 0}}, D));  // a point segment inside
}
TEST_CASE("obb_segment: oracle", "[obb_segment][oracle]") {
    support::run_obb_pair<obb3, segment3>("obb_segment", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("obb_segment: rewritten shapes give the same answer", "[obb_segment]") {
    support::run_rewritten<obb3, segment3>("obb_segment", support::cases(20000), near_case, random_case, variants);
}

TEST_CASE("obb_segment: contains(obb, segment)", "[obb_segment][oracle]") {
    support::contains_oracle<obb3, segment3>(
        "obb_segment (obb around segment)", support::cases(10000), approx_bound,
        [](support::rng& r) { return support::obb_case<obb3, segment3>::random(r); }, support::obb_holding<segment3>);
}

} // namespace test_query_obb_segment
