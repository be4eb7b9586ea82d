// plane3 x tetrahedron3: fixtures (through a vertex, one ulp past it, a face's plane, cutting it,
// zero normals, coplanar tetrahedra, NaN); the CGAL Epeck oracle (Tetrahedron_3; the exact LP for
// coplanar tetrahedra) on 20,000 random and 20,000 near-degenerate cases (planes through a vertex,
// an edge or face point, inside or just outside; planes containing an edge direction; then a
// random exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, negated and
// doubled planes, rotated and reflected vertex orders, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_plane_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("plane_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("plane_tetrahedron: fixtures", "[plane_tetrahedron]") {
    CHECK(intersects(plane3{{0, 0, 1}, 1}, T));                         // the top vertex
    CHECK_FALSE(intersects(plane3{{0, 0, 1}, 0x1.0000000000001p0}, T)); // one ulp above it
    CHECK(intersects(T, plane3{{1, 1, 1}, 1}));                         // the slanted face
    CHECK(intersects(plane3{{1, 1, 1}, 0.5}, T));                       // cutting it
    CHECK_FALSE(intersects(plane3{{1, 1, 1}, -0x1p-1074}, T));          // a subnormal below the corner
    CHECK(intersects(plane3{{0, 0, 0}, 0}, T));                         // a zero normal, offset 0: everything
    CHECK_FALSE(intersects(plane3{{0, 0, 0}, 1}, T));                   // nothing
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(plane3{{1, 0, 0}, 2}, flat));
    CHECK_FALSE(intersects(plane3{{1, 0, 0}, 0x1.0000000000001p1}, flat));
    CHECK_FALSE(intersects(plane3{{0, 0, 1}, 1}, tetrahedron3{T.a, T.b, T.c, {0, 0, std::nan("")}}));
}
TEST_CASE("plane_tetrahedron: oracle, random and near-degenerate", "[plane_tetrahedron][oracle]") {
    support::flat_oracle<plane3, tetrahedron3>("plane_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("plane_tetrahedron: rewrites of either shape and exact translations give the same answer", "[plane_tetrahedron]") {
    support::flat_symmetries<plane3, tetrahedron3>("plane_tetrahedron", support::cases(20000));
}

} // namespace test_query_plane_tetrahedron
