// intersects and intersection of a line, a ray or a segment against a scene3, in the four tiers,
// against the brute force (the scalar query of the same tier looped over every triangle) and, for
// the exact first contact, against the CGAL Epeck oracle (the first-contact triangles and the
// parameter, by other methods than the library's): random triangle soups at scales 2^-500..2^500;
// grids whose vertices and edges the objects pass exactly, with coplanar objects, duplicated
// triangles (exact ties: the least index wins) and degenerate ones; scenes beyond the fast slab
// test's range (coordinates near 2^1000 and subnormal); and the real meshes from libcgal-demo.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <bit>
#include <type_traits>
#include <array>
#include <filesystem>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>
import incidence;
#include "testkit/testing.hpp"
#include "testkit/linear_objects.hpp"
#include "testkit/point_sets.hpp"
#include "testkit/scene_cases.hpp"

namespace test_scene_linear_scene { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::box_of;
using support::grid;
using support::make_grid;
using support::random_soup;

namespace {

struct counts {
    long cases = 0, hits = 0, ties = 0, oracle_checked = 0, oracle_inside = 0, wrong = 0, approximate_other = 0;
};

std::string str(point3 p) { return "(" + support::hex(p.x) + ", " + support::hex(p.y) + ", " + support::hex(p.z) + ")"; }
std::string str(const ray3& x) { return "ray " + str(x.origin) + " dir " + str(point3{x.direction.x, x.direction.y, x.direction.z}); }
std::string str(const line3& x) { return "line " + str(x.origin) + " dir " + str(point3{x.direction.x, x.direction.y, x.direction.z}); }
std::string str(const segment3& x) { return "segment " + str(x.a) + " " + str(x.b); }

void fail(counts& c, const std::string& what, const std::string& object) {
    if (++c.wrong <= 8) std::printf("  %s: %s\n", what.c_str(), object.c_str());
}

bool same(const triangle_hit<double>& a, const scene_hit<double>& b) {
    return a.t == b.t && a.point == b.point && a.normal == b.normal && a.u == b.u && a.v == b.v && a.w == b.w;
}

oracle::mesh_data soup_data(const std::vector<triangle3>& ts) {
    oracle::mesh_data m;
    for (const triangle3& t : ts) {
        const auto n = static_cast<unsigned>(m.v.size());
        for (point3 p : {t.a, t.b, t.c}) m.v.push_back({p.x, p.y, p.z});
        m.t.push_back({n, n + 1, n + 2});
    }
    return m;
}

// Yes/no: exact and aggressive as the brute force (an aggressive yes is certain, so the triangles the
// hierarchy rules out are aggressive noes too); conservative between the exact answer and the brute
// force's (a triangle ruled out by its box is not met, where the scalar conservative tier may still
// say yes for it); approximate: the plain-double answers of the triangles whose boxes the object may
// meet, so between those of the boxes it meets exactly and the brute force's (counted where unlike
// the brute force).
template <class Tier, class S>
void check_any(const std::vector<triangle3>& ts, const scene3& sc, const S& x, counts& c, const char* tier, bool truth) {
    bool brute = false, in_met_boxes = false;
    for (const triangle3& t : ts) {
        const bool yes = intersects<Tier>(x, t);
        brute = brute || yes;
        in_met_boxes = in_met_boxes || (yes && intersects<exact>(x, box_of(t)));
    }
    const bool a = intersects<Tier>(x, sc), b = intersects<Tier>(sc, x);
    bool ok = a == brute && b == brute;
    if constexpr (std::is_same_v<Tier, conservative>) ok = a == b && (a || !truth) && (!a || brute);
    if constexpr (std::is_same_v<Tier, approximate>) {
        ok = a == b && (a || !in_met_boxes) && (!a || brute);
        c.approximate_other += ok && a != brute;
    }
    if (!ok) fail(c, std::string(tier) + " intersects unlike the brute force's (" + (brute ? "yes" : "no") + ")", str(x));
}

template <class V>
bool bits_equal(const V& a, const V& b) {
    if constexpr (std::is_same_v<V, point3> || std::is_same_v<V, vec3>)
        return bits_equal(a.x, b.x) && bits_equal(a.y, b.y) && bits_equal(a.z, b.z);
    else return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Every tier against the brute force; the exact tier also against CGAL, the interval tiers'
// values against CGAL's exact ones.
template <class S>
void check(const std::vector<triangle3>& ts, const scene3& sc, const S& x, counts& c, bool with_oracle) {
    ++c.cases;
    bool truth = false;
    for (const triangle3& t : ts) truth = truth || intersects<exact>(x, t);
    check_any<exact>(ts, sc, x, c, "exact", truth);
    check_any<conservative>(ts, sc, x, c, "conservative", truth);
    check_any<aggressive>(ts, sc, x, c, "aggressive", truth);
    check_any<approximate>(ts, sc, x, c, "approximate", truth);

    // exact: the least correctly rounded t of the brute force, a triangle that has it, its values
    std::optional<double> least;
    std::vector<std::optional<triangle_hit<double>>> each(ts.size());
    for (std::size_t i = 0; i < ts.size(); ++i) {
        each[i] = intersection<exact>(x, ts[i]);
        if (each[i] && (!least || each[i]->t < *least)) least = each[i]->t;
    }
    const auto h = intersection<exact>(x, sc);
    const auto h2 = intersection<exact>(sc, x);
    if (h.has_value() != least.has_value() || h2.has_value() != h.has_value()) {
        fail(c, std::string("exact first hit ") + (h ? "found" : "missing") + " against the brute force", str(x));
        return;
    }
    if (h) {
        ++c.hits;
        long at_least = 0;
        for (const auto& e : each) at_least += e && e->t == *least;
        c.ties += at_least > 1;
        if (h->t != *least || !each[h->triangle] || !same(*each[h->triangle], *h) || h2->triangle != h->triangle ||
            h->exists != certainty::yes)
            fail(c,
                 "exact first hit: triangle " + std::to_string(h->triangle) + " t " + support::hex(h->t) + ", brute force least t " +
                     support::hex(*least),
                 str(x));
    }
    if (with_oracle) {
        const oracle::exact_hit first = oracle::exact_mesh(support::object_of(x), soup_data(ts));
        if (first.first_triangle_ok(static_cast<std::size_t>(-1))) {
            ++c.oracle_inside; // the oracle's even-odd inside of a soup: no triangle to check
        } else {
            ++c.oracle_checked;
            if (first.exists() != h.has_value() ||
                (h && (!first.first_triangle_ok(h->triangle) || !first.rounds_to(oracle::quantity::t_enter, h->t))))
                fail(c, "exact first hit against the oracle", str(x));
            else if (h)
                for (std::size_t j = 0; j < h->triangle; ++j) // exact ties: the least index
                    if (first.first_triangle_ok(j)) {
                        fail(c, "exact first hit: triangle " + std::to_string(j) + " ties and comes first", str(x));
                        break;
                    }
        }
    }

    // conservative and aggressive: the exact tier's triangle, intervals around the exact values
    auto enclosing = [&](const auto& hi, const char* tier) {
        if (hi.has_value() != h.has_value()) return fail(c, std::string(tier) + " first hit exists unlike the exact tier's", str(x));
        if (!hi) return;
        if (hi->triangle != h->triangle || hi->exists != certainty::yes)
            return fail(c, std::string(tier) + " first hit names another triangle", str(x));
        const triangle3& t = ts[h->triangle];
        double a[3], b[3], cc[3];
        support::arr(t.a, a);
        support::arr(t.b, b);
        support::arr(t.c, cc);
        const oracle::exact_hit e = oracle::exact_triangle(support::object_of(x), a, b, cc);
        using q = oracle::quantity;
        const std::pair<q, interval> values[] = {{q::t_enter, hi->t},   {q::x, hi->point.x},  {q::y, hi->point.y}, {q::z, hi->point.z},
                                                 {q::u, hi->u},         {q::v, hi->v},        {q::w, hi->w},       {q::nx, hi->normal.x},
                                                 {q::ny, hi->normal.y}, {q::nz, hi->normal.z}};
        for (const auto& [what, iv] : values)
            if (e.has(what) && !e.within(what, iv.lo, iv.hi))
                return fail(c, std::string(tier) + " interval misses the exact value " + std::to_string(static_cast<int>(what)), str(x));
    };
    if (with_oracle || c.cases % 8 == 0) {
        enclosing(intersection<conservative>(x, sc), "conservative");
        enclosing(intersection<aggressive>(sc, x), "aggressive");
    }

    // approximate: the named triangle's scalar values, bit for bit; existence as the brute force's
    const auto ha = intersection<approximate>(x, sc);
    bool brute = false;
    for (const triangle3& t : ts) brute = brute || intersection<approximate>(x, t).has_value();
    if (ha.has_value() != brute) ++c.approximate_other;
    if (ha) {
        const auto one = intersection<approximate>(x, ts[ha->triangle]);
        if (!one || !bits_equal(one->t, ha->t) || !bits_equal(one->point, ha->point) || !bits_equal(one->normal, ha->normal) ||
            !bits_equal(one->u, ha->u) || !bits_equal(one->v, ha->v) || !bits_equal(one->w, ha->w) || ha->exists != certainty::uncertain)
            fail(c, "approximate first hit differs from its triangle's scalar values", str(x));
    }
}

// A ray, a segment or a line from o towards p (the segment ends there or beyond).
template <class F>
void each_kind(support::rng& r, point3 o, point3 p, F&& f) {
    const vec3 d{p.x - o.x, p.y - o.y, p.z - o.z};
    switch (r.integer(0, 2)) {
    case 0: f(ray3{o, d}); break;
    case 1: f(segment3{o, r.coin() ? p : point3{p.x + d.x, p.y + d.y, p.z + d.z}}); break;
    default: f(line3{o, d}); break;
    }
}

// An object aimed exactly at a grid vertex, an edge point or a cell, or lying in a grid's plane.
template <class F>
void grid_object(support::rng& r, const grid& g, F&& f) {
    using support::small;
    const int kind = r.integer(0, 3);
    const double tx = r.integer(-4, 4) + (kind == 1 ? 0.5 : (kind == 2 ? 0.25 : 0.0)), ty = r.integer(-4, 4) + (kind == 2 ? 0.5 : 0.0);
    const double z = r.integer(0, 1);
    const double ox = small(r), oy = small(r), oz = kind == 3 ? z : small(r);
    each_kind(r, g.at(ox, oy, oz), g.at(tx, ty, z), f);
}

} // namespace

TEST_CASE("scene: a line, a ray, a segment against random triangle soups, every tier against the brute force and CGAL", "[scene]") {
    support::rng r(support::seed());
    counts c;
    const long sets = support::cases(1000);
    for (long k = 0; k < sets; ++k) {
        support::transform tr = support::random_transform(r, false);
        const std::vector<triangle3> ts = random_soup(r, tr, r.integer(1, 160));
        const auto sc = scene3::make(ts);
        REQUIRE(sc.has_value());
        for (int j = 0; j < 4; ++j) {
            const point3 o{tr.apply(r.uniform(-2, 2), 0), tr.apply(r.uniform(-2, 2), 1), tr.apply(r.uniform(-2, 2), 2)};
            const triangle3& t = ts[static_cast<std::size_t>(r.integer(0, static_cast<int>(ts.size()) - 1))];
            const point3 aim =
                j == 0 ? t.a
                       : point3{t.a.x / 4 + t.b.x / 4 + t.c.x / 2, t.a.y / 4 + t.b.y / 4 + t.c.y / 2, t.a.z / 4 + t.b.z / 4 + t.c.z / 2};
            each_kind(r, o, aim, [&](const auto& x) { check(ts, sc.value(), x, c, true); });
        }
    }
    std::printf("[cases] scene soups: %ld objects, %ld hits, %ld exact ties of the rounded t, %ld checked by the oracle (%ld in its "
                "even-odd inside, unchecked); %ld wrong; approximate unlike its brute force %ld\n",
                c.cases, c.hits, c.ties, c.oracle_checked, c.oracle_inside, c.wrong, c.approximate_other);
    CHECK(c.wrong == 0);
    CHECK(c.approximate_other * 100 < c.cases); // within its contract (check_any), and unlike the brute force rarely
    CHECK(c.oracle_inside * 4 < c.oracle_checked);
}

TEST_CASE("scene: objects through grid vertices and edges, in the grid's plane, with repeated and degenerate triangles", "[scene]") {
    support::rng r(support::seed());
    counts c;
    const long sets = support::cases(2000);
    for (long k = 0; k < sets; ++k) {
        const grid g = make_grid(r);
        const auto sc = scene3::make(g.ts);
        REQUIRE(sc.has_value());
        grid_object(r, g, [&](const auto& x) { check(g.ts, sc.value(), x, c, true); });
    }
    std::printf(
        "[cases] scene grids: %ld objects, %ld hits, %ld exact ties of the rounded t, %ld checked by the oracle (%ld in its even-odd "
        "inside, unchecked); %ld wrong; approximate unlike its brute force %ld (near-degenerate: allowed)\n",
        c.cases, c.hits, c.ties, c.oracle_checked, c.oracle_inside, c.wrong, c.approximate_other);
    CHECK(c.wrong == 0);
    CHECK(c.ties * 10 > c.hits); // the repeated triangles and shared edges make ties common
    CHECK(c.oracle_inside * 4 < c.oracle_checked);
}

TEST_CASE("scene: beyond the fast slab test's range (coordinates near 2^1000, subnormal ones, tiny directions)", "[scene]") {
    support::rng r(support::seed());
    counts c;
    const long sets = support::cases(500);
    for (long k = 0; k < sets; ++k) {
        support::transform tr;
        tr.r = &r;
        tr.nudged = false;
        tr.k = r.coin() ? r.integer(990, 1015) : r.integer(-1074, -1040);
        const std::vector<triangle3> ts = random_soup(r, tr, r.integer(1, 60));
        const auto sc = scene3::make(ts);
        REQUIRE(sc.has_value());
        const point3 o{tr.apply(r.uniform(-2, 2), 0), tr.apply(r.uniform(-2, 2), 1), tr.apply(r.uniform(-2, 2), 2)};
        const triangle3& t = ts[static_cast<std::size_t>(r.integer(0, static_cast<int>(ts.size()) - 1))];
        each_kind(r, o, t.a, [&](const auto& x) { check(ts, sc.value(), x, c, false); });
        // a direction of subnormal size, on a scene at scale 1
        support::transform one;
        one.r = &r;
        one.nudged = false;
        const std::vector<triangle3> unit = random_soup(r, one, 20);
        const auto su = scene3::make(unit);
        REQUIRE(su.has_value());
        const point3 o1{r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-2, 2)};
        const point3 a = unit[static_cast<std::size_t>(r.integer(0, 19))].b;
        check(unit, su.value(), ray3{o1, vec3{(a.x - o1.x) * 0x1p-1070, (a.y - o1.y) * 0x1p-1070, (a.z - o1.z) * 0x1p-1070}}, c, false);
    }
    std::printf("[cases] scene far from scale 1: %ld objects, %ld hits; %ld wrong; approximate unlike its brute force %ld\n", c.cases,
                c.hits, c.wrong, c.approximate_other);
    CHECK(c.wrong == 0);
}

TEST_CASE("scene: rays into the real meshes (libcgal-demo), every tier against the brute force, exact against CGAL", "[scene]") {
    const std::vector<support::point_set> names = support::real_meshes();
    if (names.empty() && support::meshes_required()) FAIL("the real meshes are missing (run.sh unpacks them)");
    support::rng r(support::seed());
    const std::filesystem::path dir = std::filesystem::path(INCIDENCE_SOURCE_DIR) / "build/data/meshes";
    for (const char* name : {"bunny00", "fandisk"}) {
        const auto file = dir / (std::string(name) + ".off");
        if (!std::filesystem::exists(file)) continue;
        const audit::mesh m = audit::read_mesh(file.string());
        std::vector<triangle3> ts;
        for (const auto& f : m.faces) ts.push_back({m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]});
        const auto sc = scene3::make(ts);
        REQUIRE(sc.has_value());
        aabb3 box{m.vertices[0], m.vertices[0]};
        for (const point3& p : m.vertices)
            box = {{std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)},
                   {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)}};
        const point3 mid{box.min.x / 2 + box.max.x / 2, box.min.y / 2 + box.max.y / 2, box.min.z / 2 + box.max.z / 2};
        const double reach = 2 * std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
        counts c;
        const long rays = support::cases(1000) / 10; // 100, and 10 in the sanitizer build (brute force over the mesh per ray)
        for (long k = 0; k < rays; ++k) {
            const point3 o{mid.x + reach * r.uniform(-1, 1), mid.y + reach * r.uniform(-1, 1), mid.z + reach * r.uniform(-1, 1)};
            const point3 v = m.vertices[static_cast<std::size_t>(r.integer(0, static_cast<int>(m.vertices.size()) - 1))];
            const point3 aim = r.coin() ? v : point3{v.x + reach * 0.01 * r.uniform(-1, 1), v.y, v.z};
            check(ts, sc.value(), ray3{o, vec3{aim.x - o.x, aim.y - o.y, aim.z - o.z}}, c, k % 10 == 0);
        }
        std::printf("[cases] scene %s (%zu triangles): %ld rays, %ld hits; %ld wrong; approximate unlike its brute force %ld\n", name,
                    ts.size(), c.cases, c.hits, c.wrong, c.approximate_other);
        CHECK(c.wrong == 0);
    }
}

