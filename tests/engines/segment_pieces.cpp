// The segment split shared by contains(mesh | polygon, segment) (modules/query/segment_pieces.cppm),
// on parameters t = n / d of two doubles: the merge sort under an exact and an inconsistent order,
// which breakpoints lie strictly inside (0, 1) and are kept with D made positive, and the pieces
// visited: every open piece once, at a double t proven inside it, or at the exact midpoint where no
// double lies between its ends (1 - 2^-53 and 1); a piece rejected stops the walk.
#include <catch2/catch_test_macros.hpp>
#include <cstdint>
#include <utility>
#include <vector>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"

namespace test_query_segment_pieces { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
namespace pieces = incidence::detail::pieces;

namespace {
// t = n / d (negated both when flip), homogeneous of degree 1 over degree 1
struct ratio {
    double n, d;
    bool flip = false;
};
constexpr auto fraction = [](auto L, const ratio& p) {
    const auto n = L(p.n), d = L(p.d);
    return p.flip ? std::pair{-n, -d} : std::pair{n, d};
};
struct visit {
    std::vector<double> at_double;                // the t of each piece decided at a double
    std::vector<std::pair<double, double>> exact; // the ends (as n / d) of each decided at its midpoint
};
visit walk(std::vector<ratio> params, bool stop_at_second = false) {
    arith::exact_kernel k;
    visit v;
    std::vector<ratio> kept;
    for (const ratio& p : params) (void)pieces::keep(k, fraction, p, kept);
    const bool all = pieces::all_pieces(
        k, kept, ratio{0, 1}, ratio{1, 1}, fraction,
        [&](double t) {
            v.at_double.push_back(t);
            return !(stop_at_second && v.at_double.size() == 2);
        },
        [&](const ratio& lo, const ratio& hi) {
            v.exact.push_back({lo.n / lo.d, hi.n / hi.d});
            return true;
        });
    CHECK(all == !stop_at_second);
    return v;
}
} // namespace

TEST_CASE("segment_pieces: merge sort, exact and inconsistent orders", "[segment_pieces]") {
    std::vector<int> v{5, 3, 9, 1, 1, 7, 2, 8, 0, 6, 4};
    pieces::merge_sort(v, [](int a, int b) { return a < b; });
    CHECK(v == std::vector<int>{0, 1, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    support::rng r(support::seed());
    for (int round = 0; round < 100; ++round) { // a coin for an order: a permutation stays, nothing out of range
        std::vector<int> w(static_cast<std::size_t>(r.integer(0, 40)));
        for (std::size_t i = 0; i < w.size(); ++i) w[i] = static_cast<int>(i);
        pieces::merge_sort(w, [&](int, int) { return r.coin(); });
        std::vector<int> seen(w.size(), 0);
        for (int x : w) ++seen[static_cast<std::size_t>(x)];
        CHECK(seen == std::vector<int>(w.size(), 1));
    }
}

TEST_CASE("segment_pieces: breakpoints kept strictly inside (0, 1), D made positive", "[segment_pieces]") {
    arith::exact_kernel k;
    std::vector<ratio> kept;
    CHECK(pieces::keep(k, fraction, ratio{1, 2}, kept));
    CHECK(pieces::keep(k, fraction, ratio{-1, -3}, kept));     // 1/3, D negative: flipped
    CHECK(pieces::keep(k, fraction, ratio{0, 5}, kept));       // t = 0: not kept
    CHECK(pieces::keep(k, fraction, ratio{-2, -2}, kept));     // t = 1: not kept
    CHECK(pieces::keep(k, fraction, ratio{3, 2}, kept));       // beyond 1
    CHECK_FALSE(pieces::keep(k, fraction, ratio{1, 0}, kept)); // D = 0: no parameter
    REQUIRE(kept.size() == 2);
    CHECK_FALSE(kept[0].flip);
    CHECK(kept[1].flip);
    CHECK(pieces::inside_unit(k, fraction, kept[1]));
}

TEST_CASE("segment_pieces: every open piece once, at a double inside it or at its exact midpoint", "[segment_pieces]") {
    // 2/3, 1/3 and 2/6 (equal to 1/3: no piece between them), unsorted
    const visit v = walk({{2, 3}, {1, 3}, {2, 6}});
    REQUIRE(v.at_double.size() == 3);
    CHECK(v.exact.empty());
    CHECK((0 < v.at_double[0] && 3 * v.at_double[0] < 1));
    CHECK((1 < 3 * v.at_double[1] && 3 * v.at_double[1] < 2));
    CHECK((2 < 3 * v.at_double[2] && v.at_double[2] < 1));
    // 1 - 2^-53 and 1 are neighbouring doubles: that piece goes to the exact midpoint
    const visit w = walk({{0x1.fffffffffffffp-1, 1}, {0.5, 1}});
    CHECK(w.at_double.size() == 2);
    REQUIRE(w.exact.size() == 1);
    CHECK(w.exact[0] == std::pair{0x1.fffffffffffffp-1, 1.0});
    // no breakpoint: the one piece (0, 1)
    CHECK(walk({}).at_double.size() == 1);
    // a piece rejected stops the walk
    CHECK(walk({{1, 4}, {1, 2}, {3, 4}}, true).at_double.size() == 2);
}

} // namespace test_query_segment_pieces
