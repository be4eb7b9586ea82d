// The clip decided in double (modules/engines/clip.cppm: box_slabs, clip_in_double): where it
// decides, its range (the bounding constraints, or a miss) is the exact kernel's clip's, on random
// inputs at many scales and on small-integer inputs, where parameters tie exactly (a ray through a
// box's edge or corner, a segment ending on a face, a plane through the start). It must decide most
// random cases (else the fast path is vacuous) and may decline ties.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"

namespace test_engines_clip { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
namespace detail = incidence::detail;

namespace {
struct tally {
    long cases = 0, decided = 0, wrong = 0;
};
bool same(const std::optional<detail::clipped>& a, const std::optional<detail::clipped>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->lower == b->lower && a->upper == b->upper);
}
void compare(tally& t, const detail::slab_choice& c, const std::optional<detail::clipped>& exact, const char* what) {
    ++t.cases;
    if (!c.decided) return;
    ++t.decided;
    if (!same(c.range, exact) && ++t.wrong <= 5)
        std::printf("  %s: decided %s (%d, %d), exact %s (%d, %d)\n", what, c.range ? "range" : "miss", c.range ? c.range->lower : 0,
                    c.range ? c.range->upper : 0, exact ? "range" : "miss", exact ? exact->lower : 0, exact ? exact->upper : 0);
}

detail::extent kind_of(support::rng& r) {
    const int k = r.integer(0, 2);
    return k == 0 ? detail::extent::ray : (k == 1 ? detail::extent::segment : detail::extent::line);
}
// A coordinate: uniform at a random scale 2^-40..2^40, or a small integer.
double coordinate(support::rng& r, bool grid, double scale) { return grid ? double(r.integer(-3, 3)) : r.uniform(-1, 1) * scale; }
point3 point_of(support::rng& r, bool grid, double scale) {
    return {coordinate(r, grid, scale), coordinate(r, grid, scale), coordinate(r, grid, scale)};
}
detail::linear3 linear_of(support::rng& r, bool grid, double scale) {
    const point3 o = point_of(r, grid, scale), q = point_of(r, grid, scale);
    return detail::linear3{o, q - o, q, kind_of(r)};
}
double power_scale(support::rng& r) { return std::ldexp(1.0, r.integer(-40, 40)); }

// n cases, every other one on the small-integer grid: one(r, on_grid, scale) -> {the choice in
// double, the exact clip}. Every decided choice must be the exact one; at least `percent` of the
// random cases decided; some grid case (a tie) declined.
template <class One>
void run(const char* what, int n, long percent, const One& one) {
    support::rng r(support::seed());
    tally random, grid;
    for (int i = 0; i < n; ++i) {
        const bool on_grid = i % 2 == 1;
        const auto [choice, exact] = one(r, on_grid, power_scale(r));
        compare(on_grid ? grid : random, choice, exact, what);
    }
    std::printf("[cases] %s: random %ld cases, %ld decided, %ld wrong; small integers %ld cases, %ld decided, %ld wrong\n", what,
                random.cases, random.decided, random.wrong, grid.cases, grid.decided, grid.wrong);
    CHECK(random.wrong == 0);
    CHECK(grid.wrong == 0);
    CHECK(random.decided * 100 >= random.cases * percent);
    CHECK(grid.decided < grid.cases);
}
} // namespace

TEST_CASE("clip: the box's slab test in double, where it decides, is the exact clip", "[clip]") {
    run("box", 200000, 99, [](support::rng& r, bool on_grid, double scale) {
        const point3 a = point_of(r, on_grid, scale), b = point_of(r, on_grid, scale);
        const aabb3 box{{std::fmin(a.x, b.x), std::fmin(a.y, b.y), std::fmin(a.z, b.z)},
                        {std::fmax(a.x, b.x), std::fmax(a.y, b.y), std::fmax(a.z, b.z)}};
        const detail::linear3 s = linear_of(r, on_grid, scale);
        arith::exact_kernel k;
        return std::pair{detail::box_slabs(box, s), detail::clip(k, detail::box_constraints(box, s), 6, s.kind)};
    });
}

TEST_CASE("clip: half-spaces in double, where it decides, is the exact clip", "[clip]") {
    run("half-spaces", 100000, 90, [](support::rng& r, bool on_grid, double scale) {
        const int m = r.integer(1, 8);
        plane3 planes[8];
        for (int j = 0; j < m; ++j) {
            const point3 n = point_of(r, on_grid, 1.0);
            planes[j] = plane3{{n.x, n.y, n.z}, coordinate(r, on_grid, scale)};
        }
        const detail::linear3 s = linear_of(r, on_grid, scale);
        const auto con = detail::halfspace_constraints(planes, s);
        arith::exact_kernel k;
        return std::pair{detail::clip_in_double(con, m, s.kind), detail::clip(k, con, m, s.kind)};
    });
}

} // namespace test_engines_clip
