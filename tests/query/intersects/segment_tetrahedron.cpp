// segment3 x tetrahedron3: fixtures (crossing the solid, touching an edge, one ulp beside it,
// inside, along a face, coplanar tetrahedra, NaN); the CGAL Epeck oracle (Tetrahedron_3; the exact
// LP for coplanar tetrahedra) on 20,000 random and 20,000 near-degenerate cases (touching at an
// end point, a vertex, an edge or face point, crossing, just missing; parallel to and in a face's
// plane; point segments and coplanar tetrahedra; then a random exact-or-nudged scale
// 2^-500..2^500 and translation); both argument orders, reversed segments, rotated and reflected
// vertex orders, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_segment_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("segment_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("segment_tetrahedron: fixtures", "[segment_tetrahedron]") {
    CHECK(intersects(segment3{{-1, 0.2, 0.2}, {2, 0.2, 0.2}}, T)); // through two faces
    CHECK(intersects(segment3{{0.5, 0.5, -1}, {0.5, 0.5, 1}}, T)); // through an edge point
    CHECK_FALSE(intersects(segment3{{0.5, 0x1.0000000000001p-1, -1}, {0.5, 0x1.0000000000001p-1, 1}}, T));
    CHECK(intersects(T, segment3{{0.1, 0.1, 0.1}, {0.2, 0.2, 0.2}}));                  // inside
    CHECK(intersects(segment3{{-1, 0.5, 0}, {1, 0.5, 0}}, T));                         // in the face z = 0
    CHECK_FALSE(intersects(segment3{{-1, 0.5, -0x1p-1074}, {1, 0.5, -0x1p-1074}}, T)); // a subnormal below it
    CHECK(intersects(segment3{{1, 0, 0}, {2, 0, 0}}, T));                              // ends at a vertex
    CHECK_FALSE(intersects(segment3{{-1, 0.2, 0.2}, {-0.5, 0.2, 0.2}}, T));            // short of it
    CHECK(intersects(segment3{{0.5, 0.5, 0}, {0.5, 0.5, 0}}, T));                      // a point segment on an edge
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(segment3{{0.5, 0.5, -1}, {0.5, 0.5, 1}}, flat));
    CHECK_FALSE(intersects(segment3{{1.5, 1.5, -1}, {1.5, 1.5, 1}}, flat));
    CHECK_FALSE(intersects(segment3{{-1, 0.2, 0.2}, {2, 0.2, std::nan("")}}, T));
}
TEST_CASE("segment_tetrahedron: oracle, random and near-degenerate", "[segment_tetrahedron][oracle]") {
    support::flat_oracle<segment3, tetrahedron3>("segment_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("segment_tetrahedron: rewrites of either shape and exact translations give the same answer", "[segment_tetrahedron]") {
    support::flat_symmetries<segment3, tetrahedron3>("segment_tetrahedron", support::cases(20000));
}

} // namespace test_query_segment_tetrahedron
