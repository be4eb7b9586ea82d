// tetrahedron3 x tetrahedron3: fixtures (sharing a vertex, one ulp apart, sharing a face, one
// inside the other, crossing edges with no vertex inside, coplanar ones, NaN); the CGAL Epeck
// oracle (Tetrahedron_3; the exact LP when one is coplanar) on 20,000 random and 20,000
// near-degenerate cases (touching at a vertex, an edge or face point, crossing, just missing;
// faces in one plane; coplanar tetrahedra; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rotated and reflected vertex orders, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_tetrahedron_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("tetrahedron_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
tetrahedron3 shifted(const tetrahedron3& t, vec3 v) { return {t.a + v, t.b + v, t.c + v, t.d + v}; }
} // namespace

TEST_CASE("tetrahedron_tetrahedron: fixtures", "[tetrahedron_tetrahedron]") {
    CHECK(intersects(T, shifted(T, {1, 0, 0}))); // a shared vertex
    CHECK_FALSE(intersects(T, shifted(T, {0x1.0000000000001p0, 0, 0})));
    CHECK(intersects(T, tetrahedron3{{0, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}));                      // the opposite corner
    CHECK(intersects(T, tetrahedron3{T.b, T.c, T.d, {1, 1, 1}}));                                           // a shared face
    CHECK(intersects(T, tetrahedron3{{0.1, 0.1, 0.1}, {0.2, 0.1, 0.1}, {0.1, 0.2, 0.1}, {0.1, 0.1, 0.2}})); // inside
    // crossing edges, no vertex inside the other: a wedge through the middle of the edge (1,0,0)-(0,1,0)
    CHECK(intersects(T, tetrahedron3{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {2, 2, -1}, {2, 2.5, 1}}));
    CHECK_FALSE(intersects(T, tetrahedron3{{0.5, 0x1.0000000000001p-1, -1}, {0.5, 0x1.0000000000001p-1, 1}, {2, 2, -1}, {2, 2.5, 1}}));
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(flat, shifted(T, {0.5, 0.5, 0})));
    CHECK_FALSE(intersects(flat, shifted(T, {0.5, 0.5, 0x1p-1000})));
    CHECK_FALSE(intersects(T, tetrahedron3{T.a, T.b, T.c, {0, 0, std::nan("")}}));
}
TEST_CASE("tetrahedron_tetrahedron: oracle, random and near-degenerate", "[tetrahedron_tetrahedron][oracle]") {
    support::flat_oracle<tetrahedron3, tetrahedron3>("tetrahedron_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("tetrahedron_tetrahedron: rewrites of either shape and exact translations give the same answer", "[tetrahedron_tetrahedron]") {
    support::flat_symmetries<tetrahedron3, tetrahedron3>("tetrahedron_tetrahedron", support::cases(20000));
}

} // namespace test_query_tetrahedron_tetrahedron
