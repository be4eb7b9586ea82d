// batch::intersects(ray3, triangles) and batch::intersects(rays, triangle3): on every SIMD target
// this processor has (Highway lets a test choose it), each lane's answer equals the scalar
// intersects<Tier>(ray, triangle) in all four tiers, for the array and the structure-of-arrays
// entry points, on random triangles, on meshes whose edges and vertices the rays pass exactly
// (with coplanar rays, degenerate triangles, ulp nudges and scales 2^-500..2^500), and on special
// values (NaN, infinities, huge and subnormal coordinates); many rays at one triangle's vertices,
// edges, inside and outside points, in its plane and not. The exact lanes are also checked
// against the CGAL Epeck oracle on the meshes and the rays.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/simd_targets.hpp"

namespace test_batch_ray_triangles { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {

struct ray_set {
    ray3 ray;
    std::vector<triangle3> triangles;
};

point3 P(support::transform& tr, double x, double y, double z) { return {tr.apply(x, 0), tr.apply(y, 1), tr.apply(z, 2)}; }

// A ray and 2 n + 1 random triangles around it, at one random scale and place (an odd count, so
// that the SIMD tails run).
ray_set random_set(support::rng& r, int n) {
    support::transform tr = support::random_transform(r, false);
    auto p = [&] { return point3{support::random_coord(r, tr, 0), support::random_coord(r, tr, 1), support::random_coord(r, tr, 2)}; };
    ray_set s;
    const point3 o = p(), aim = p();
    s.ray = ray3{o, vec3{aim.x - o.x, aim.y - o.y, aim.z - o.z}};
    for (int i = 0; i < 2 * n + 1; ++i) s.triangles.push_back({p(), p(), p()});
    return s;
}

// A random frame: the axes permuted cyclically, then support's random transform (scale, translation,
// ulp nudges): at() places a point, along() a direction.
struct random_frame {
    int perm;
    support::transform tr;
    explicit random_frame(support::rng& r) : perm(r.integer(0, 2)), tr(support::random_transform(r, r.coin())) {}
    [[nodiscard]] std::array<double, 3> axes(double x, double y, double z) const {
        return perm == 0 ? std::array<double, 3>{x, y, z} : (perm == 1 ? std::array<double, 3>{z, x, y} : std::array<double, 3>{y, z, x});
    }
    [[nodiscard]] point3 at(double x, double y, double z) {
        const auto q = axes(x, y, z);
        return P(tr, q[0], q[1], q[2]);
    }
    [[nodiscard]] vec3 along(double x, double y, double z) {
        const auto d = axes(x, y, z);
        return {tr.dir(d[0]), tr.dir(d[1]), tr.dir(d[2])};
    }
};

// A grid mesh in the plane z = 0 (cells of side 1 from -4 to 4, each split along a diagonal), a
// ray aimed exactly at a vertex, an edge point or a cell's inside, or lying in the plane, and the
// whole scaled, translated, nudged and with its axes permuted; some triangles made degenerate.
ray_set mesh_set(support::rng& r) {
    using support::small;
    random_frame f(r);
    auto at = [&](double x, double y, double z) { return f.at(x, y, z); };
    ray_set s;
    for (int i = -4; i < 4; ++i)
        for (int j = -4; j < 4; ++j) {
            s.triangles.push_back({at(i, j, 0), at(i + 1, j, 0), at(i + 1, j + 1, 0)});
            s.triangles.push_back({at(i, j, 0), at(i + 1, j + 1, 0), at(i, j + 1, 0)});
        }
    for (int k = 0; k < 5; ++k) { // collinear triangles, and one with the ray's origin as a vertex below
        const double x = r.integer(-4, 4), y = r.integer(-4, 4);
        s.triangles.push_back({at(x, y, 0), at(x + 1, y + 1, 0), at(x + 2, y + 2, 0)});
    }
    const int kind = r.integer(0, 3);
    const double tx = r.integer(-4, 4) + (kind == 1 ? 0.5 : (kind == 2 ? 0.25 : 0.0)), ty = r.integer(-4, 4) + (kind == 2 ? 0.5 : 0.0);
    const bool coplanar = kind == 3;
    const double ox = small(r), oy = small(r), oz = coplanar ? 0.0 : small(r);
    double dx = tx - ox, dy = ty - oy, dz = -oz;
    if (r.integer(0, 7) == 0) dx = -dx, dy = -dy, dz = -dz; // pointing away
    s.ray = ray3{at(ox, oy, oz), f.along(dx, dy, dz)};
    s.triangles.push_back({s.ray.origin, at(tx, ty, 0), at(tx + 1, ty, 0)});
    return s;
}

// Triangles with NaN, infinite, huge and subnormal coordinates, against a ray that is ordinary
// or special itself.
ray_set special_set(support::rng& r) {
    auto pick = [&] { return support::special_or_uniform(r); };
    auto point = [&] { return point3{pick(), pick(), pick()}; };
    ray_set s;
    s.ray = ray3{point(), vec3{pick(), pick(), pick()}};
    for (int i = 0; i < 37; ++i) s.triangles.push_back({point(), point(), point()});
    return s;
}

struct soa_copy {
    std::vector<double> c[9];
    explicit soa_copy(const std::vector<triangle3>& ts) {
        for (const triangle3& t : ts) {
            const double v[9] = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z};
            for (int k = 0; k < 9; ++k) c[k].push_back(v[k]);
        }
    }
    batch::triangles_soa view() const { return {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]}; }
};

