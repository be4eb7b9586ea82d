// kdop_of<K>: every point inside (exact), and each bound the nearest double outside the exact
// extreme (checked with exact dyadic sums independently of the construction's candidate pass).
#include <catch2/catch_test_macros.hpp>
#include <span>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"

namespace test_bound_kdop_of { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
template <int K>
void check_all(const std::vector<support::point_set>& sets, long& points, long& bounds) {
    for (const auto& s : sets) {
        const auto k = bound::kdop_of<K>(std::span<const point3>(s.points));
        REQUIRE(k);
        for (const point3& p : s.points) {
            CHECK(bound::contains(k.value(), p));
            ++points;
        }
        const auto dirs = kdop<K>::directions();
        for (unsigned i = 0; i < dirs.size(); ++i) {
            // exact extremes by brute force
            arith::dyadic lo, hi;
            bool first = true;
            for (const point3& p : s.points) {
                const arith::dyadic x =
                    arith::to_dyadic(dirs[i].x * p.x) + arith::to_dyadic(dirs[i].y * p.y) + arith::to_dyadic(dirs[i].z * p.z);
                if (first || arith::sign_of(x - lo) < 0) lo = x;
                if (first || arith::sign_of(x - hi) > 0) hi = x;
                first = false;
            }
            // min <= lo < next_up(min) and next_down(max) < hi <= max: tightest outward doubles
            CHECK(arith::sign_of(arith::to_dyadic(k.value().min[i]) - lo) <= 0);
            CHECK(arith::sign_of(arith::to_dyadic(arith::next_up(k.value().min[i])) - lo) > 0);
            CHECK(arith::sign_of(arith::to_dyadic(k.value().max[i]) - hi) >= 0);
            CHECK(arith::sign_of(arith::to_dyadic(arith::next_down(k.value().max[i])) - hi) < 0);
            ++bounds;
        }
    }
}
} // namespace

TEST_CASE("kdop_of: K = 6, 14, 18, 26 on every generated and real set", "[bound][kdop_of]") {
    support::rng r(support::seed());
    auto sets = support::point_sets(r, support::cases(1000));
    for (auto& m : support::real_meshes()) sets.push_back(std::move(m));
    long points = 0, bounds = 0;
    check_all<6>(sets, points, bounds);
    check_all<14>(sets, points, bounds);
    check_all<18>(sets, points, bounds);
    check_all<26>(sets, points, bounds);
    std::printf("[cases] kdop_of: %zu point sets x 4 kinds, %ld points inside, %ld bounds tightest outward\n", sets.size(), points, bounds);
}

TEST_CASE("kdop_of: bad input and overflow", "[bound][kdop_of]") {
    CHECK(bound::kdop_of<14>(std::span<const point3>()).error().code == errc::empty_input);
    const point3 inf_pt[] = {{0, 0, __builtin_inf()}};
    CHECK(bound::kdop_of<6>(std::span<const point3>(inf_pt)).error().code == errc::not_finite);
    const point3 huge[] = {{1.7e308, 1.7e308, 1.7e308}};
    CHECK(bound::kdop_of<6>(std::span<const point3>(huge)));                                     // axes: fine
    CHECK(bound::kdop_of<14>(std::span<const point3>(huge)).error().code == errc::out_of_range); // x + y + z overflows
    constexpr point3 cp[] = {{1, 2, 3}, {-1, 5, 0}};
    static_assert(bound::kdop_of<14>(std::span<const point3>(cp)).value().max[3] == 6.0);
}

} // namespace test_bound_kdop_of
