// detail::exactly<Body, R>(a, b) (modules/query/exactly.cppm): the exact tier's out-of-line re-run,
// compiled once in the library. On touching cases, where the filter leaves a sign open and the tiers
// call it, it gives the exact answer: the same as the exact tier's front door, in constant
// evaluation (where the definition is visible) and at run time (the library's instance), for a
// yes/no pair, a value pair and both distances.
#include <catch2/catch_test_macros.hpp>
#include <optional>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"

namespace test_query_exactly { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using detail::exactly;

// A segment whose end point lies on the triangle's hypotenuse, and one that stops 2^-60 above it.
constexpr triangle3 tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
constexpr segment3 touching{{0.5, 0.5, 1}, {0.5, 0.5, 0}};
constexpr segment3 short_of{{0.5, 0.5, 1}, {0.5, 0.5, 0x1p-60}};
// A ray that grazes the unit box's face y = 1, entering at x = 0 (t = 1).
constexpr aabb3 box{{0, 0, 0}, {1, 1, 1}};
constexpr ray3 grazing{{-1, 1, 0.5}, {1, 0, 0}};

static_assert(exactly<detail::intersects_body, bool>(touching, tri));
static_assert(!exactly<detail::intersects_body, bool>(short_of, tri));

TEST_CASE("exactly: the exact re-run gives the exact tier's answer on touching cases", "[exactly]") {
    // yes/no: the library's instance against the front door, and the known answer
    CHECK(exactly<detail::intersects_body, bool>(touching, tri));
    CHECK(!exactly<detail::intersects_body, bool>(short_of, tri));
    CHECK(intersects<exact>(touching, tri) == exactly<detail::intersects_body, bool>(touching, tri));
    CHECK(intersects<exact>(short_of, tri) == exactly<detail::intersects_body, bool>(short_of, tri));
    CHECK(classify(touching, tri) != certainty::no);

    // a value: the span of the grazing ray, t_enter = 1 and t_exit = 2, the entry point (0, 1, 0.5)
    const auto h = exactly<detail::intersection_body, std::optional<span_hit<double>>>(box, grazing);
    REQUIRE(h.has_value());
    CHECK(h->exists == certainty::yes);
    CHECK(h->t_enter == 1.0);
    CHECK(h->t_exit == 2.0);
    CHECK(h->point.x == 0.0);
    CHECK(h->point.y == 1.0);
    CHECK(h->point.z == 0.5);
    const auto front = intersection<exact>(box, grazing);
    REQUIRE(front.has_value());
    CHECK(front->t_enter == h->t_enter);
    CHECK(front->t_exit == h->t_exit);

    // the distances of a point outside the box: nearest (1, 0.5, 0.5), farthest (0, 0 or 1, 0 or 1)
    const point3 p{2, 0.5, 0.5};
    CHECK(exactly<detail::nearest_body, double>(box, p) == 1.0);
    CHECK(exactly<detail::farthest_body, double>(box, p) == 4.5);
    CHECK(squared_distance<exact>(box, p) == exactly<detail::nearest_body, double>(box, p));
    CHECK(max_squared_distance<exact>(box, p) == exactly<detail::farthest_body, double>(box, p));
}

} // namespace test_query_exactly