std::string str(point3 p) { return "(" + support::hex(p.x) + "," + support::hex(p.y) + "," + support::hex(p.z) + ")"; }
std::string str(vec3 v) { return str(point3{v.x, v.y, v.z}); }

struct counts {
    long lanes = 0, wrong = 0;
};

// Many rays against one triangle: the triangle (0,0,0), (4,0,0), (0,4,0) in a random frame (axes
// permuted, scaled, translated; collinear once in eight), and 2 n + 1 rays aimed exactly at a
// vertex, an edge point, an inside or an outside point, lying in the plane once in four, pointing
// away once in eight, nudged or with a zero direction now and then; or, for `special`, rays and a
// triangle of special values.
struct rays_set {
    triangle3 triangle;
    std::vector<ray3> rays;
};
rays_set rays_at_one(support::rng& r, bool special) {
    rays_set s;
    if (special) {
        auto pick = [&] { return support::special_or_uniform(r); };
        auto point = [&] { return point3{pick(), pick(), pick()}; };
        s.triangle = r.coin() ? triangle3{point(), point(), point()} : triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        for (int i = 0; i < 37; ++i) s.rays.push_back(ray3{point(), vec3{pick(), pick(), pick()}});
        return s;
    }
    using support::small;
    random_frame f(r);
    auto at = [&](double x, double y, double z) { return f.at(x, y, z); };
    s.triangle = r.integer(0, 7) == 0 ? triangle3{at(0, 0, 0), at(2, 2, 0), at(4, 4, 0)} : triangle3{at(0, 0, 0), at(4, 0, 0), at(0, 4, 0)};
    const int n = 2 * r.integer(20, 80) + 1;
    for (int i = 0; i < n; ++i) {
        const int kind = r.integer(0, 3);
        double tx = r.integer(0, 4), ty = 0;                                     // an edge point (or a vertex) of the first edge
        if (kind == 1) tx = r.integer(0, 4), ty = 4 - tx;                        // the hypotenuse
        else if (kind == 2) tx = r.integer(1, 2), ty = r.integer(1, 2) - 0.5;    // inside
        else if (kind == 3) tx = r.integer(-2, 6), ty = r.integer(-2, 6) + 0.25; // anywhere, mostly outside
        const bool coplanar = r.integer(0, 3) == 0;
        const double ox = small(r), oy = small(r), oz = coplanar ? 0.0 : small(r);
        double dx = tx - ox, dy = ty - oy, dz = -oz;
        if (r.integer(0, 7) == 0) dx = -dx, dy = -dy, dz = -dz; // pointing away
        if (r.integer(0, 31) == 0) dx = dy = dz = 0;            // a point
        ray3 ray{at(ox, oy, oz), f.along(dx, dy, dz)};
        if (r.integer(0, 7) == 0)
            ray.origin = {support::nudge(ray.origin.x, r.integer(-2, 2)), support::nudge(ray.origin.y, r.integer(-2, 2)), ray.origin.z};
        s.rays.push_back(ray);
    }
    return s;
}

