// contains(obb3, capsule3): fixtures (a capsule along a turned box's axis touching its top and
// bottom faces from inside, and one ulp too wide; an end outside); the box around both end balls in
// exact rationals (contains_truth) on 10,000 random cases and 10,000 capsules grown inside balls
// that boxes hold, some touching from inside (testkit/capsule_checks.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_obb_capsule { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_capsule"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("obb_capsule: fixtures", "[obb_capsule]") {
    // turned 45 degrees about z: the side faces at sqrt 2 from the axis, the top and bottom at z = +-2
    const obb3 T{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 2}};
    CHECK(contains(T, capsule3{{0, 0, -1}, {0, 0, 1}, 1}));
    CHECK_FALSE(contains(T, capsule3{{0, 0, -1}, {0, 0, 1}, 0x1.0000000000001p+0}));
    CHECK_FALSE(contains(T, capsule3{{0, 0, -1}, {0, 0, 3}, 0}));           // an end outside
    CHECK(contains(T, capsule3{{0, 0, 0}, {0, 0, 0}, 1.4142135623730949})); // a ball, just inside the sides
    CHECK_FALSE(contains(T, capsule3{{0, 0, 0}, {0, 0, __builtin_nan("")}, 0}));
}
TEST_CASE("obb_capsule: contains", "[obb_capsule][oracle]") {
    support::capsule_contained<obb3>("obb_capsule", support::cases(10000), approx_bound);
}

} // namespace test_query_obb_capsule
