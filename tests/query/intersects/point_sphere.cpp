// point3 x sphere3 (ball): CGAL Epeck oracle on 100,000 random and 100,000 near-degenerate cases
// (points exactly on the sphere from Pythagorean quadruples, nudged by ulps, scaled, translated).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/sphere_points.hpp"

namespace test_query_point_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("point_sphere"); // stated in the catalog (modules/query/catalog.cppm)
std::string describe(const point3& p, const sphere3& s) {
    return "point " + support::str(p) + " ball " + support::str(s.center) + " r " + support::hex(s.radius);
}
bool truth(const point3& p, const sphere3& s) {
    double a[3], c[3];
    arr(p, a);
    arr(s.center, c);
    return oracle::point_in_ball(a, c, s.radius);
}
bool skip(const point3&, const sphere3&) { return false; }
std::pair<point3, sphere3> near_case(support::rng& r) {
    const double C[3] = {support::small(r), support::small(r), support::small(r)};
    const auto q = support::pythagorean(r);
    const double k = r.integer(1, 4);
    support::transform tr = support::random_transform(r, true);
    return {point3{tr.apply(C[0] + k * q.x, 0), tr.apply(C[1] + k * q.y, 1), tr.apply(C[2] + k * q.z, 2)},
            sphere3{{tr.apply(C[0], 0), tr.apply(C[1], 1), tr.apply(C[2], 2)}, tr.dir(k * q.w)}};
}
std::pair<point3, sphere3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto c = [&](int i) { return support::random_coord(r, tr, i); };
    return {point3{c(0), c(1), c(2)}, sphere3{{c(0), c(1), c(2)}, tr.scale_only(r.uniform(0, 1.5))}};
}
} // namespace

TEST_CASE("point_sphere: fixtures", "[point_sphere]") {
    const sphere3 S{{1, 2, 3}, 3};
    CHECK(intersects(point3{2, 4, 5}, S)); // on the sphere: (1,2,2) has length 3
    CHECK(intersects(S, point3{2, 4, 5}));
    CHECK(contains(S, point3{1, 2, 3}));
    CHECK_FALSE(intersects(point3{2, 4, 5.000000000000001}, S));
    CHECK(intersects(point3{0, 0, 0}, sphere3{{0, 0, 0}, 0})); // a zero-radius ball is its centre
}
TEST_CASE("point_sphere: oracle, random", "[point_sphere][oracle]") {
    support::run_oracle("point_sphere random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("point_sphere: oracle, near-degenerate", "[point_sphere][oracle]") {
    support::run_oracle("point_sphere near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}

} // namespace test_query_point_sphere
