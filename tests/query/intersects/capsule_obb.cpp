// capsule3 x obb3: fixtures (a capsule's middle nearest a turned box's corner by a 3-4-5 step, its
// segment across a vertical edge, an end ball at a corner, each touching and one ulp short; through
// the box; above a flat box; NaN and negative numbers); every tier against the exact QP (CGAL's
// QP_solver over Gmpzf: the squared distance between the capsule's segment and the box, against
// the radius) on 10,000 random cases and 10,000 capsules grown from balls touching small dyadic
// boxes (signed-permutation, near-rotation and skew frames, zero extents) at a corner, an edge or
// a face, exactly or within ulps, at a random scale (testkit/capsule_cases.hpp).
// contains(obb3, capsule3): fixtures (a capsule along a turned box's axis touching its top and
// bottom faces from inside, and one ulp too wide; an end outside); the box around both end balls in
// exact rationals (contains_truth) on 10,000 random cases and 10,000 capsules grown inside balls
// that boxes hold, some touching from inside (testkit/capsule_checks.hpp).
// contains(capsule3, obb3): fixtures (a turned box whose corners touch the capsule's end caps, a
// box whose corners lie on its cylinder, each one ulp too narrow); the box's corners against the
// segment in exact rationals (oracle::box_in_capsule) on 10,000 random cases and 10,000 boxes
// along a capsule's segment with corners on its cylinder or inside, in coordinate frames and in a
// frame turned about the segment.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_obb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_obb"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_obb: fixtures", "[capsule_obb]") {
    // turned 45 degrees about z: the side faces at sqrt 2 from the axis, the top and bottom at z = +-2
    const obb3 T{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 2}};
    CHECK(contains(T, capsule3{{0, 0, -1}, {0, 0, 1}, 1}));
    CHECK_FALSE(contains(T, capsule3{{0, 0, -1}, {0, 0, 1}, 0x1.0000000000001p+0}));
    CHECK_FALSE(contains(T, capsule3{{0, 0, -1}, {0, 0, 3}, 0}));           // an end outside
    CHECK(contains(T, capsule3{{0, 0, 0}, {0, 0, 0}, 1.4142135623730949})); // a ball, just inside the sides
    CHECK_FALSE(contains(T, capsule3{{0, 0, 0}, {0, 0, __builtin_nan("")}, 0}));
}
TEST_CASE("capsule_obb: intersects fixtures", "[capsule_obb]") {
    // turned 45 degrees about z: the corners (+-2, 0, +-2) and (0, +-2, +-2)
    const obb3 T{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 2}};
    CHECK(intersects(T, capsule3{{5, -5, 6}, {5, 5, 6}, 5})); // its middle nearest the corner (2, 0, 2): (3, 0, 4) away
    CHECK_FALSE(intersects(T, capsule3{{5, -5, 6}, {5, 5, 6}, 0x1.3ffffffffffffp2}));
    CHECK(intersects(capsule3{{5, -4, 0}, {5, 4, 0}, 3}, T)); // across the vertical edge at (2, 0)
    CHECK_FALSE(intersects(capsule3{{5, -4, 0}, {5, 4, 0}, 0x1.7ffffffffffffp1}, T));
    CHECK(intersects(T, capsule3{{5, 0, 6}, {9, 0, 10}, 5})); // the end (5, 0, 6) nearest the corner
    CHECK_FALSE(intersects(T, capsule3{{5, 0, 6}, {9, 0, 10}, 0x1.3ffffffffffffp2}));
    CHECK(intersects(T, capsule3{{-5, 0, 0}, {5, 0, 0}, 0})); // through it
    CHECK(intersects(T, capsule3{{5, 0, 6}, {5, 0, 6}, 5}));  // a ball
    CHECK_FALSE(intersects(T, capsule3{{5, 0, 6}, {5, 0, 6}, 0x1.3ffffffffffffp2}));
    const obb3 F{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 0}}; // a flat square
    CHECK(intersects(F, capsule3{{-5, 0, 3}, {5, 0, 3}, 3}));
    CHECK_FALSE(intersects(F, capsule3{{-5, 0, 3}, {5, 0, 3}, 0x1.7ffffffffffffp1}));
    CHECK(intersects(F, capsule3{{-5, 0, 3}, {5, 0, 3}, -3})); // an unchecked negative radius acts as |r|
    CHECK_FALSE(intersects(F, capsule3{{-5, 0, 3}, {5, 0, 3}, __builtin_nan("")}));
    CHECK_FALSE(intersects(obb3{{0, 0, 0}, F.axes, {1, -1, 0}}, capsule3{{0, 0, 0}, {1, 0, 0}, 1}));
}
TEST_CASE("capsule_obb: oracle, random and near-degenerate", "[capsule_obb][oracle]") {
    support::capsule_oracle<obb3>("capsule_obb", support::cases(10000), approx_bound);
}
TEST_CASE("capsule_obb: capsule contains box, fixtures", "[capsule_obb]") {
    const obb3 T{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 2}};
    CHECK(contains(capsule3{{0, 0, -2}, {0, 0, 2}, 2}, T)); // the corners (2, 0, +-2) on the end caps
    CHECK_FALSE(contains(capsule3{{0, 0, -2}, {0, 0, 2}, 0x1.fffffffffffffp0}, T));
    CHECK_FALSE(contains(capsule3{{0, 0, -1}, {0, 0, 1}, 2}, T));
    const obb3 B{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {3, 4, 1}};
    CHECK(contains(capsule3{{0, 0, -1}, {0, 0, 1}, 5}, B)); // every corner on the cylinder
    CHECK_FALSE(contains(capsule3{{0, 0, -1}, {0, 0, 1}, 0x1.3ffffffffffffp2}, B));
    CHECK(contains(capsule3{{0, 0, 0}, {0, 0, 0}, 5}, obb3{{0, 0, 0}, B.axes, {3, 4, 0}})); // a ball and a flat box
    CHECK_FALSE(contains(capsule3{{0, 0, 0}, {0, 0, 0}, 0x1.3ffffffffffffp2}, obb3{{0, 0, 0}, B.axes, {3, 4, 0}}));
    CHECK_FALSE(contains(capsule3{{0, 0, -1}, {0, 0, 1}, 5}, obb3{{0, 0, 0}, B.axes, {3, 4, __builtin_nan("")}}));
}
TEST_CASE("capsule_obb: contains", "[capsule_obb][oracle]") {
    support::capsule_contained<obb3>("capsule_obb", support::cases(10000), approx_bound);
    support::capsule_contains<obb3>("capsule_obb", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_obb
