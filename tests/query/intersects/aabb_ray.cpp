// aabb3 x ray3: slab method in every tier, Woo's method, exact t_enter/t_exit rounding;
// CGAL Epeck oracle on 100,000 random and 100,000 near-degenerate cases (rays grazing faces,
// edges and corners, rays in face planes, axis-parallel directions, ulp nudges, 2^+-500).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"

namespace test_query_aabb_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_ray"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const aabb3& b, const ray3& r) {
    return "box " + support::str(b.min) + support::str(b.max) + " ray " + support::str(r.origin) + " dir " + support::str(r.direction);
}
bool truth(const aabb3& b, const ray3& r) {
    double o[3], d[3], mn[3], mx[3];
    arr(r.origin, o);
    arr(r.direction, d);
    arr(b.min, mn);
    arr(b.max, mx);
    return oracle::ray_box(o, d, mn, mx);
}
bool skip(const aabb3&, const ray3& r) { return r.direction == vec3{0, 0, 0}; }

std::pair<aabb3, ray3> near_case(support::rng& r) {
    using support::small;
    double lo[3], hi[3], target[3], O[3], D[3];
    for (int i = 0; i < 3; ++i) {
        lo[i] = small(r);
        hi[i] = lo[i] + r.integer(0, 8) * 0.5; // flat boxes included
    }
    // target on a face, edge or corner: each axis at lo, hi, or strictly inside
    for (int i = 0; i < 3; ++i) {
        const int w = r.integer(0, 2);
        target[i] = w == 0 ? lo[i] : (w == 1 ? hi[i] : (lo[i] + hi[i]) * 0.5);
        // sometimes just outside by a quarter
        if (r.integer(0, 5) == 0) target[i] += r.coin() ? 0.25 : -0.25;
    }
    for (int i = 0; i < 3; ++i) {
        O[i] = small(r);
        if (r.integer(0, 4) == 0) O[i] = target[i]; // ray in a face plane / axis-parallel
        D[i] = target[i] - O[i];
        if (r.integer(0, 9) == 0) D[i] = -D[i];
    }
    support::transform tr = support::random_transform(r, true);
    const aabb3 b{{tr.apply(lo[0], 0), tr.apply(lo[1], 1), tr.apply(lo[2], 2)},
                  {tr.apply(hi[0], 0), tr.apply(hi[1], 1), tr.apply(hi[2], 2)}};
    aabb3 fixed = b; // nudges may invert a flat box: keep min <= max
    fixed = support::ordered(fixed);
    return {fixed, ray3{{tr.apply(O[0], 0), tr.apply(O[1], 1), tr.apply(O[2], 2)}, {tr.dir(D[0]), tr.dir(D[1]), tr.dir(D[2])}}};
}
std::pair<aabb3, ray3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto c = [&](int i) { return support::random_coord(r, tr, i); };
    double a[3] = {c(0), c(1), c(2)}, b[3] = {c(0), c(1), c(2)};
    for (int i = 0; i < 3; ++i)
        if (a[i] > b[i]) std::swap(a[i], b[i]);
    const point3 o{c(0), c(1), c(2)};
    const vec3 d{tr.scale_only(r.uniform(-1, 1)), tr.scale_only(r.uniform(-1, 1)), tr.scale_only(r.uniform(-1, 1))};
    return {aabb3{{a[0], a[1], a[2]}, {b[0], b[1], b[2]}}, ray3{o, d}};
}
} // namespace

