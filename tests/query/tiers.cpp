// The tier driver (modules/query/tiers.cppm): on an exactly touching case, where the filter cannot
// decide, conservative says yes, aggressive no, exact the truth, classify uncertain; on every case
// classify never contradicts exact; a conservative value hit that is not sure says so, and one exact
// has is never missed.
#include <catch2/catch_test_macros.hpp>
import incidence;
#include "testkit/testing.hpp"

namespace test_query_tiers { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("tiers: the driver maps the filter's verdict per tier", "[tiers]") {
    const triangle3 t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    // grazing an edge exactly: the filter cannot prove the zero, exact can
    const ray3 edge{{0.5, 0, 1}, {0, 0, -1}};
    CHECK(classify(edge, t) == certainty::uncertain);
    CHECK(intersects<exact>(edge, t));
    CHECK(intersects<conservative>(edge, t));
    CHECK_FALSE(intersects<aggressive>(edge, t));
    // just beside the edge, outside: exact no; whatever the filter proves, classify never
    // contradicts exact and aggressive never says yes
    const ray3 beside{{0.5, -0x1p-53, 1}, {0, 0, -1}};
    CHECK_FALSE(intersects<exact>(beside, t));
    CHECK(classify(beside, t) != certainty::yes);
    CHECK(intersects<conservative>(beside, t) == (classify(beside, t) == certainty::uncertain));
    CHECK_FALSE(intersects<aggressive>(beside, t));
    // clear cases: every tier agrees with classify
    const ray3 through{{0.25, 0.25, 1}, {0, 0, -1}}, away{{2, 2, 1}, {0, 0, -1}};
    CHECK(classify(through, t) == certainty::yes);
    CHECK((intersects<exact>(through, t) && intersects<conservative>(through, t) && intersects<aggressive>(through, t) &&
           intersects<approximate>(through, t)));
    CHECK(classify(away, t) == certainty::no);
    CHECK_FALSE((intersects<exact>(away, t) || intersects<conservative>(away, t) || intersects<aggressive>(away, t) ||
                 intersects<approximate>(away, t)));
}

TEST_CASE("tiers: values on a touching case are enclosed or absent, never made up", "[tiers]") {
    const triangle3 t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const ray3 beside{{0.5, -0x1p-53, 1}, {0, 0, -1}}; // misses by one ulp
    CHECK_FALSE(intersection<exact>(beside, t).has_value());
    CHECK_FALSE(intersection<aggressive>(beside, t).has_value());
    const auto c = intersection<conservative>(beside, t);
    if (c) CHECK(c->exists == certainty::uncertain); // only a hit it could not exclude
    const auto c_edge = intersection<conservative>(ray3{{0.5, 0, 1}, {0, 0, -1}}, t);
    REQUIRE(c_edge.has_value());              // exact says hit: conservative never misses it
    const ray3 edge{{0.5, 0, 1}, {0, 0, -1}}; // hits at t = 1 exactly
    const auto e = intersection<exact>(edge, t);
    REQUIRE(e.has_value());
    CHECK(e->t == 1.0);
    const auto ce = intersection<conservative>(edge, t);
    REQUIRE(ce.has_value());
    CHECK((ce->t.lo <= 1.0 && 1.0 <= ce->t.hi));
}

} // namespace test_query_tiers
