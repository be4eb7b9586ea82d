// Core vocabulary: tiers, certainty logic, vector algebra.
#include <catch2/catch_test_macros.hpp>
import incidence;

namespace test_core_core { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("core: points and vectors", "[core]") {
    const point3 a{1, 2, 3}, b{4, 6, 8};
    CHECK(b - a == vec3{3, 4, 5});
    CHECK(a + (b - a) == b);
    CHECK(dot(vec3{1, 2, 3}, vec3{4, 5, 6}) == 32.0);
    CHECK(cross(vec3{1, 0, 0}, vec3{0, 1, 0}) == vec3{0, 0, 1});
    CHECK(is_finite(point3{0, 0, 0}));
    CHECK_FALSE(is_finite(0.0 / 0.0 + 0.0 * (1.0 / 0.0)));
}
TEST_CASE("core: sign and certainty", "[core]") {
    CHECK(-sign::positive == sign::negative);
    CHECK(sign::negative * sign::negative == sign::positive);
    CHECK(!certainty::yes == certainty::no);
    CHECK(!certainty::uncertain == certainty::uncertain);
    static_assert(tier<exact> && tier<approximate> && !tier<int>);
}

} // namespace test_core_core