// Every lane of both entry points of many rays against one triangle, against the scalar query.
template <class Tier>
void compare_rays(const rays_set& s, counts& c, const std::string& where) {
    const std::size_t n = s.rays.size();
    std::vector<std::uint8_t> aos(n, 7), soa(n, 7);
    const auto ra = batch::intersects<Tier>(std::span<const ray3>(s.rays), s.triangle, aos);
    std::vector<double> f[6];
    for (const ray3& ray : s.rays) {
        const double v[6] = {ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z};
        for (int k = 0; k < 6; ++k) f[k].push_back(v[k]);
    }
    const auto rs = batch::intersects<Tier>(batch::rays_soa{f[0], f[1], f[2], f[3], f[4], f[5]}, s.triangle, soa);
    REQUIRE(ra.has_value());
    REQUIRE(rs.has_value());
    std::size_t met = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t scalar = intersects<Tier>(s.rays[i], s.triangle) ? 1 : 0;
        met += scalar;
        ++c.lanes;
        if (aos[i] != scalar || soa[i] != scalar) {
            if (++c.wrong <= 5)
                std::printf("  %s lane %zu: scalar %d, batch %d (array) %d (soa); ray %s dir %s\n", where.c_str(), i, scalar, aos[i],
                            soa[i], str(s.rays[i].origin).c_str(), str(s.rays[i].direction).c_str());
        }
    }
    if (ra.value() != met || rs.value() != met) ++c.wrong;
}

// Every lane of both entry points against the scalar query of the tier.
template <class Tier>
void compare(const ray_set& s, counts& c, const std::string& where) {
    const std::size_t n = s.triangles.size();
    std::vector<std::uint8_t> aos(n, 7), soa(n, 7);
    const auto ra = batch::intersects<Tier>(s.ray, std::span<const triangle3>(s.triangles), aos);
    const soa_copy copy(s.triangles);
    const auto rs = batch::intersects<Tier>(s.ray, copy.view(), soa);
    REQUIRE(ra.has_value());
    REQUIRE(rs.has_value());
    std::size_t met = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t scalar = intersects<Tier>(s.ray, s.triangles[i]) ? 1 : 0;
        met += scalar;
        ++c.lanes;
        if (aos[i] != scalar || soa[i] != scalar) {
            if (++c.wrong <= 5)
                std::printf("  %s lane %zu: scalar %d, batch %d (array) %d (soa); ray %s dir %s\n", where.c_str(), i, scalar, aos[i],
                            soa[i], str(s.ray.origin).c_str(), str(s.ray.direction).c_str());
        }
    }
    if (ra.value() != met || rs.value() != met) ++c.wrong;
}

template <class Make>
void every_tier_on_every_target(const char* name, long sets, Make make) {
    counts c[4];
    const int targets = support::on_every_target(name, [&](support::rng& r, const std::string& where, const char* target) {
        REQUIRE(std::string(batch::simd_target()) == target);
        for (long k = 0; k < sets; ++k) {
            const ray_set s = make(r);
            compare<exact>(s, c[0], where + ", exact");
            compare<conservative>(s, c[1], where + ", conservative");
            compare<aggressive>(s, c[2], where + ", aggressive");
            compare<approximate>(s, c[3], where + ", approximate");
        }
    });
    std::printf("[cases] batch ray_triangles %s: %d SIMD targets, %ld lanes per tier; lanes unlike the scalar answer: exact %ld, "
                "conservative %ld, aggressive %ld, approximate %ld\n",
                name, targets, c[0].lanes, c[0].wrong, c[1].wrong, c[2].wrong, c[3].wrong);
    CHECK(targets >= 2); // the portable emulation and at least one native target
    for (const counts& x : c) CHECK(x.wrong == 0);
}

} // namespace

TEST_CASE("batch ray_triangles: every lane is the scalar answer, random triangles, every target", "[batch]") {
    every_tier_on_every_target("random", support::cases(400), [](support::rng& r) { return random_set(r, 128); });
}

TEST_CASE("batch ray_triangles: every lane is the scalar answer, rays through a mesh's edges and vertices, every target", "[batch]") {
    every_tier_on_every_target("mesh", support::cases(400), mesh_set);
}

TEST_CASE("batch ray_triangles: every lane is the scalar answer, special values, every target", "[batch]") {
    every_tier_on_every_target("special", support::cases(400), special_set);
}

