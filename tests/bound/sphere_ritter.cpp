// sphere_ritter: every point inside (CGAL exact rationals) after outward rounding; within
// Ritter's usual 5-20% of the minimum sphere on real meshes (measured, reported).
#include <catch2/catch_test_macros.hpp>
#include <span>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"
#include "testkit/sphere_checks.hpp"

namespace test_bound_sphere_ritter { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("sphere_ritter: every generated and real set", "[bound][sphere_ritter]") {
    support::rng r(support::seed());
    auto sets = support::point_sets(r, support::cases(2000));
    for (auto& m : support::real_meshes()) sets.push_back(std::move(m));
    for (const auto& s : sets) {
        INFO(s.name);
        const std::span<const point3> pts(s.points);
        const auto q = bound::sphere_ritter(pts);
        REQUIRE(q);
        CHECK(support::all_inside(pts, q.value()));
        const auto w = bound::sphere_welzl(pts);
        REQUIRE(w);
        CHECK(q.value().radius >= w.value().sphere.radius * (1 - 1e-12));
        std::printf("[cases] sphere_ritter %s: radius / minimum radius = %.4f\n", s.name.c_str(),
                    w.value().sphere.radius > 0 ? q.value().radius / w.value().sphere.radius : 1.0);
    }
    CHECK(bound::sphere_ritter(std::span<const point3>()).error().code == errc::empty_input);
}

} // namespace test_bound_sphere_ritter
