// line3 x obb3: the three axes d x a_i in every tier; the exact LP oracle on 20,000 random and
// 20,000 near-degenerate cases (lines through a corner, edge or face point, in face planes, flat
// boxes, skew frames, ulp nudges, 2^+-500), reversed directions and rewritten axes.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"

namespace test_query_line_obb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_obb"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<line3, obb3> near_case(support::rng& r) { return support::obb_case<line3, obb3>::near(r); }
std::pair<line3, obb3> random_case(support::rng& r) { return support::obb_case<line3, obb3>::random(r); }
std::vector<std::pair<line3, obb3>> variants(const line3& a, const obb3& b, support::rng& r) {
    (void)r;
    return {{a, support::rewritten(b, 0)},
            {line3{a.origin, vec3{-a.direction.x, -a.direction.y, -a.direction.z}}, support::rewritten(b, 1)}};
}
} // namespace

TEST_CASE("line_obb: fixtures", "[line_obb]") {
    const obb3 D{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(line3{{2, 0, 7}, {0, 0, 1}}, D)); // along the vertical edge through (2, 0)
    CHECK_FALSE(intersects(line3{{2.0000000000000004, 0, 7}, {0, 0, 1}}, D));
    CHECK(intersects(line3{{5, 0, 0}, {1, 0, 0}}, D));   // the x axis, through the box
    CHECK(intersects(D, line3{{4, -2, 1}, {-1, 1, 0}})); // in the plane z = 1 along the face x + y = 2
}
TEST_CASE("line_obb: oracle", "[line_obb][oracle]") {
    support::run_obb_pair<line3, obb3>("line_obb", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("line_obb: rewritten shapes give the same answer", "[line_obb]") {
    support::run_rewritten<line3, obb3>("line_obb", support::cases(20000), near_case, random_case, variants);
}

} // namespace test_query_line_obb
