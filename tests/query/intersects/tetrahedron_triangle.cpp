// tetrahedron3 x triangle3: fixtures (piercing it with no vertex inside, in a face's plane, one
// ulp below it, inside, touching at a vertex, coplanar tetrahedra and collinear triangles, NaN);
// the CGAL Epeck oracle (Tetrahedron_3; the exact LP for coplanar tetrahedra) on 20,000 random and
// 20,000 near-degenerate cases (touching at a vertex, an edge or face point, crossing, just
// missing; triangles in and parallel to a face's plane; degenerate shapes; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and
// reflected vertex orders of both, exact translations; the rounded triangle-side stage
// (tetra::rounded_triangle_side) against the oracle.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_tetrahedron_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("tetrahedron_triangle"); // stated in the catalog (modules/query/catalog.cppm)
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("tetrahedron_triangle: fixtures", "[tetrahedron_triangle]") {
    CHECK(intersects(T, triangle3{{-5, -5, 0.5}, {5, -5, 0.5}, {0, 5, 0.5}})); // cuts it, no vertex inside
    CHECK(intersects(triangle3{{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}}, T));      // in the face z = 0
    CHECK_FALSE(intersects(T, triangle3{{-1, -1, -0x1p-1074}, {3, -1, -0x1p-1074}, {-1, 3, -0x1p-1074}}));
    CHECK(intersects(T, triangle3{{0.1, 0.1, 0.1}, {0.2, 0.1, 0.1}, {0.1, 0.2, 0.1}})); // inside
    CHECK(intersects(T, triangle3{{1, 0, 0}, {2, 0, 0}, {2, 1, 0}}));                   // a shared vertex
    CHECK_FALSE(intersects(T, triangle3{{0x1.0000000000001p0, 0, 0}, {2, 0, 0}, {2, 1, 0}}));
    CHECK(intersects(T, triangle3{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}}));     // its edge through an edge point
    CHECK(intersects(T, triangle3{{0.2, 0.2, -1}, {0.2, 0.2, 1}, {0.2, 0.2, 3}})); // collinear, through the solid
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(flat, triangle3{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 1}}));
    CHECK_FALSE(intersects(flat, triangle3{{0.5, 0.5, 0x1p-1000}, {0.5, 0.6, 1}, {3, 3, 1}}));
    CHECK_FALSE(intersects(T, triangle3{{-5, -5, 0.5}, {5, -5, 0.5}, {0, 5, std::nan("")}}));
}
TEST_CASE("tetrahedron_triangle: oracle, random and near-degenerate", "[tetrahedron_triangle][oracle]") {
    support::flat_oracle<tetrahedron3, triangle3>("tetrahedron_triangle", support::cases(20000), approx_bound);
}
TEST_CASE("tetrahedron_triangle: the rounded triangle-side stage never claims what the oracle denies", "[tetrahedron_triangle][oracle]") {
    // tetra::rounded_triangle_side (the triangle's plane against the tetrahedron's vertices, the
    // tetrahedron's edges through the triangle): random cases at every scale and at scale 1,
    // near-degenerate ones (touching, coplanar, nudged by an ulp, collinear triangles, coplanar
    // tetrahedra), the integer grid {-2..2}^3, where edges pass exactly through vertices and
    // edges of the triangle, and edges an ulp beside a triangle's edge. Each claim (meets, apart) is checked against the CGAL Epeck oracle.
    support::rng r(support::seed() + 19);
    long n = 0, claimed = 0, met = 0, wrong = 0;
    for (long i = 0; i < support::cases(40000); ++i) {
        const int kind = int(i % 4);
        auto grid = [&] {
            auto g = [&] { return double(r.integer(-2, 2)); };
            auto p = [&] { return point3{g(), g(), g()}; };
            return std::pair{tetrahedron3{p(), p(), p(), p()}, triangle3{p(), p(), p()}};
        };
        const auto [t, f] = kind == 0   ? support::flat_random<tetrahedron3, triangle3>(r)
                            : kind == 1 ? support::flat_random<tetrahedron3, triangle3>(r, false)
                            : kind == 2 ? support::flat_near<tetrahedron3, triangle3>(r)
                                        : grid();
        const point3 fv[3] = {f.a, f.b, f.c};
        const certainty got = detail::tetra::rounded_triangle_side(fv, t);
        ++n;
        if (got == certainty::uncertain) continue;
        ++claimed;
        met += got == certainty::yes;
        if ((got == certainty::yes) != support::flat_truth(t, f) && ++wrong <= 5)
            std::printf("  rounded triangle side wrong: %s %s\n", support::shape_str(t).c_str(), support::shape_str(f).c_str());
    }
    // An edge of the tetrahedron through the midpoint of an edge of the triangle, its far end
    // nudged by an ulp (so the edge passes just inside or just outside the triangle, or through
    // it): integer coordinates below 2^20, so the values' products round.
    long beside = 0;
    for (long i = 0; i < support::cases(4000); ++i) {
        auto g = [&] { return double(r.integer(-(1 << 19), 1 << 19)); };
        auto p = [&] { return point3{g(), g(), g()}; };
        const point3 a = p(), w = p(), c = p(), u = p(), d = p(), e = p();
        const point3 b{a.x + 2 * w.x, a.y + 2 * w.y, a.z + 2 * w.z}, m{a.x + w.x, a.y + w.y, a.z + w.z};
        point3 q{m.x + u.x, m.y + u.y, m.z + u.z};
        const int nudge = int(r.integer(0, 2)) - 1;
        q.x = nudge == 0 ? q.x : std::nextafter(q.x, nudge > 0 ? HUGE_VAL : -HUGE_VAL);
        const tetrahedron3 t{point3{m.x - u.x, m.y - u.y, m.z - u.z}, q, d, e};
        const triangle3 f{a, b, c};
        const point3 fv[3] = {f.a, f.b, f.c};
        const certainty got = detail::tetra::rounded_triangle_side(fv, t);
        ++n, ++beside;
        if (got == certainty::uncertain) continue;
        ++claimed;
        met += got == certainty::yes;
        if ((got == certainty::yes) != support::flat_truth(t, f) && ++wrong <= 5)
            std::printf("  rounded triangle side wrong beside an edge: %s %s\n", support::shape_str(t).c_str(),
                        support::shape_str(f).c_str());
    }
    std::printf("[cases] tetrahedron rounded triangle side: %ld cases (%ld beside an edge), %ld claimed (%ld meets), wrong %ld\n", n,
                beside, claimed, met, wrong);
    CHECK(wrong == 0);
    CHECK(claimed > n / 4);
    CHECK(met > n / 20);
}
TEST_CASE("tetrahedron_triangle: rewrites of either shape and exact translations give the same answer", "[tetrahedron_triangle]") {
    support::flat_symmetries<tetrahedron3, triangle3>("tetrahedron_triangle", support::cases(20000));
}

} // namespace test_query_tetrahedron_triangle
