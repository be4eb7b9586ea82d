// The textbook alternatives (modules/query/methods.cppm) on fixtures where plain double is exact:
// each hits what it should, misses what it should, and reports the same parameter as the exact tier.
#include <catch2/catch_test_macros.hpp>
import incidence;
#include "testkit/testing.hpp"

namespace test_query_methods { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("methods: alternatives on clear fixtures", "[methods]") {
    const triangle3 t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const ray3 down{{0.25, 0.25, 2}, {0, 0, -1}}, away{{2, 2, 2}, {0, 0, -1}};
    const auto mt = method::ray_triangle_moller_trumbore(down, t);
    REQUIRE(mt.has_value());
    CHECK(mt->t == intersection(down, t)->t);
    CHECK_FALSE(method::ray_triangle_moller_trumbore(away, t).has_value());
    CHECK(method::ray_triangle_watertight(down, t).has_value());
    CHECK_FALSE(method::ray_triangle_watertight(away, t).has_value());
    const aabb3 b{{0, 0, 0}, {1, 1, 1}};
    const ray3 in{{-1, 0.5, 0.5}, {1, 0, 0}}, off{{-1, 2, 0.5}, {1, 0, 0}};
    const auto slab = method::aabb_ray_slab(b, in);
    REQUIRE(slab.has_value());
    CHECK(slab->t_enter == 1.0);
    CHECK(slab->t_exit == 2.0);
    CHECK_FALSE(method::aabb_ray_slab(b, off).has_value());
    const sphere3 s{{0, 0, 5}, 1};
    const ray3 up{{0, 0, 0}, {0, 0, 1}};
    CHECK(method::ray_sphere_geometric(up, s).has_value());
    CHECK(method::ray_sphere_algebraic(up, s).has_value());
    CHECK_FALSE(method::ray_sphere_geometric(ray3{{0, 0, 0}, {0, 0, -1}}, s).has_value());
}

} // namespace test_query_methods
