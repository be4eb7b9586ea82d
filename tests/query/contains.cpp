// contains() at the front door (modules/query/contains.cppm): closed sets (a boundary point is
// inside), the tiers' one-sided promises and classify_contains on touching and clear cases.
#include <catch2/catch_test_macros.hpp>
import incidence;
#include "testkit/testing.hpp"

namespace test_query_contains { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("contains: closed sets, one-sided tiers, classify_contains", "[contains]") {
    const tetrahedron3 tet{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const segment3 on_face{{0.25, 0.25, 0}, {0.5, 0.25, 0}}; // in the face z = 0: inside (closed)
    CHECK(contains<exact>(tet, on_face));
    CHECK(contains<conservative>(tet, on_face));
    CHECK(classify_contains(tet, on_face) != certainty::no);
    const segment3 poking{{0.25, 0.25, 0.25}, {0.25, 0.25, -0x1p-60}}; // one end just below the face
    CHECK_FALSE(contains<exact>(tet, poking));
    CHECK_FALSE(contains<aggressive>(tet, poking));
    const segment3 deep{{0.1, 0.1, 0.1}, {0.2, 0.1, 0.1}};
    CHECK(classify_contains(tet, deep) == certainty::yes);
    CHECK((contains<exact>(tet, deep) && contains<aggressive>(tet, deep) && contains<approximate>(tet, deep)));
    const aabb3 box{{0, 0, 0}, {1, 1, 1}};
    CHECK(contains(box, aabb3{{0, 0, 0}, {1, 1, 1}})); // a box holds itself
    CHECK_FALSE(contains(aabb3{{0, 0, 0}, {1, 1, 0.5}}, box));
}

} // namespace test_query_contains