TEST_CASE("batch rays_triangle: every lane is the scalar answer, rays at one triangle's vertices and edges, every target", "[batch]") {
    counts c[4], sc[4];
    const int targets = support::on_every_target("rays", [&](support::rng& r, const std::string& where, const char*) {
        for (long k = 0; k < support::cases(300); ++k) {
            const rays_set s = rays_at_one(r, false), sp = rays_at_one(r, true);
            compare_rays<exact>(s, c[0], where + ", exact");
            compare_rays<conservative>(s, c[1], where + ", conservative");
            compare_rays<aggressive>(s, c[2], where + ", aggressive");
            compare_rays<approximate>(s, c[3], where + ", approximate");
            compare_rays<exact>(sp, sc[0], where + ", special, exact");
            compare_rays<conservative>(sp, sc[1], where + ", special, conservative");
            compare_rays<aggressive>(sp, sc[2], where + ", special, aggressive");
            compare_rays<approximate>(sp, sc[3], where + ", special, approximate");
        }
    });
    std::printf("[cases] batch rays_triangle: %d SIMD targets, %ld lanes per tier (and %ld of special values); lanes unlike the scalar "
                "answer: %ld %ld %ld %ld, special %ld %ld %ld %ld (exact, conservative, aggressive, approximate)\n",
                targets, c[0].lanes, sc[0].lanes, c[0].wrong, c[1].wrong, c[2].wrong, c[3].wrong, sc[0].wrong, sc[1].wrong, sc[2].wrong,
                sc[3].wrong);
    CHECK(targets >= 2);
    for (int t = 0; t < 4; ++t) CHECK((c[t].wrong == 0 && sc[t].wrong == 0));
}

TEST_CASE("batch rays_triangle: the exact lanes against the CGAL Epeck oracle", "[batch]") {
    support::rng r(support::seed());
    long lanes = 0, wrong = 0, skipped = 0, met = 0;
    for (long k = 0; k < support::cases(1000); ++k) {
        const rays_set s = rays_at_one(r, false);
        std::vector<std::uint8_t> out(s.rays.size());
        REQUIRE(batch::intersects<exact>(std::span<const ray3>(s.rays), s.triangle, out).has_value());
        double a[3], b[3], c[3];
        support::arr(s.triangle.a, a);
        support::arr(s.triangle.b, b);
        support::arr(s.triangle.c, c);
        for (std::size_t i = 0; i < s.rays.size(); ++i) {
            if (s.rays[i].direction == vec3{0, 0, 0} || oracle::triangle_is_degenerate(a, b, c)) {
                ++skipped;
                continue;
            }
            double o[3], d[3];
            support::arr(s.rays[i].origin, o);
            support::arr(s.rays[i].direction, d);
            ++lanes;
            met += out[i];
            if ((out[i] == 1) != oracle::ray_triangle(o, d, a, b, c)) ++wrong;
        }
    }
    std::printf("[cases] batch rays_triangle exact against the oracle: %ld lanes (%ld met), %ld wrong; %ld lanes with a zero direction "
                "or a collinear triangle left to the scalar test\n",
                lanes, met, wrong, skipped);
    CHECK(wrong == 0);
    CHECK(met * 5 > lanes); // the rays mostly aim at the triangle
    CHECK(skipped * 4 < lanes);
}

