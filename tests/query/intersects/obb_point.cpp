// obb3 x point3: the three face normals of the parallelepiped in every tier; the exact LP oracle
// on 20,000 random and 20,000 near-degenerate cases (points on corners, edges and faces or a
// quarter off, flat boxes, skew and near-rotated frames, ulp nudges, 2^+-500), rewritten axes.
// contains(obb, point) (the same test) against exact rationals (the vertices or the inner box's
// corners by Cramer's rule in the box's frame) on 10,000 random and 10,000 cases inside, on the
// boundary from inside or just beyond it.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_obb_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_point"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<obb3, point3> near_case(support::rng& r) { return support::obb_case<obb3, point3>::near(r); }
std::pair<obb3, point3> random_case(support::rng& r) { return support::obb_case<obb3, point3>::random(r); }
std::vector<std::pair<obb3, point3>> variants(const obb3& a, const point3& b, support::rng& r) {
    (void)r;
    return {{support::rewritten(a, 0), b}, {support::rewritten(a, 1), b}};
}
} // namespace

TEST_CASE("obb_point: fixtures", "[obb_point]") {
    const obb3 D{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(D, point3{2, 0, 0})); // a corner of the rotated (and scaled) box
    CHECK_FALSE(intersects(D, point3{2.0000000000000004, 0, 0}));
    CHECK(intersects(point3{1, 1, 1}, D)); // on an edge
    CHECK_FALSE(intersects(obb3{{0, 0, 0}, D.axes, {1, 1, -0.0 - 1}}, point3{0, 0, 0}));
}
TEST_CASE("obb_point: oracle", "[obb_point][oracle]") {
    support::run_obb_pair<obb3, point3>("obb_point", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("obb_point: rewritten shapes give the same answer", "[obb_point]") {
    support::run_rewritten<obb3, point3>("obb_point", support::cases(20000), near_case, random_case, variants);
}

TEST_CASE("obb_point: contains(obb, point)", "[obb_point][oracle]") {
    support::contains_oracle<obb3, point3>(
        "obb_point (obb around point)", support::cases(10000), approx_bound,
        [](support::rng& r) { return support::obb_case<obb3, point3>::random(r); }, support::obb_holding<point3>);
}

} // namespace test_query_obb_point