TEST_CASE("aabb_ray: fixtures (closed box, grazing counts)", "[aabb_ray]") {
    const aabb3 B{{0, 0, 0}, {1, 1, 1}};
    CHECK(intersects(B, ray3{{-1, 0.5, 0.5}, {1, 0, 0}}));
    CHECK(intersects(B, ray3{{-1, 1, 0.5}, {1, 0, 0}})); // along a face
    CHECK(intersects(B, ray3{{-1, 1, 1}, {1, 0, 0}}));   // along an edge
    CHECK(intersects(B, ray3{{-1, -1, -1}, {1, 1, 1}})); // through corners
    CHECK(intersects(B, ray3{{2, 1, 0}, {-1, -1, 0}}));  // touching only the edge x = 1, y = 0
    CHECK_FALSE(intersects(B, ray3{{2.0000000000000004, 1, 0}, {-1, -1, 0}}));
    CHECK_FALSE(intersects(B, ray3{{-1, 0.5, 0.5}, {-1, 0, 0}}));
    CHECK(intersects(B, ray3{{0.5, 0.5, 0.5}, {0, 0, 0}})); // zero direction: the origin point
    CHECK(intersects(ray3{{-1, 0.5, 0.5}, {1, 0, 0}}, B));  // reversed order
    const auto h = intersection(B, ray3{{-1, 0.5, 0.5}, {2, 0, 0}});
    REQUIRE(h);
    CHECK(h->t_enter == 0.5);
    CHECK(h->t_exit == 1.0);
    CHECK(method::aabb_ray_woo(B, ray3{{-1, 0.5, 0.5}, {1, 0, 0}}));
}
TEST_CASE("aabb_ray: oracle, random", "[aabb_ray][oracle]") {
    support::run_oracle("aabb_ray random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("aabb_ray: oracle, near-degenerate", "[aabb_ray][oracle]") {
    support::run_oracle("aabb_ray near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("aabb_ray: exact t_enter and t_exit are correctly rounded", "[aabb_ray]") {
    support::run_values(
        "aabb_ray exact t", support::cases(50000), 3, near_case, random_case,
        [](const aabb3& b, const ray3& ray) -> std::optional<bool> {
            const auto h = intersection(b, ray);
            if (!h) return std::nullopt;
            double o[3], d[3], mn[3], mx[3];
            arr(ray.origin, o);
            arr(ray.direction, d);
            arr(b.min, mn);
            arr(b.max, mx);
            return oracle::is_rounded_ray_box_t(o, d, mn, mx, h->t_enter, h->t_exit);
        },
        describe);
}
TEST_CASE("aabb_ray: Woo's method against the oracle (independent second algorithm)", "[aabb_ray][oracle]") {
    support::rng r(support::seed() + 4);
    long n = 0, wrong = 0, outside = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        auto [b, ray] = (i % 2) ? near_case(r) : random_case(r);
        if (skip(b, ray)) continue;
        ++n;
        const bool t = truth(b, ray);
        if (method::aabb_ray_woo(b, ray) != t) {
            ++wrong;
            // Woo's decision also depends on where the ray crosses the box's edges (its hit
            // point is compared with the face bounds), so its stated margin includes the
            // ray's relative distance to each of the 12 edge lines: det(d, p - o, q - o).
            support_margin::margin_kernel mk;
            (void)detail::intersects(mk, b, ray);
            const double lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
            for (int axis = 0; axis < 3; ++axis)
                for (int corner = 0; corner < 4; ++corner) {
                    double p[3], q[3];
                    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                    p[axis] = lo[axis];
                    q[axis] = hi[axis];
                    p[u] = q[u] = (corner & 1) ? hi[u] : lo[u];
                    p[v] = q[v] = (corner & 2) ? hi[v] : lo[v];
                    const point3 P{p[0], p[1], p[2]}, Q{q[0], q[1], q[2]};
                    (void)mk.sgn([&](auto L) {
                        const auto O = arith::lift(L, ray.origin);
                        return arith::det3(arith::lift(L, ray.direction), arith::lift(L, P) - O, arith::lift(L, Q) - O);
                    });
                }
            if (mk.min_rel > approx_bound && ++outside <= 5)
                std::printf("  Woo wrong (truth %d) at margin %g: %s\n", t, mk.min_rel, describe(b, ray).c_str());
        }
    }
    std::printf("[cases] aabb_ray Woo: %ld cases, %ld wrong, %ld outside the stated bound\n", n, wrong, outside);
    CHECK(outside == 0);
}

namespace {
// A direction component far from scale 1 (2^+-900, subnormal, zero), or a coordinate that is not
// finite, in some of the cases.
vec3 stretched(support::rng& r, vec3 d) {
    double c[3] = {d.x, d.y, d.z};
    for (double& x : c) {
        const int w = r.integer(0, 15);
        if (w == 0) x = std::ldexp(x, 900);
        else if (w == 1) x = std::ldexp(x, -900);
        else if (w == 2) x = x * 0x1p-1070;
        else if (w == 3) x = 0.0;
    }
    return {c[0], c[1], c[2]};
}
} // namespace

// The rounded slab parameters (detail::slab_parameters_decide) decide a case only as the exact signs
// do, for rays, segments and lines, on the oracle tests' random and near-degenerate cases with
// directions stretched to 2^+-900 or the subnormal range and a few non-finite coordinates; and they
// decide most random cases (else the signs would run everywhere).
TEST_CASE("aabb_ray: the rounded slab parameters never decide against the signs", "[aabb_ray]") {
    support::rng r(support::seed() + 9);
    long n = 0, decided = 0, random_decided = 0, random_n = 0, wrong = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        const bool near = (i % 2) != 0;
        auto [b, ray] = near ? near_case(r) : random_case(r);
        const vec3 d = r.integer(0, 3) == 0 ? stretched(r, ray.direction) : ray.direction;
        point3 o = ray.origin;
        if (r.integer(0, 99) == 0) o.y = r.coin() ? std::nan("") : (r.coin() ? 1.0 : -1.0) * INFINITY;
        const point3 e{o.x + d.x, o.y + d.y, o.z + d.z};
        auto check = [&]<detail::slab_extent X>(std::integral_constant<detail::slab_extent, X>) {
            const certainty fast = detail::slab_parameters_decide<X>(b, o, d, e);
            arith::exact_kernel k;
            const bool want = detail::slab_signs<X>(k, b, o, d, e) && k.valid;
            ++n;
            if (!near) ++random_n;
            if (fast == certainty::uncertain) return;
            ++decided;
            if (!near) ++random_decided;
            if ((fast == certainty::yes) != want) ++wrong;
        };
        check(std::integral_constant<detail::slab_extent, detail::slab_extent::ray>{});
        check(std::integral_constant<detail::slab_extent, detail::slab_extent::segment>{});
        check(std::integral_constant<detail::slab_extent, detail::slab_extent::line>{});
    }
    std::printf("[cases] aabb slab parameters: %ld checks, %ld decided (%ld of %ld random), wrong %ld\n", n, decided, random_decided,
                random_n, wrong);
    CHECK(wrong == 0);
    CHECK(random_decided > random_n / 2);
}

} // namespace test_query_aabb_ray