// The first hit: batch::intersection against intersection(ray, scene) over a scene of the same
// triangles, both entry points, value for value (t, point, normal, barycentrics, index, exists);
// in the approximate tier the values of the triangle it names against the scalar approximate ones.
bool same_value(double a, double b) { return a == b || (a != a && b != b); }
bool same_value(const interval& a, const interval& b) { return same_value(a.lo, b.lo) && same_value(a.hi, b.hi); }
template <class V>
bool same_hit(const std::optional<scene_hit<V>>& a, const std::optional<scene_hit<V>>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    return same_value(a->t, b->t) && same_value(a->point.x, b->point.x) && same_value(a->point.y, b->point.y) &&
           same_value(a->point.z, b->point.z) && same_value(a->normal.x, b->normal.x) && same_value(a->normal.y, b->normal.y) &&
           same_value(a->normal.z, b->normal.z) && same_value(a->u, b->u) && same_value(a->v, b->v) && same_value(a->w, b->w) &&
           a->triangle == b->triangle && a->exists == b->exists;
}
struct first_counts {
    long sets = 0, hits = 0, wrong = 0, special = 0, special_wrong = 0, existence_unlike = 0;
};
template <class Tier>
void compare_first(const ray_set& s, first_counts& c, const std::string& where) {
    const auto batch = batch::intersection<Tier>(s.ray, std::span<const triangle3>(s.triangles));
    const soa_copy copy(s.triangles);
    const auto packet = batch::intersection<Tier>(s.ray, copy.view());
    REQUIRE(batch.has_value());
    REQUIRE(packet.has_value());
    const auto scene = scene3::make(std::span<const triangle3>(s.triangles));
    if (!scene) { // non-finite coordinates: no scene to compare with; an exact hit must be a triangle the ray meets
        ++c.special;
        const auto& h = batch.value();
        const bool ok =
            same_hit(h, packet.value()) && (!h || !std::is_same_v<Tier, exact> || intersects<exact>(s.ray, s.triangles[h->triangle]));
        if (!ok && ++c.special_wrong <= 3) std::printf("  %s: a special set's first hit\n", where.c_str());
        return;
    }
    ++c.sets;
    const auto truth = intersection<Tier>(s.ray, scene.value());
    c.hits += truth.has_value();
    bool ok = same_hit(batch.value(), packet.value());
    if constexpr (std::is_same_v<Tier, approximate>) {
        // plain double decides the comparisons, so the scene's order of visits can change the
        // winner: the hit's values must be the scalar approximate values of the triangle it names,
        // and it exists where the exact first hit does (counted apart from `wrong` where not)
        const auto& h = batch.value();
        if (h) {
            const auto scalar = intersection<approximate>(s.ray, s.triangles[h->triangle]);
            ok = ok && scalar && same_value(scalar->t, h->t) && same_value(scalar->u, h->u) && same_value(scalar->v, h->v) &&
                 same_value(scalar->w, h->w); // NaN where plain double divides 0 by 0 on a degenerate triangle, as the scalar
        }
        if (h.has_value() != intersection<exact>(s.ray, scene.value()).has_value()) ++c.existence_unlike;
    } else {
        ok = ok && same_hit(batch.value(), truth);
    }
    if (!ok && ++c.wrong <= 5)
        std::printf("  %s: batch first hit unlike the scene's (%s, %s)\n", where.c_str(), truth ? "hit" : "none",
                    batch.value() ? "hit" : "none");
}

TEST_CASE("batch ray_triangles: the first hit is the scene's, every tier", "[batch]") {
    first_counts c[4];
    support::rng r(support::seed());
    for (long k = 0; k < support::cases(400); ++k) {
        const int kind = static_cast<int>(k % 3);
        const ray_set s = kind == 0 ? random_set(r, 128) : (kind == 1 ? mesh_set(r) : special_set(r));
        compare_first<exact>(s, c[0], "exact");
        compare_first<conservative>(s, c[1], "conservative");
        compare_first<aggressive>(s, c[2], "aggressive");
        compare_first<approximate>(s, c[3], "approximate");
    }
    std::printf("[cases] batch first hit against the scene's: %ld sets (%ld with a hit), unlike: %ld %ld %ld %ld (exact, conservative, "
                "aggressive, approximate; approximate: the values of the triangle it names); %ld sets with special values, %ld wrong; "
                "approximate hits whose existence is unlike the exact tier's: %ld\n",
                c[0].sets, c[0].hits, c[0].wrong, c[1].wrong, c[2].wrong, c[3].wrong, c[0].special,
                c[0].special_wrong + c[1].special_wrong + c[2].special_wrong + c[3].special_wrong, c[3].existence_unlike);
    for (const first_counts& x : c) CHECK((x.wrong == 0 && x.special_wrong == 0));
    CHECK(c[0].hits * 4 > c[0].sets);
}

TEST_CASE("batch ray_triangles: the exact lanes against the CGAL Epeck oracle, rays through a mesh", "[batch]") {
    support::rng r(support::seed());
    long lanes = 0, wrong = 0, skipped = 0;
    const long sets = support::cases(1000);
    for (long k = 0; k < sets; ++k) {
        const ray_set s = mesh_set(r);
        std::vector<std::uint8_t> out(s.triangles.size());
        REQUIRE(batch::intersects<exact>(s.ray, std::span<const triangle3>(s.triangles), out).has_value());
        double o[3], d[3];
        support::arr(s.ray.origin, o);
        support::arr(s.ray.direction, d);
        for (std::size_t i = 0; i < s.triangles.size(); ++i) {
            double a[3], b[3], c[3];
            support::arr(s.triangles[i].a, a);
            support::arr(s.triangles[i].b, b);
            support::arr(s.triangles[i].c, c);
            // the oracle's ray needs a direction and its triangle an area (the scalar test covers the rest)
            if (s.ray.direction == vec3{0, 0, 0} || oracle::triangle_is_degenerate(a, b, c)) {
                ++skipped;
                continue;
            }
            ++lanes;
            if ((out[i] == 1) != oracle::ray_triangle(o, d, a, b, c)) ++wrong;
        }
    }
    std::printf("[cases] batch ray_triangles exact against the oracle: %ld lanes, %ld wrong; %ld lanes with a degenerate triangle left to "
                "the scalar test\n",
                lanes, wrong, skipped);
    CHECK(wrong == 0);
    CHECK(skipped * 10 < lanes); // the degenerate triangles are a small share of the set
}

