// triangle3 x triangle3: fixtures and the CGAL Epeck oracle on 100,000 random and 100,000
// near-degenerate cases (shared vertices and edges, a vertex on the other's edge or face,
// coplanar overlaps and near-misses, then a random exact-or-nudged similarity transform) and
// 100,000 cases on the integer grid {-2..2}^3 (exact touching across both planes).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"

namespace test_query_triangle_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("triangle_triangle"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const triangle3& p, const triangle3& q) {
    return "tri " + support::str(p.a) + support::str(p.b) + support::str(p.c) + " tri " + support::str(q.a) + support::str(q.b) +
           support::str(q.c);
}
bool truth(const triangle3& p, const triangle3& q) {
    double a[3], b[3], c[3], d[3], e[3], f[3];
    arr(p.a, a);
    arr(p.b, b);
    arr(p.c, c);
    arr(q.a, d);
    arr(q.b, e);
    arr(q.c, f);
    return oracle::triangle_triangle(a, b, c, d, e, f);
}
bool skip(const triangle3& p, const triangle3& q) {
    double a[3], b[3], c[3], d[3], e[3], f[3];
    arr(p.a, a);
    arr(p.b, b);
    arr(p.c, c);
    arr(q.a, d);
    arr(q.b, e);
    arr(q.c, f);
    return oracle::triangle_is_degenerate(a, b, c) || oracle::triangle_is_degenerate(d, e, f);
}
point3 P(support::transform& tr, const double* v) { return {tr.apply(v[0], 0), tr.apply(v[1], 1), tr.apply(v[2], 2)}; }

std::pair<triangle3, triangle3> near_case(support::rng& r) {
    using support::small;
    double T[3][3], U[3][3];
    for (auto& v : T)
        for (double& x : v) x = small(r);
    const int kind = r.integer(0, 4);
    const double s = r.integer(0, 4) * 0.25, u = r.integer(0, 4) * 0.25;
    double target[3];
    for (int i = 0; i < 3; ++i) {
        if (kind == 0) target[i] = T[0][i];                                // a vertex
        else if (kind == 1) target[i] = T[0][i] + s * (T[1][i] - T[0][i]); // an edge point
        else if (kind == 2) target[i] = T[0][i] + 0.5 * s * (T[1][i] - T[0][i]) + 0.5 * u * (T[2][i] - T[0][i]);
        else target[i] = T[0][i] + (1 + s) * (T[1][i] - T[0][i]) - u * (T[2][i] - T[0][i]); // beside it
    }
    const bool coplanar = r.integer(0, 2) == 0;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            if (j == 0) U[j][i] = target[i];
            else if (coplanar) U[j][i] = T[0][i] + small(r) * 0.25 * (T[1][i] - T[0][i]) + small(r) * 0.25 * (T[2][i] - T[0][i]);
            else U[j][i] = small(r);
        }
    if (kind == 4) // a shared edge, the other triangle folded by a random third vertex
        for (int i = 0; i < 3; ++i) U[0][i] = T[0][i], U[1][i] = T[1][i];
    support::transform tr = support::random_transform(r, true);
    const triangle3 t{P(tr, T[0]), P(tr, T[1]), P(tr, T[2])}, w{P(tr, U[0]), P(tr, U[1]), P(tr, U[2])};
    return r.coin() ? std::pair{t, w} : std::pair{w, t};
}
std::pair<triangle3, triangle3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto p = [&] { return point3{support::random_coord(r, tr, 0), support::random_coord(r, tr, 1), support::random_coord(r, tr, 2)}; };
    const triangle3 t{p(), p(), p()};
    return {t, triangle3{p(), p(), p()}};
}
} // namespace