TEST_CASE("scene: bad input and empty scenes", "[scene]") {
    const double nan = std::nan(""), inf = INFINITY;
    const std::vector<triangle3> bad{{{0, 0, 0}, {1, 0, 0}, {0, nan, 0}}};
    REQUIRE(scene3::make(bad).has_error());
    CHECK(scene3::make(bad).error().code == errc::not_finite);
    const std::vector<triangle3> infinite{{{0, 0, 0}, {inf, 0, 0}, {0, 1, 0}}};
    CHECK(scene3::make(infinite).error().code == errc::not_finite);
    const std::vector<point3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<std::array<std::uint32_t, 3>> f{{0, 1, 3}};
    CHECK(scene3::make(v, f).error().code == errc::index_out_of_range);
    const auto empty = scene3::make(std::vector<triangle3>{});
    REQUIRE(empty.has_value());
    CHECK(empty.value().empty());
    CHECK(!intersects<exact>(ray3{{0, 0, 0}, {1, 0, 0}}, empty.value()));
    CHECK(!intersection<conservative>(line3{{0, 0, 0}, {1, 0, 0}}, empty.value()).has_value());
    const std::vector<triangle3> one{{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}};
    const auto sc = scene3::make(one);
    REQUIRE(sc.has_value());
    for (const ray3& x : {ray3{{nan, 0, 0}, {0, 0, 1}}, ray3{{0, 0, 0}, {0, inf, 1}}, ray3{{0, 0, 0}, {nan, nan, nan}}}) {
        CHECK(!intersects<exact>(x, sc.value()));
        CHECK(!intersects<conservative>(x, sc.value()));
        CHECK(!intersects<approximate>(x, sc.value()));
        CHECK(!intersection<exact>(x, sc.value()).has_value());
        CHECK(!intersection<aggressive>(x, sc.value()).has_value());
        CHECK(!intersection<approximate>(x, sc.value()).has_value());
    }
    // a zero direction is the point itself: on the triangle, met at t = 0
    const auto at = intersection<exact>(ray3{{0.25, 0.25, 1}, {0, 0, 0}}, sc.value());
    REQUIRE(at.has_value());
    CHECK(at->t == 0.0);
    CHECK(at->triangle == 0);
    CHECK(!intersection<exact>(ray3{{0.25, 0.25, 2}, {0, 0, 0}}, sc.value()).has_value());
}

} // namespace test_scene_linear_scene