namespace {

// Triangles kept in floats (batch::triangles_soa_f). A float set: a float ray and triangles of
// floats, all at one power-of-two scale in [2^-16, 2^16] (so that every nonzero difference lies in
// the float tier's stated range [2^-40, 2^40]): random, or a grid mesh of integer coordinates that
// the ray passes exactly at a vertex, an edge or in its plane, with one-float-ulp nudges and
// collinear triangles; or special floats (NaN, infinities, the largest, subnormal). A lane is held
// to the bound where its differences lie in the stated range (in_float_range).
struct float_set {
    ray3 ray;
    std::vector<float> c[9];
    [[nodiscard]] batch::triangles_soa_f view() const { return {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]}; }
    [[nodiscard]] std::size_t size() const { return c[0].size(); }
    [[nodiscard]] triangle3 at(std::size_t i) const { return view()[i]; }
    void add(const float (&v)[9]) {
        for (int k = 0; k < 9; ++k) c[k].push_back(v[k]);
    }
};
float nudge_float(float x, int ulps) {
    for (; ulps > 0; --ulps) x = std::nextafter(x, INFINITY);
    for (; ulps < 0; ++ulps) x = std::nextafter(x, -INFINITY);
    return x;
}
float_set float_random_set(support::rng& r, int n) {
    const int k = r.integer(-16, 16);
    auto f = [&] { return std::ldexp(static_cast<float>(r.uniform(-1, 1)), k); };
    float_set s;
    const float o[3] = {f(), f(), f()}, aim[3] = {f(), f(), f()};
    s.ray = ray3{{o[0], o[1], o[2]}, {static_cast<double>(aim[0] - o[0]), aim[1] - o[1], aim[2] - o[2]}};
    for (int i = 0; i < 2 * n + 1; ++i) {
        float v[9];
        for (float& x : v) x = f();
        s.add(v);
    }
    return s;
}
float_set float_mesh_set(support::rng& r) {
    const int k = r.integer(-16, 10), perm = r.integer(0, 2);
    auto put = [&](float* v, double x, double y, double z) { // axes permuted cyclically, scaled by 2^k
        const double q[3] = {x, y, z};
        for (int a = 0; a < 3; ++a) v[a] = static_cast<float>(std::ldexp(q[(a + perm) % 3], k));
    };
    float_set s;
    auto triangle = [&](double ax, double ay, double bx, double by, double cx, double cy) {
        float v[9];
        put(v, ax, ay, 0), put(v + 3, bx, by, 0), put(v + 6, cx, cy, 0);
        if (r.integer(0, 7) == 0) v[r.integer(0, 8)] = nudge_float(v[r.integer(0, 8)], r.integer(-2, 2));
        s.add(v);
    };
    for (int i = -4; i < 4; ++i)
        for (int j = -4; j < 4; ++j) {
            triangle(i, j, i + 1, j, i + 1, j + 1);
            triangle(i, j, i + 1, j + 1, i, j + 1);
        }
    for (int c = 0; c < 5; ++c) { // collinear
        const double x = r.integer(-4, 4), y = r.integer(-4, 4);
        triangle(x, y, x + 1, y + 1, x + 2, y + 2);
    }
    const int kind = r.integer(0, 3);
    const double tx = r.integer(-4, 4) + (kind == 1 ? 0.5 : (kind == 2 ? 0.25 : 0.0)), ty = r.integer(-4, 4) + (kind == 2 ? 0.5 : 0.0);
    const double ox = r.integer(-8, 8), oy = r.integer(-8, 8), oz = kind == 3 ? 0.0 : r.integer(1, 8) * (r.coin() ? 1 : -1);
    float o[3], t[3];
    put(o, ox, oy, oz), put(t, tx, ty, 0);
    if (r.coin()) o[r.integer(0, 2)] = nudge_float(o[r.integer(0, 2)], r.integer(-2, 2));
    s.ray = ray3{{o[0], o[1], o[2]}, {static_cast<double>(t[0] - o[0]), t[1] - o[1], t[2] - o[2]}};
    return s;
}
float_set float_special_set(support::rng& r) {
    const float specials[] = {NAN, INFINITY, -INFINITY, 0x1.fffffep127f, -0x1p100f, 0x1p-149f, -0x1p-130f, 0x1p-126f, 0.0f, 1.0f, -1.0f};
    auto pick = [&] { return r.integer(0, 2) == 0 ? specials[r.integer(0, 10)] : static_cast<float>(r.uniform(-1, 1)); };
    float_set s;
    s.ray = ray3{{pick(), pick(), pick()}, {pick(), pick(), pick()}};
    for (int i = 0; i < 37; ++i) {
        float v[9];
        for (float& x : v) x = pick();
        s.add(v);
    }
    return s;
}

