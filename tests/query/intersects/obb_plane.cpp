// obb3 x plane3: one sign of degree 3 in every tier; the exact LP oracle on 20,000 random and
// 20,000 near-degenerate cases (planes through a corner, edge or face point, flat boxes, skew
// frames, ulp nudges, 2^+-500), rewritten axes and a negated plane.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"

namespace test_query_obb_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_plane"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<obb3, plane3> near_case(support::rng& r) { return support::obb_case<obb3, plane3>::near(r); }
std::pair<obb3, plane3> random_case(support::rng& r) { return support::obb_case<obb3, plane3>::random(r); }
std::vector<std::pair<obb3, plane3>> variants(const obb3& a, const plane3& b, support::rng& r) {
    (void)r;
    return {{support::rewritten(a, 0), b}, {support::rewritten(a, 1), plane3{vec3{-b.normal.x, -b.normal.y, -b.normal.z}, -b.offset}}};
}
} // namespace

TEST_CASE("obb_plane: fixtures", "[obb_plane]") {
    const obb3 D{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(D, plane3{{1, 0, 0}, 2})); // x = 2 touches the corner edge
    CHECK_FALSE(intersects(D, plane3{{1, 0, 0}, 2.0000000000000004}));
    CHECK(intersects(plane3{{1, 1, 0}, 2}, D));       // x + y = 2 holds a face
    CHECK(intersects(D, plane3{{0, 0, 0}, 0}));       // the zero plane is everything
    CHECK_FALSE(intersects(D, plane3{{0, 0, 0}, 1})); // and nothing
}
TEST_CASE("obb_plane: oracle", "[obb_plane][oracle]") {
    support::run_obb_pair<obb3, plane3>("obb_plane", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("obb_plane: rewritten shapes give the same answer", "[obb_plane]") {
    support::run_rewritten<obb3, plane3>("obb_plane", support::cases(20000), near_case, random_case, variants);
}

} // namespace test_query_obb_plane
