// segment3 x triangle3: fixtures and the CGAL Epeck oracle on 100,000 random and 100,000
// near-degenerate cases (end points exactly on vertices, edges, the interior; coplanar segments).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"

namespace test_query_segment_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("segment_triangle"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const segment3& s, const triangle3& t) {
    return "seg " + support::str(s.a) + support::str(s.b) + " tri " + support::str(t.a) + support::str(t.b) + support::str(t.c);
}
bool truth(const segment3& s, const triangle3& t) {
    double p[3], q[3], a[3], b[3], c[3];
    arr(s.a, p);
    arr(s.b, q);
    arr(t.a, a);
    arr(t.b, b);
    arr(t.c, c);
    return oracle::segment_triangle(p, q, a, b, c);
}
bool skip(const segment3& s, const triangle3& t) {
    double a[3], b[3], c[3];
    arr(t.a, a);
    arr(t.b, b);
    arr(t.c, c);
    return s.a == s.b || oracle::triangle_is_degenerate(a, b, c);
}
point3 P(support::transform& tr, const double* v) { return {tr.apply(v[0], 0), tr.apply(v[1], 1), tr.apply(v[2], 2)}; }

std::pair<segment3, triangle3> near_case(support::rng& r) {
    using support::small;
    const double A[3] = {small(r), small(r), small(r)}, B[3] = {small(r), small(r), small(r)}, C[3] = {small(r), small(r), small(r)};
    const double s = r.integer(0, 4) * 0.25, u = r.integer(0, 4) * 0.25;
    const int kind = r.integer(0, 3);
    const bool coplanar = r.integer(0, 3) == 0;
    const double f = r.integer(1, 4) * 0.5; // end point before, on, or beyond the target
    double target[3], O[3], Q[3];
    for (int i = 0; i < 3; ++i) {
        if (kind == 0) target[i] = A[i];
        else if (kind == 1) target[i] = A[i] + s * (B[i] - A[i]);
        else if (kind == 2) target[i] = A[i] + s * (B[i] - A[i]) * 0.5 + u * (C[i] - A[i]) * 0.5;
        else target[i] = A[i] + (1 + s) * (B[i] - A[i]) - u * (C[i] - A[i]);
        O[i] = coplanar ? A[i] + 2 * (C[i] - A[i]) - (B[i] - A[i]) : small(r);
        Q[i] = O[i] + f * (target[i] - O[i]);
    }
    support::transform tr = support::random_transform(r, true);
    return {segment3{P(tr, O), P(tr, Q)}, triangle3{P(tr, A), P(tr, B), P(tr, C)}};
}
std::pair<segment3, triangle3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto p = [&] { return point3{support::random_coord(r, tr, 0), support::random_coord(r, tr, 1), support::random_coord(r, tr, 2)}; };
    const triangle3 t{p(), p(), p()};
    return {segment3{p(), p()}, t};
}
} // namespace

TEST_CASE("segment_triangle: fixtures", "[segment_triangle]") {
    const triangle3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(intersects(segment3{{0.25, 0.25, 1}, {0.25, 0.25, -1}}, T));
    CHECK(intersects(segment3{{0.25, 0.25, 1}, {0.25, 0.25, 0}}, T)); // end point on the triangle
    CHECK_FALSE(intersects(segment3{{0.25, 0.25, 1}, {0.25, 0.25, 0.5}}, T));
    CHECK(intersects(segment3{{0.5, 0, 1}, {0.5, 0, -1}}, T));          // through an edge
    CHECK(intersects(segment3{{-1, 0.5, 0}, {0, 0.5, 0}}, T));          // coplanar, touching the edge x = 0
    CHECK_FALSE(intersects(segment3{{-1, 0.5, 0}, {-0.5, 0.5, 0}}, T)); // coplanar, short of it
    CHECK(intersects(segment3{{0.1, 0.1, 0}, {0.2, 0.2, 0}}, T));       // coplanar, inside
    CHECK(intersects(segment3{{0.1, 0.1, 0}, {0.1, 0.1, 0}}, T));       // a point segment on it
    CHECK(intersects(T, segment3{{0.25, 0.25, 1}, {0.25, 0.25, -1}}));  // reversed order
    const auto h = intersection(segment3{{0.25, 0.25, 1}, {0.25, 0.25, -3}}, T);
    REQUIRE(h);
    CHECK(h->t == 0.25);
    CHECK(h->point == point3{0.25, 0.25, 0});
}
TEST_CASE("segment_triangle: oracle, random", "[segment_triangle][oracle]") {
    support::run_oracle("segment_triangle random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("segment_triangle: oracle, near-degenerate", "[segment_triangle][oracle]") {
    support::run_oracle("segment_triangle near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}

TEST_CASE("segment_triangle: exact first contact t is correctly rounded", "[segment_triangle][oracle]") {
    support::run_values(
        "segment_triangle exact t", support::cases(40000), 12, near_case, random_case,
        [](const segment3& s, const triangle3& t) -> std::optional<bool> {
            if (skip(s, t)) return std::nullopt;
            const auto h = intersection(s, t);
            if (!h) return std::nullopt;
            double p[3], q[3], a[3], b[3], c[3];
            arr(s.a, p);
            arr(s.b, q);
            arr(t.a, a);
            arr(t.b, b);
            arr(t.c, c);
            return oracle::is_rounded_segment_triangle_t(p, q, a, b, c, h->t) && h->t >= 0.0 && h->t <= 1.0;
        },
        describe);
}

} // namespace test_query_segment_triangle