// Is lane i in the float tier's stated range: every nonzero difference (a vertex minus the origin,
// an edge, a direction's component) of magnitude in [2^-40, 2^40]?
bool in_float_range(const ray3& ray, const triangle3& t) {
    auto ok = [](double x) { return x == 0.0 || (std::fabs(x) >= 0x1p-40 && std::fabs(x) <= 0x1p40); };
    const point3 v[3] = {t.a, t.b, t.c};
    bool in = ok(ray.direction.x) && ok(ray.direction.y) && ok(ray.direction.z);
    for (int i = 0; i < 3; ++i) {
        const point3& p = v[i];
        const point3& q = v[(i + 1) % 3];
        in = in && ok(p.x - ray.origin.x) && ok(p.y - ray.origin.y) && ok(p.z - ray.origin.z) && ok(q.x - p.x) && ok(q.y - p.y) &&
             ok(q.z - p.z);
    }
    return in;
}

struct float_counts {
    long lanes = 0, out_of_range = 0, wrong[4] = {}, approx_unlike_exact = 0, outside_bound = 0, double_ray_wrong = 0;
    double most_margin_unlike = 0; // the largest margin at which an approximate lane in the range was wrong
};

// A float set's lanes: the filtered tiers against the scalar tier on the widened triangles, the
// approximate tier against the exact answer (wrong only within the stated bound, for a set in the
// stated range); then with the ray's origin moved off floats by one double ulp, the approximate
// tier against the scalar approximate answer (it runs in double then).
void compare_float(const float_set& s, float_counts& c, const std::string& where) {
    const std::size_t n = s.size();
    std::vector<std::uint8_t> out[4];
    for (auto& o : out) o.assign(n, 7);
    REQUIRE(batch::intersects<exact>(s.ray, s.view(), out[0]).has_value());
    REQUIRE(batch::intersects<conservative>(s.ray, s.view(), out[1]).has_value());
    REQUIRE(batch::intersects<aggressive>(s.ray, s.view(), out[2]).has_value());
    const auto met = batch::intersects<approximate>(s.ray, s.view(), out[3]);
    REQUIRE(met.has_value());
    ray3 off = s.ray;
    off.origin.x = support::nudge(off.origin.x, 1);
    std::vector<std::uint8_t> off_out(n, 7);
    REQUIRE(batch::intersects<approximate>(off, s.view(), off_out).has_value());
    std::size_t ones = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const triangle3 t = s.at(i);
        const bool in_range = in_float_range(s.ray, t);
        ++c.lanes;
        c.out_of_range += !in_range;
        const std::uint8_t truth[3] = {intersects<exact>(s.ray, t), intersects<conservative>(s.ray, t), intersects<aggressive>(s.ray, t)};
        for (int k = 0; k < 3; ++k)
            if (out[k][i] != truth[k] && ++c.wrong[k] <= 5)
                std::printf("  %s, float lane %zu, tier %d: scalar %d, batch %d\n", where.c_str(), i, k, truth[k], out[k][i]);
        ones += out[3][i] == 1;
        if (out[3][i] > 1) ++c.wrong[3];
        if (off_out[i] != (intersects<approximate>(off, t) ? 1 : 0)) ++c.double_ray_wrong;
        if (out[3][i] == truth[0]) continue;
        ++c.approx_unlike_exact;
        support_margin::margin_kernel mk;
        (void)detail::intersects(mk, s.ray, t);
        if (in_range && mk.min_rel > c.most_margin_unlike) c.most_margin_unlike = mk.min_rel;
        if (in_range && mk.min_rel > batch::float_approximate_bound && ++c.outside_bound <= 5)
            std::printf("  %s, float lane %zu: approximate wrong at margin %g: ray %s dir %s\n", where.c_str(), i, mk.min_rel,
                        str(s.ray.origin).c_str(), str(s.ray.direction).c_str());
    }
    if (met.value() != ones) ++c.wrong[3];
}

} // namespace

