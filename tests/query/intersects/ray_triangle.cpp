// ray3 x triangle3: fixtures, watertightness, and the CGAL Epeck oracle on 100,000 random and
// 100,000 near-degenerate cases (edge, vertex, interior, coplanar rays; ulp nudges; 2^+-500).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"

namespace test_query_ray_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("ray_triangle"); // stated in the catalog (modules/query/catalog.cppm)

using support::arr;
std::string describe(const ray3& r, const triangle3& t) {
    return "ray " + support::str(r.origin) + " dir " + support::str(r.direction) + " tri " + support::str(t.a) + support::str(t.b) +
           support::str(t.c);
}
bool truth(const ray3& r, const triangle3& t) {
    double o[3], d[3], a[3], b[3], c[3];
    arr(r.origin, o);
    arr(r.direction, d);
    arr(t.a, a);
    arr(t.b, b);
    arr(t.c, c);
    return oracle::ray_triangle(o, d, a, b, c);
}
bool degenerate(const triangle3& t) {
    double a[3], b[3], c[3];
    arr(t.a, a);
    arr(t.b, b);
    arr(t.c, c);
    return oracle::triangle_is_degenerate(a, b, c);
}
bool skip(const ray3& r, const triangle3& t) { return r.direction == vec3{0, 0, 0} || degenerate(t); }
point3 P(support::transform& tr, double x, double y, double z) { return {tr.apply(x, 0), tr.apply(y, 1), tr.apply(z, 2)}; }

// A near-degenerate case: a ray aimed exactly at a vertex, an edge point, an interior point or a
// point just outside, or lying in the triangle's plane; then scaled, translated and nudged.
std::pair<ray3, triangle3> near_case(support::rng& r) {
    using support::small;
    const double A[3] = {small(r), small(r), small(r)}, B[3] = {small(r), small(r), small(r)}, C[3] = {small(r), small(r), small(r)};
    const double s = r.integer(0, 4) * 0.25, u = r.integer(0, 4) * 0.25;
    double target[3];
    const int kind = r.integer(0, 4);
    for (int i = 0; i < 3; ++i) {
        if (kind == 0) target[i] = A[i];                                                          // vertex
        else if (kind == 1) target[i] = A[i] + s * (B[i] - A[i]);                                 // edge point
        else if (kind == 2) target[i] = A[i] + s * (B[i] - A[i]) * 0.5 + u * (C[i] - A[i]) * 0.5; // inside
        else target[i] = A[i] + (1 + s) * (B[i] - A[i]) - u * (C[i] - A[i]);                      // outside, in plane
    }
    double O[3], D[3];
    const bool coplanar = r.integer(0, 3) == 0;
    for (int i = 0; i < 3; ++i) {
        O[i] = coplanar ? A[i] + 2 * (C[i] - A[i]) - (B[i] - A[i]) : small(r);
        D[i] = target[i] - O[i];
        if (r.integer(0, 7) == 0) D[i] *= -1; // sometimes pointing away
    }
    support::transform tr = support::random_transform(r, true);
    const triangle3 t{P(tr, A[0], A[1], A[2]), P(tr, B[0], B[1], B[2]), P(tr, C[0], C[1], C[2])};
    const ray3 ray{P(tr, O[0], O[1], O[2]), vec3{tr.dir(D[0]), tr.dir(D[1]), tr.dir(D[2])}};
    return {ray, t};
}
std::pair<ray3, triangle3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto p = [&] { return point3{support::random_coord(r, tr, 0), support::random_coord(r, tr, 1), support::random_coord(r, tr, 2)}; };
    const triangle3 t{p(), p(), p()};
    const point3 o = p();
    const point3 aim = p();
    const vec3 d{tr.scale_only(r.uniform(-1, 1)) + (aim.x - o.x) * 0.5, tr.scale_only(r.uniform(-1, 1)) + (aim.y - o.y) * 0.5,
                 tr.scale_only(r.uniform(-1, 1)) + (aim.z - o.z) * 0.5};
    return {ray3{o, d}, t};
}
} // namespace

