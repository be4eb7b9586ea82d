// kdop<K> x kdop<M>: fixtures (slabs that all overlap around disjoint k-DOPs, touching at a
// corner, an empty 14-DOP, mixed K, NaN and inverted bounds); the circuit counts; the exact LP
// oracle (both k-DOPs as their slabs lo <= d . x <= hi) on 5,000 random and 5,000
// near-degenerate cases for each K = 6, 14, 18, 26 against the same K (20,000 and 20,000 in all:
// the k-DOPs of two dyadic clouds, one on or beyond a face of the other, or moved onto it and
// slid along it, or interpenetrating; then a random exact-or-nudged scale 2^-500..2^500 and
// translation), and 1,000 + 1,000 for three mixed pairs; both argument orders, exact
// translations of both.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/kdop_checks.hpp"
#include "testkit/kdop_fixtures.hpp"

namespace test_query_kdop_kdop { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::edge_cut;
using support::empty14;
using support::unit26;
using support::unit6;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_kdop"); // stated in the catalog (modules/query/catalog.cppm)
// The cube [b, 2]^3 as a 14-DOP with loose diagonal slabs: near corner_cut's cut corner.
constexpr kdop<14> near_corner(double b) { return kdop<14>{{b, b, b, -5, -5, -5, -5}, {2, 2, 2, 6, 5, 5, 5}}; }
} // namespace