TEST_CASE("triangle_triangle: fixtures", "[triangle_triangle]") {
    const triangle3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(intersects(T, triangle3{{0.25, 0.25, -1}, {0.25, 0.25, 1}, {2, 2, 0}})); // piercing
    CHECK(intersects(T, triangle3{{0, 0, 0}, {-1, 0, 1}, {0, -1, 1}}));            // shared vertex only
    CHECK(intersects(T, triangle3{{1, 0, 0}, {0, 1, 0}, {1, 1, 1}}));              // shared edge
    CHECK(intersects(T, triangle3{{0.5, 0.5, 0}, {1, 1, 1}, {1, 1, -1}}));         // vertex on the hypotenuse
    CHECK_FALSE(intersects(T, triangle3{{0.5, std::nextafter(0.5, 1.0), 0}, {1, 1, 1}, {1, 1, -1}}));
    CHECK(intersects(T, triangle3{{0.1, 0.1, 0}, {0.2, 0.1, 0}, {0.1, 0.2, 0}})); // coplanar, inside
    CHECK(intersects(T, triangle3{{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}}));         // coplanar, around it
    CHECK_FALSE(intersects(T, triangle3{{1, 1, 0}, {2, 1, 0}, {1, 2, 0}}));       // coplanar, apart
    CHECK_FALSE(intersects(T, triangle3{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}));       // parallel planes
    CHECK(intersects(T, triangle3{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}));             // a point triangle on a vertex
    CHECK(intersects(triangle3{{2, 0.5, 0}, {-2, 0.5, 0}, {0, 0.5, 0}}, T));      // a collinear triangle across it
    // Each strictly across the other's plane, touching at one point of T's hypotenuse (the last
    // Guigue-Devillers sign is zero), then moved 2^-40 along x, off it.
    CHECK(intersects(T, triangle3{{0, 0, -1}, {1, 1, 1}, {3, 0, 1}}));
    CHECK(intersects(triangle3{{0, 0, -1}, {1, 1, 1}, {3, 0, 1}}, T));
    CHECK_FALSE(intersects(T, triangle3{{0x1p-40, 0, -1}, {1 + 0x1p-40, 1, 1}, {3 + 0x1p-40, 0, 1}}));
    CHECK_FALSE(intersects<approximate>(T, triangle3{{0x1p-40, 0, -1}, {1 + 0x1p-40, 1, 1}, {3 + 0x1p-40, 0, 1}}));
    CHECK_FALSE(method::triangle_triangle_sat(T, triangle3{{1, 1, 0}, {2, 1, 0}, {1, 2, 0}}));
    CHECK(method::triangle_triangle_sat(T, triangle3{{1, 0, 0}, {0, 1, 0}, {1, 1, 1}}));
}
TEST_CASE("triangle_triangle: oracle, random", "[triangle_triangle][oracle]") {
    support::run_oracle("triangle_triangle random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("triangle_triangle: oracle, near-degenerate", "[triangle_triangle][oracle]") {
    support::run_oracle("triangle_triangle near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
// Coordinates in {-2, ..., 2}: many pairs straddle each other's planes strictly (the
// Guigue-Devillers path) and touch there exactly, at a vertex, an edge point or along a segment.
TEST_CASE("triangle_triangle: oracle, small integer grid", "[triangle_triangle][oracle]") {
    auto grid_case = [](support::rng& r) {
        auto p = [&] { return point3{double(r.integer(-2, 2)), double(r.integer(-2, 2)), double(r.integer(-2, 2))}; };
        const triangle3 t{p(), p(), p()};
        return std::pair{t, triangle3{p(), p(), p()}};
    };
    const auto t = support::run_oracle("triangle_triangle grid", support::cases(100000), approx_bound, grid_case, truth, skip, describe);
    // How many took the straddling path: all six vertex signs nonzero.
    support::rng r(support::seed());
    long straddling = 0, meeting = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        const auto [p, q] = grid_case(r);
        auto straddles = [](const triangle3& t, const triangle3& u) { // t's vertices on both sides of u's plane, none in it
            const sign s[3] = {orient3d(u.a, u.b, u.c, t.a), orient3d(u.a, u.b, u.c, t.b), orient3d(u.a, u.b, u.c, t.c)};
            return s[0] != sign::zero && s[1] != sign::zero && s[2] != sign::zero && !(s[0] == s[1] && s[1] == s[2]);
        };
        if (!straddles(p, q) || !straddles(q, p)) continue;
        ++straddling;
        meeting += intersects(p, q);
    }
    std::printf("[cases] triangle_triangle grid: %ld straddling pairs (%ld meet) of %ld\n", straddling, meeting, t.n);
    CHECK(straddling > t.n / 20);
}
TEST_CASE("triangle_triangle: vertex rotation and reversed winding give the same answer", "[triangle_triangle]") {
    support::rng r(support::seed() + 31);
    long n = 0, bad = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        auto [p, q] = near_case(r);
        const bool e = intersects(p, q);
        for (const triangle3& p2 : {triangle3{p.b, p.c, p.a}, triangle3{p.c, p.b, p.a}})
            for (const triangle3& q2 : {triangle3{q.c, q.a, q.b}, triangle3{q.a, q.c, q.b}}) {
                ++n;
                if (intersects(p2, q2) != e) ++bad;
            }
    }
    std::printf("[cases] triangle_triangle permutations: %ld, %ld differ\n", n, bad);
    CHECK(bad == 0);
}

} // namespace test_query_triangle_triangle