TEST_CASE("ray_triangle: fixtures (closed triangle, edges and vertices count)", "[ray_triangle]") {
    const triangle3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(intersects(ray3{{0.25, 0.25, 1}, {0, 0, -1}}, T));
    CHECK(intersects(ray3{{0.5, 0, 1}, {0, 0, -1}}, T));        // edge
    CHECK(intersects(ray3{{1, 0, 1}, {0, 0, -1}}, T));          // vertex
    CHECK(intersects(ray3{{0.5, 0.5, 1}, {0, 0, -1}}, T));      // hypotenuse
    CHECK_FALSE(intersects(ray3{{0.5, 0.5, 1}, {0, 0, 1}}, T)); // pointing away
    CHECK(intersects(ray3{{0.25, 0.25, 0}, {0, 0, 1}}, T));     // origin on the triangle: t = 0
    CHECK(intersects(ray3{{-1, 0.5, 0}, {1, 0, 0}}, T));        // coplanar, crossing
    CHECK_FALSE(intersects(ray3{{-1, 0.5, 0}, {-1, 0, 0}}, T)); // coplanar, away
    CHECK(intersects(ray3{{-1, 0, 0}, {1, 0, 0}}, T));          // coplanar, along an edge
    CHECK(intersects(ray3{{2, -1, 0}, {-1, 1, 0}}, T));         // coplanar, through the vertex (1,0)
    // reversed winding, rotated vertices: same answers
    const triangle3 R{{0, 1, 0}, {1, 0, 0}, {0, 0, 0}};
    CHECK(intersects(ray3{{0.5, 0, 1}, {0, 0, -1}}, R));
    CHECK(intersects(ray3{{1, 0, 1}, {0, 0, -1}}, triangle3{T.b, T.c, T.a}));
    // degenerate triangles are their hull (a segment) and a point
    const triangle3 S{{0, 0, 0}, {2, 0, 0}, {1, 0, 0}};
    CHECK(intersects(ray3{{1.5, 0, 1}, {0, 0, -1}}, S));
    CHECK_FALSE(intersects(ray3{{2.5, 0, 1}, {0, 0, -1}}, S));
    CHECK(intersects(ray3{{-1, 0, 0}, {1, 0, 0}}, S)); // collinear
    CHECK(intersects(ray3{{1, 1, 1}, {0, -1, -1}}, triangle3{{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}));
    // coplanar hits report the first contact, not the origin
    const auto cp = intersection(ray3{{-1, 0.25, 0}, {4, 0, 0}}, T);
    REQUIRE(cp);
    CHECK(cp->t == 0.25);
    CHECK(cp->point == point3{0, 0.25, 0});
    CHECK(cp->u == 0.75);
    CHECK(cp->v == 0.0);
    CHECK(cp->w == 0.25);
    const auto inside = intersection(ray3{{0.25, 0.25, 0}, {1, 0, 0}}, T);
    REQUIRE(inside);
    CHECK(inside->t == 0.0);
    const auto along = intersection(ray3{{3, 0, 0}, {-1, 0, 0}}, T); // along an edge, entering at a vertex
    REQUIRE(along);
    CHECK(along->t == 2.0);
    const auto seg = intersection(ray3{{1.5, 1, 1}, {0, -1, -1}}, S); // degenerate triangle: its hull
    REQUIRE(seg);
    CHECK(seg->t == 1.0);
    CHECK(seg->point == point3{1.5, 0, 0});
    // a zero direction is the origin point
    CHECK(intersects(ray3{{0.25, 0.25, 0}, {0, 0, 0}}, T));
    CHECK_FALSE(intersects(ray3{{0.25, 0.25, 1}, {0, 0, 0}}, T));
}

TEST_CASE("ray_triangle: exact hit values are correctly rounded", "[ray_triangle]") {
    // t against CGAL (coplanar hits by their first contact); barycentrics sum to 1 within rounding
    support::run_values(
        "ray_triangle exact t", support::cases(20000), 1, near_case, random_case,
        [](const ray3& ray, const triangle3& tri) -> std::optional<bool> {
            if (skip(ray, tri)) return std::nullopt;
            const auto h = intersection(ray, tri);
            if (!h) return std::nullopt;
            double o[3], d[3], a[3], b[3], c[3];
            arr(ray.origin, o);
            arr(ray.direction, d);
            arr(tri.a, a);
            arr(tri.b, b);
            arr(tri.c, c);
            const double sum = std::fabs(h->u) + std::fabs(h->v) + std::fabs(h->w);
            return oracle::is_rounded_ray_triangle_t(o, d, a, b, c, h->t) &&
                   std::fabs(h->u + h->v + h->w - 1.0) <= 0x1p-50 * sum + 0x1p-1000;
        },
        describe);
}

TEST_CASE("ray_triangle: oracle, random", "[ray_triangle][oracle]") {
    support::run_oracle("ray_triangle random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("ray_triangle: oracle, near-degenerate", "[ray_triangle][oracle]") {
    support::run_oracle("ray_triangle near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}

TEST_CASE("ray_triangle: approximate tier is watertight on shared edges", "[ray_triangle]") {
    // Two triangles sharing the edge (p, q); rays through exact points of that edge must hit at
    // least one of them (Woop, Benthin, Wald 2013). Moeller-Trumbore is counted for comparison.
    support::rng r(support::seed() + 2);
    long n = 0, watertight_miss = 0, mt_miss = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        support::transform tr = support::random_transform(r, false);
        tr.k = r.integer(-20, 20);
        auto p = [&] { return point3{tr.apply(r.uniform(-1, 1), 0), tr.apply(r.uniform(-1, 1), 1), tr.apply(r.uniform(-1, 1), 2)}; };
        const point3 a = p(), b = p(), c = p(), e = p();
        const double s = r.uniform(0, 1);
        const point3 on{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)};
        const point3 o = p();
        const ray3 ray{o, on - o};
        const triangle3 t1{a, b, c}, t2{b, a, e};
        // Watertightness is about an unfolded hinge: c and e on opposite sides of the plane
        // (o, a, b) that contains the ray, so the projected triangles share the edge without overlap.
        if (orient3d(o, a, b, c) * orient3d(o, a, b, e) != sign::negative) continue;
        // the true line may miss the shared edge (rounded `on`); count only exact hits of the union
        if (!(intersects(ray, t1) || intersects(ray, t2))) continue;
        ++n;
        if (!(intersects<approximate>(ray, t1) || intersects<approximate>(ray, t2))) ++watertight_miss;
        if (!(method::ray_triangle_moller_trumbore(ray, t1) || method::ray_triangle_moller_trumbore(ray, t2))) ++mt_miss;
    }
    std::printf("[cases] ray_triangle shared-edge rays: %ld; watertight misses both %ld; Moeller-Trumbore misses both %ld\n", n,
                watertight_miss, mt_miss);
    CHECK(watertight_miss == 0);
}

TEST_CASE("ray_triangle: coplanar rays report their first contact, correctly rounded", "[ray_triangle][oracle]") {
    // Exactly coplanar configurations (dyadic coordinates, exact power-of-two scaling, no
    // nudges): CGAL's intersection is then a segment, and t must be its nearer end, rounded.
    support::rng r(support::seed() + 11);
    long hits = 0, bad = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        using support::small;
        const double A[3] = {small(r), small(r), small(r)}, B[3] = {small(r), small(r), small(r)}, C[3] = {small(r), small(r), small(r)};
        const double u = r.integer(-8, 8) * 0.25, v = r.integer(-8, 8) * 0.25, du = r.integer(-4, 4) * 0.5, dv = r.integer(-4, 4) * 0.5;
        const int k = r.integer(-200, 200);
        auto P = [&](double a, double b, double c) { return point3{std::ldexp(a, k), std::ldexp(b, k), std::ldexp(c, k)}; };
        const triangle3 t{P(A[0], A[1], A[2]), P(B[0], B[1], B[2]), P(C[0], C[1], C[2])};
        double O[3], D[3];
        for (int j = 0; j < 3; ++j) {
            O[j] = A[j] + u * (B[j] - A[j]) + v * (C[j] - A[j]);
            D[j] = du * (B[j] - A[j]) + dv * (C[j] - A[j]);
        }
        const ray3 ray{P(O[0], O[1], O[2]), vec3{std::ldexp(D[0], k), std::ldexp(D[1], k), std::ldexp(D[2], k)}};
        if (skip(ray, t)) continue;
        const auto h = intersection(ray, t);
        if (h.has_value() != truth(ray, t)) {
            ++bad;
            continue;
        }
        if (!h) continue;
        ++hits;
        double o[3], d[3], a[3], b[3], c[3];
        arr(ray.origin, o);
        arr(ray.direction, d);
        arr(t.a, a);
        arr(t.b, b);
        arr(t.c, c);
        if (!oracle::is_rounded_ray_triangle_t(o, d, a, b, c, h->t) && ++bad <= 5)
            std::printf("  coplanar t %a wrong: %s\n", h->t, describe(ray, t).c_str());
        if (std::fabs(h->u + h->v + h->w - 1.0) > 0x1p-50) ++bad;
    }
    std::printf("[cases] ray_triangle coplanar first contact: %ld hits checked, %ld wrong\n", hits, bad);
    CHECK(hits > support::cases(20000) / 20); // the generator must actually produce coplanar hits
    CHECK(bad == 0);
}

} // namespace test_query_ray_triangle
