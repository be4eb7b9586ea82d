// line3 x tetrahedron3: fixtures (through the solid, through one vertex, along an edge, one ulp
// beside a vertex, in a face's plane, coplanar tetrahedra, NaN); the CGAL Epeck oracle
// (Tetrahedron_3; the exact LP for coplanar tetrahedra) on 20,000 random and 20,000
// near-degenerate cases (through a vertex, an edge or face point, inside or just outside; lines in
// and parallel to a face's plane; zero directions and coplanar tetrahedra; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, negated and doubled
// directions, rotated and reflected vertex orders, exact translations; the rounded stage
// (tetra::rounded_line_meets, for lines and rays) against the oracle.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_line_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("line_tetrahedron: fixtures", "[line_tetrahedron]") {
    CHECK(intersects(line3{{-5, 0.2, 0.2}, {-1, 0, 0}}, T));                   // through it, origin behind
    CHECK(intersects(line3{{0, 0, 1}, {1, 1, 0}}, T));                         // through the vertex only
    CHECK_FALSE(intersects(line3{{0, 0, 0x1.0000000000001p0}, {1, 1, 0}}, T)); // one ulp above it
    CHECK(intersects(T, line3{{7, 0, 0}, {3, 0, 0}}));                         // along an edge
    CHECK(intersects(line3{{-1, 0.5, 0}, {1, 0, 0}}, T));                      // in the face z = 0
    CHECK_FALSE(intersects(line3{{-1, 0.5, -0x1p-1074}, {1, 0, 0}}, T));
    CHECK(intersects(line3{{1, 1, 1}, {-1, -1, -1}}, T)); // through the slanted face and a vertex
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(line3{{0.5, 0.5, 3}, {0, 0, 1}}, flat));
    CHECK_FALSE(intersects(line3{{1.5, 1.5, 3}, {0, 0, 1}}, flat));
    CHECK_FALSE(intersects(line3{{std::nan(""), 0.2, 0.2}, {1, 0, 0}}, T));
}
TEST_CASE("line_tetrahedron: oracle, random and near-degenerate", "[line_tetrahedron][oracle]") {
    support::flat_oracle<line3, tetrahedron3>("line_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("line_tetrahedron: the rounded stage never claims what the oracle denies", "[line_tetrahedron][ray_tetrahedron][oracle]") {
    // tetra::rounded_line_meets for lines and rays (ray_tetrahedron's stage too): random cases at
    // every scale and at scale 1, near-degenerate ones (through a vertex, an edge or a face point,
    // in or parallel to a face's plane, coplanar tetrahedra, ulp nudges), and the integer grid
    // {-2..2}^3 for every point and direction (lines through vertices and along edges and faces).
    // Each claim (meets, misses) is checked against the CGAL Epeck oracle.
    support::rng r(support::seed() + 17);
    long n = 0, claimed = 0, one_n = 0, one_claimed = 0, wrong = 0;
    for (long i = 0; i < support::cases(40000); ++i) {
        const int kind = int(i % 4);
        const bool ray = (i / 4) % 2 == 1;
        auto grid = [&] {
            auto g = [&] { return double(r.integer(-2, 2)); };
            auto p = [&] { return point3{g(), g(), g()}; };
            return std::pair{line3{p(), vec3{g(), g(), g()}}, tetrahedron3{p(), p(), p(), p()}};
        };
        auto as_line = [](const auto& pair) { return std::pair{line3{pair.first.origin, pair.first.direction}, pair.second}; };
        auto drawn = [&]<class L>(L*) {
            return kind == 0   ? as_line(support::flat_random<L, tetrahedron3>(r))
                   : kind == 1 ? as_line(support::flat_random<L, tetrahedron3>(r, false))
                   : kind == 2 ? as_line(support::flat_near<L, tetrahedron3>(r))
                               : grid();
        };
        auto [l, t] = ray ? drawn(static_cast<ray3*>(nullptr)) : drawn(static_cast<line3*>(nullptr));
        const certainty got = detail::tetra::rounded_line_meets(t, l.origin, l.direction, ray);
        ++n;
        one_n += kind == 1;
        if (got == certainty::uncertain) continue;
        ++claimed;
        one_claimed += kind == 1;
        const bool truth = ray ? support::flat_truth(ray3{l.origin, l.direction}, t) : support::flat_truth(l, t);
        if ((got == certainty::yes) != truth && ++wrong <= 5)
            std::printf("  rounded %s stage wrong: %s %s\n", ray ? "ray" : "line", support::shape_str(l).c_str(),
                        support::shape_str(t).c_str());
    }
    std::printf("[cases] tetrahedron rounded line stage: %ld cases, %ld claimed (%ld of %ld random at scale 1), wrong %ld\n", n, claimed,
                one_claimed, one_n, wrong);
    CHECK(wrong == 0);
    CHECK(one_claimed > one_n * 9 / 10);
}
TEST_CASE("line_tetrahedron: rewrites of either shape and exact translations give the same answer", "[line_tetrahedron]") {
    support::flat_symmetries<line3, tetrahedron3>("line_tetrahedron", support::cases(20000));
}

} // namespace test_query_line_tetrahedron