TEST_CASE("kdop_kdop: the positive circuits of the normals", "[kdop_kdop]") {
    STATIC_REQUIRE(detail::kdop_slabs::circuits<6>.size() == 3);
    STATIC_REQUIRE(detail::kdop_slabs::circuits<14>.size() == 41);
    STATIC_REQUIRE(detail::kdop_slabs::circuits<18>.size() == 119);
    STATIC_REQUIRE(detail::kdop_slabs::circuits<26>.size() == 777);
    // every certificate combines its normals to zero
    auto zero_sum = []<int K>() {
        const auto d = kdop<K>::directions();
        for (const auto& c : detail::kdop_slabs::circuits<K>) {
            long long s[3] = {0, 0, 0};
            for (unsigned t = 0; t < static_cast<unsigned>(c.n); ++t) {
                const int sg = c.upper[t] ? 1 : -1;
                const auto& di = d[static_cast<unsigned>(c.slab[t])];
                s[0] += sg * c.mult[t] * di.x, s[1] += sg * c.mult[t] * di.y, s[2] += sg * c.mult[t] * di.z;
                if (c.mult[t] <= 0) return false;
            }
            if (s[0] != 0 || s[1] != 0 || s[2] != 0) return false;
        }
        return true;
    };
    CHECK(zero_sum.template operator()<6>());
    CHECK(zero_sum.template operator()<14>());
    CHECK(zero_sum.template operator()<18>());
    CHECK(zero_sum.template operator()<26>());
}
TEST_CASE("kdop_kdop: fixtures", "[kdop_kdop]") {
    // every slab overlaps, yet x + y + z >= 3 * 0.875 > 2.5: disjoint
    CHECK_FALSE(intersects(corner_cut, near_corner(0.875)));
    CHECK(intersects(corner_cut, near_corner(0.8125)));
    CHECK(intersects(near_corner(0.8125), corner_cut));
    kdop<14> cut = corner_cut;
    cut.max[3] = 2.625; // touching at the corner (0.875, 0.875, 0.875)
    CHECK(intersects(cut, near_corner(0.875)));
    cut.max[3] = std::nextafter(2.625, 0.0);
    CHECK_FALSE(intersects(cut, near_corner(0.875)));
    CHECK(intersects(unit6, unit6));
    CHECK(intersects(unit6, kdop<6>{{1, 1, 1}, {2, 2, 2}})); // a shared corner
    CHECK_FALSE(intersects(unit6, kdop<6>{{1, 1, 0x1.0000000000001p0}, {2, 2, 2}}));
    CHECK_FALSE(intersects(empty14, corner_cut));
    CHECK_FALSE(intersects(empty14, empty14));
    // mixed K: the 6-DOP has no x + y slab, the 18-DOP's x + y <= 3/2 separates them
    CHECK_FALSE(intersects(edge_cut, kdop<6>{{0.875, 0.875, 0}, {2, 2, 1}}));
    CHECK(intersects(kdop<6>{{0.75, 0.75, 0}, {2, 2, 1}}, edge_cut));
    CHECK(intersects(edge_cut, corner_cut));
    CHECK(intersects(unit26, corner_cut));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(intersects(kdop<6>{{0, 0, 0}, {1, nan, 1}}, unit6));
    CHECK_FALSE(intersects(unit6, kdop<6>{{0, 0, 0}, {1, -1, 1}}));
    CHECK_FALSE(intersects(unit26, kdop<26>{{0, 0, 0, -5, -5, -5, -5, -5, -5, -5, -5, -5, -5},
                                            {1, 1, 1, 5, 5, 5, 5, 5, 5, 5, 5, 5, std::numeric_limits<double>::infinity()}}));
}
TEST_CASE("kdop_kdop: oracle, random and near-degenerate, K = 6, 14, 18, 26 and mixed", "[kdop_kdop][oracle]") {
    const long n = support::cases(5000);
    support::kdop_oracle<6, kdop<6>>("kdop_kdop", n, approx_bound);
    support::kdop_oracle<14, kdop<14>>("kdop_kdop", n, approx_bound);
    support::kdop_oracle<18, kdop<18>>("kdop_kdop", n, approx_bound);
    support::kdop_oracle<26, kdop<26>>("kdop_kdop", n, approx_bound);
    support::kdop_oracle<14, kdop<18>>("kdop_kdop 14 x 18", n / 5, approx_bound);
    support::kdop_oracle<6, kdop<26>>("kdop_kdop 6 x 26", n / 5, approx_bound);
    support::kdop_oracle<26, kdop<14>>("kdop_kdop 26 x 14", n / 5, approx_bound);
}
TEST_CASE("kdop_kdop: both orders and exact translations give the same answer", "[kdop_kdop]") {
    const long n = support::cases(5000);
    support::kdop_symmetries<6, kdop<6>>("kdop_kdop", n);
    support::kdop_symmetries<14, kdop<14>>("kdop_kdop", n);
    support::kdop_symmetries<18, kdop<18>>("kdop_kdop", n);
    support::kdop_symmetries<26, kdop<26>>("kdop_kdop", n);
    support::kdop_symmetries<14, kdop<18>>("kdop_kdop", n / 5);
}
TEST_CASE("kdop_kdop: the cases reach pairs that slab overlap alone gets wrong", "[kdop_kdop]") {
    auto count = []<int K>() {
        support::rng r(support::seed() + 5);
        long overlap_but_apart = 0, n = 0;
        for (long i = 0; i < 5000; ++i) { // not scaled: at a few hundred cases the count may be 0
            const auto c = support::kdop_pair_near<K, K>(r);
            if (!c) continue;
            ++n;
            bool overlap = true;
            for (unsigned j = 0; j < c->first.min.size(); ++j)
                overlap = overlap && c->first.min[j] <= c->second.max[j] && c->second.min[j] <= c->first.max[j];
            overlap_but_apart += overlap && !intersects(c->first, c->second);
        }
        std::printf("[cases] kdop_kdop %d-dop: %ld of %ld near-degenerate pairs overlap in every slab and are disjoint\n", K,
                    overlap_but_apart, n);
        return overlap_but_apart;
    };
    CHECK(count.template operator()<6>() == 0); // slab overlap is exact for boxes
    CHECK(count.template operator()<14>() > 0);
    CHECK(count.template operator()<18>() > 0);
    CHECK(count.template operator()<26>() > 0);
}

} // namespace test_query_kdop_kdop