TEST_CASE("batch ray_triangles: float packets, the filtered tiers' lanes are the scalar answer and the float approximate tier keeps its "
          "bound, every target",
          "[batch]") {
    float_counts c[3]; // random, mesh, special
    const int targets = support::on_every_target("float", [&](support::rng& r, const std::string& where, const char*) {
        for (long k = 0; k < support::cases(200); ++k) {
            compare_float(float_random_set(r, 64), c[0], where + ", random");
            compare_float(float_mesh_set(r), c[1], where + ", mesh");
            compare_float(float_special_set(r), c[2], where + ", special");
        }
    });
    const char* names[3] = {"random", "mesh", "special"};
    for (int j = 0; j < 3; ++j) {
        std::printf("[cases] batch ray_triangles float %s: %d SIMD targets, %ld lanes (%ld outside the stated range); filtered lanes "
                    "unlike the scalar answer: exact %ld, "
                    "conservative %ld, aggressive %ld; approximate (float) unlike exact %ld (in the range at margins up to %g; outside the "
                    "bound 2^-16: %ld); approximate with a double ray unlike the scalar %ld\n",
                    names[j], targets, c[j].lanes, c[j].out_of_range, c[j].wrong[0], c[j].wrong[1], c[j].wrong[2], c[j].approx_unlike_exact,
                    c[j].most_margin_unlike, c[j].outside_bound, c[j].double_ray_wrong);
        for (long w : c[j].wrong) CHECK(w == 0);
        CHECK(c[j].outside_bound == 0);
        CHECK(c[j].double_ray_wrong == 0);
    }
    CHECK(targets >= 2);
    CHECK(c[1].out_of_range * 20 < c[1].lanes); // the mesh sets are mostly in the stated range
    CHECK(c[1].approx_unlike_exact > 0);        // and reach the float tier's boundary (else the bound is not tested)
}

namespace {
void float_sizes() {
    const std::vector<float> x{0.0f, 1.0f}, y{0.0f};
    const batch::triangles_soa_f uneven{x, x, x, x, x, x, x, x, y};
    std::vector<std::uint8_t> out(2);
    const auto bad = batch::intersects<approximate>(ray3{{0, 0, -1}, {0, 0, 1}}, uneven, out);
    REQUIRE(bad.has_error());
    CHECK(bad.error().code == errc::size_mismatch);
}
} // namespace

TEST_CASE("batch ray_triangles: sizes", "[batch]") {
    float_sizes();
    const ray3 ray{{0, 0, -1}, {0, 0, 1}};
    const std::vector<triangle3> ts(3, triangle3{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}});
    std::vector<std::uint8_t> out(2);
    const auto refused = batch::intersects<exact>(ray, std::span<const triangle3>(ts), out);
    REQUIRE(refused.has_error());
    CHECK(refused.error().code == errc::size_mismatch);
    out.resize(3);
    const auto all = batch::intersects<exact>(ray, std::span<const triangle3>(ts), out);
    REQUIRE(all.has_value());
    CHECK(all.value() == 3);
    const auto none = batch::intersects<approximate>(ray, std::span<const triangle3>{}, std::span<std::uint8_t>{});
    REQUIRE(none.has_value());
    CHECK(none.value() == 0);
    const std::vector<double> x{0.0, 1.0}, y{0.0};
    const batch::triangles_soa uneven{x, x, x, x, x, x, x, x, y};
    out.resize(2);
    const auto bad = batch::intersects<exact>(ray, uneven, out);
    REQUIRE(bad.has_error());
    CHECK(bad.error().code == errc::size_mismatch);
    const std::vector<ray3> rays(3, ray);
    const auto short_out = batch::intersects<exact>(std::span<const ray3>(rays), ts[0], out);
    REQUIRE(short_out.has_error());
    CHECK(short_out.error().code == errc::size_mismatch);
    out.resize(3);
    const auto three = batch::intersects<exact>(std::span<const ray3>(rays), ts[0], out);
    REQUIRE(three.has_value());
    CHECK(three.value() == 3);
    const auto uneven_rays = batch::intersects<exact>(batch::rays_soa{x, x, x, x, x, y}, ts[0], std::span<std::uint8_t>(out.data(), 2));
    REQUIRE(uneven_rays.has_error());
}

} // namespace test_batch_ray_triangles
