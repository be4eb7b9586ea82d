// line3 x tetrahedron3: fixtures (through the solid, through one vertex, along an edge, one ulp
// beside a vertex, in a face's plane, coplanar tetrahedra, NaN); the CGAL Epeck oracle
// (Tetrahedron_3; the exact LP for coplanar tetrahedra) on 20,000 random and 20,000
// near-degenerate cases (through a vertex, an edge or face point, inside or just outside; lines in
// and parallel to a face's plane; zero directions and coplanar tetrahedra; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, negated and doubled
// directions, rotated and reflected vertex orders, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "../oracle/cgal_oracle.hpp"
import incidence;
#include "../support/testing.hpp"
#include "../support/check.hpp"
#include "../support/flat_checks.hpp"

namespace test_query_line_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
constexpr double approx_bound = 0x1p-40; // stated in modules/query/line_tetrahedron.cppm
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("line_tetrahedron: fixtures", "[line_tetrahedron]") {
    CHECK(intersects(line3{{-5, 0.2, 0.2}, {-1, 0, 0}}, T));                   // through it, origin behind
    CHECK(intersects(line3{{0, 0, 1}, {1, 1, 0}}, T));                         // through the vertex only
    CHECK_FALSE(intersects(line3{{0, 0, 0x1.0000000000001p0}, {1, 1, 0}}, T)); // one ulp above it
    CHECK(intersects(T, line3{{7, 0, 0}, {3, 0, 0}}));                         // along an edge
    CHECK(intersects(line3{{-1, 0.5, 0}, {1, 0, 0}}, T));                      // in the face z = 0
    CHECK_FALSE(intersects(line3{{-1, 0.5, -0x1p-1074}, {1, 0, 0}}, T));
    CHECK(intersects(line3{{1, 1, 1}, {-1, -1, -1}}, T));                      // through the slanted face and a vertex
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(line3{{0.5, 0.5, 3}, {0, 0, 1}}, flat));
    CHECK_FALSE(intersects(line3{{1.5, 1.5, 3}, {0, 0, 1}}, flat));
    CHECK_FALSE(intersects(line3{{std::nan(""), 0.2, 0.2}, {1, 0, 0}}, T));
}
TEST_CASE("line_tetrahedron: oracle, random and near-degenerate", "[line_tetrahedron][oracle]") {
    support::flat_oracle<line3, tetrahedron3>("line_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("line_tetrahedron: rewrites of either shape and exact translations give the same answer", "[line_tetrahedron]") {
    support::flat_symmetries<line3, tetrahedron3>("line_tetrahedron", support::cases(20000));
}

} // namespace test_query_line_tetrahedron
