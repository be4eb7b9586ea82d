// A scene against a scene: intersects<Tier>(a, b) and every pair of triangles met,
// intersecting<Tier>(a, b, out), in the four tiers against the brute force (the scalar
// triangle-triangle query of the same tier over every pair, whose exact tier the pair's own test
// checks against CGAL): random soups against random soups at scales 2^-500..2^500, a grid against
// a copy of itself moved by whole cells and half cells (shared vertices, edges and coplanar
// faces: exact contacts everywhere), and a real mesh against a moved copy of itself.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>
import incidence;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"
#include "testkit/scene_cases.hpp"

namespace test_scene_scene_scene { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {

using pair_set = std::set<std::pair<std::size_t, std::size_t>>;

struct counts {
    long cases = 0, pairs = 0, wrong = 0, approximate_other = 0;
};

template <class Tier>
void check_tier(const std::vector<triangle3>& ta, const std::vector<triangle3>& tb, const scene3& a, const scene3& b, const pair_set& truth,
                counts& c) {
    pair_set brute, near;
    for (std::size_t i = 0; i < ta.size(); ++i)
        for (std::size_t j = 0; j < tb.size(); ++j)
            if (intersects<Tier>(ta[i], tb[j])) {
                brute.insert({i, j});
                if (support::boxes_meet(support::box_of(ta[i]), support::box_of(tb[j]))) near.insert({i, j});
            }
    std::vector<std::pair<std::size_t, std::size_t>> out;
    const std::size_t n = intersecting<Tier>(a, b, out);
    const pair_set listed(out.begin(), out.end());
    const bool ok = n == out.size() && listed.size() == n && intersects<Tier>(a, b) == !listed.empty() &&
                    support::set_contract<Tier>(listed, brute, truth, near);
    if constexpr (std::is_same_v<Tier, approximate>) c.approximate_other += listed != brute;
    if (!ok && ++c.wrong <= 5)
        std::printf("  %s: %zu pairs listed, %zu by the brute force\n", typeid(Tier).name(), listed.size(), brute.size());
}

void check(const std::vector<triangle3>& ta, const std::vector<triangle3>& tb, counts& c) {
    const auto a = scene3::make(ta), b = scene3::make(tb);
    REQUIRE(a.has_value());
    REQUIRE(b.has_value());
    ++c.cases;
    pair_set truth;
    for (std::size_t i = 0; i < ta.size(); ++i)
        for (std::size_t j = 0; j < tb.size(); ++j)
            if (intersects<exact>(ta[i], tb[j])) truth.insert({i, j});
    c.pairs += static_cast<long>(truth.size());
    check_tier<exact>(ta, tb, a.value(), b.value(), truth, c);
    check_tier<conservative>(ta, tb, a.value(), b.value(), truth, c);
    check_tier<aggressive>(ta, tb, a.value(), b.value(), truth, c);
    check_tier<approximate>(ta, tb, a.value(), b.value(), truth, c);
}

} // namespace

TEST_CASE("scene against scene: random soups, every tier against the brute force", "[scene]") {
    support::rng r(support::seed());
    counts c;
    const long sets = support::cases(300);
    for (long k = 0; k < sets; ++k) {
        support::transform tr = support::random_transform(r, false);
        check(support::random_soup(r, tr, r.integer(1, 60)), support::random_soup(r, tr, r.integer(1, 60)), c);
    }
    std::printf(
        "[cases] scene against scene, soups: %ld pairs of scenes, %ld pairs of triangles met; %ld wrong; approximate sets unlike the "
        "brute force %ld\n",
        c.cases, c.pairs, c.wrong, c.approximate_other);
    CHECK(c.wrong == 0);
    CHECK(c.pairs > c.cases);
}

TEST_CASE("scene against scene: a grid against a moved copy (shared vertices, edges, coplanar faces), against the brute force", "[scene]") {
    support::rng r(support::seed());
    counts c;
    const long sets = support::cases(200);
    for (long k = 0; k < sets; ++k) {
        const support::grid g = support::make_grid(r);
        std::vector<triangle3> moved;
        const double dx = r.integer(-2, 2) * 0.5, dy = r.integer(-2, 2) * 0.5, dz = r.integer(0, 2) * 0.5;
        const support::grid& h = g; // the same frame (scale, translation, axes)
        for (int z = 0; z < 2; ++z)
            for (int i = -4; i < 4; i += 2)
                for (int j = -4; j < 4; j += 2) {
                    moved.push_back({h.at(i + dx, j + dy, z + dz), h.at(i + 1 + dx, j + dy, z + dz), h.at(i + 1 + dx, j + 1 + dy, z + dz)});
                    moved.push_back({h.at(i + dx, j + dy, z + dz), h.at(i + dx, j + dy, z + dz - 1), h.at(i + 1 + dx, j + 1 + dy, z + dz)});
                }
        check(g.ts, moved, c);
    }
    std::printf(
        "[cases] scene against scene, grids: %ld pairs of scenes, %ld pairs of triangles met; %ld wrong; approximate sets unlike the "
        "brute force %ld (near-degenerate: allowed)\n",
        c.cases, c.pairs, c.wrong, c.approximate_other);
    CHECK(c.wrong == 0);
    CHECK(c.pairs > 10 * c.cases);
}

TEST_CASE("scene against scene: a real mesh against a moved copy (libcgal-demo), exact against the brute force", "[scene]") {
    if (support::real_meshes().empty() && support::meshes_required()) FAIL("the real meshes are missing (run.sh unpacks them)");
    const auto file = std::filesystem::path(INCIDENCE_SOURCE_DIR) / "build/data/meshes/elephant.off";
    if (!std::filesystem::exists(file)) return;
    const audit::mesh m = audit::read_mesh(file.string());
    std::vector<triangle3> ta, tb;
    double lo = m.vertices[0].x, hi = lo;
    for (const point3& p : m.vertices) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    const double shift = 0.0625 * (hi - lo);
    for (const auto& f : m.faces) {
        const triangle3 t{m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]};
        ta.push_back(t);
        tb.push_back({{t.a.x + shift, t.a.y, t.a.z}, {t.b.x + shift, t.b.y, t.b.z}, {t.c.x + shift, t.c.y, t.c.z}});
    }
    ta.resize(std::min(ta.size(), static_cast<std::size_t>(support::cases(6000)))); // all; 300 in the sanitizer build
    const auto a = scene3::make(ta), b = scene3::make(tb);
    REQUIRE(a.has_value());
    REQUIRE(b.has_value());
    std::set<std::pair<std::size_t, std::size_t>> brute;
    for (std::size_t i = 0; i < ta.size(); ++i)
        for (std::size_t j = 0; j < tb.size(); ++j)
            if (support::boxes_meet(support::box_of(ta[i]), support::box_of(tb[j])) && intersects<exact>(ta[i], tb[j]))
                brute.insert({i, j});
    std::vector<std::pair<std::size_t, std::size_t>> out;
    const std::size_t n = intersecting<exact>(a.value(), b.value(), out);
    const pair_set listed(out.begin(), out.end());
    std::printf(
        "[cases] scene against scene, elephant (%zu of its %zu triangles) against a copy moved by 1/16 of its width: %zu pairs met, "
        "%zu by the brute force\n",
        ta.size(), tb.size(), n, brute.size());
    CHECK(listed == brute);
    CHECK(n == out.size());
    CHECK(n > ta.size() / 100);
}

TEST_CASE("scene against scene: empty scenes", "[scene]") {
    const auto empty = scene3::make(std::vector<triangle3>{});
    const auto one = scene3::make(std::vector<triangle3>{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
    REQUIRE(empty.has_value());
    REQUIRE(one.has_value());
    std::vector<std::pair<std::size_t, std::size_t>> out;
    CHECK(!intersects<exact>(empty.value(), one.value()));
    CHECK(intersecting<approximate>(one.value(), empty.value(), out) == 0);
    CHECK(intersects<exact>(one.value(), one.value()));
    CHECK(intersecting<exact>(one.value(), one.value(), out) == 1);
}

} // namespace test_scene_scene_scene
