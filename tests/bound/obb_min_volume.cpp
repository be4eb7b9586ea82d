// obb_min_volume: every point inside the returned box (CGAL exact rationals, and the library's exact test),
// axes orthonormal within 1e-6 (obb3::make accepts the box), on generated, degenerate and real
// point sets; the volume against CGAL's oriented_bounding_box on the real meshes (printed).
#include <catch2/catch_test_macros.hpp>
#include <span>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"
#include "testkit/box_checks.hpp"

namespace test_bound_obb_min_volume { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("obb_min_volume: every generated and real set", "[bound][obb_min_volume]") {
    support::check_obb_construction("obb_min_volume", [](std::span<const point3> pts) { return bound::obb_min_volume(pts); });
}

} // namespace test_bound_obb_min_volume
