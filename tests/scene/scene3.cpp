// scene3's hierarchy: every triangle in exactly one leaf, source() a permutation, every node's box
// exactly the bounds of the vertices below it (no rounding), children inside their parent, depth
// within max_depth; on random soups at every scale, on many copies of one triangle (no split can
// separate them), on a long chain that a median split would make deep, and on the real meshes.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>
import incidence;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"

namespace test_scene_scene3 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {

aabb3 join(const aabb3& a, const aabb3& b) {
    return {{std::min(a.min.x, b.min.x), std::min(a.min.y, b.min.y), std::min(a.min.z, b.min.z)},
            {std::max(a.max.x, b.max.x), std::max(a.max.y, b.max.y), std::max(a.max.z, b.max.z)}};
}
aabb3 box_of(const triangle3& t) { return join(join({t.a, t.a}, {t.b, t.b}), {t.c, t.c}); }
bool inside(const aabb3& a, const aabb3& b) {
    return b.min.x <= a.min.x && b.min.y <= a.min.y && b.min.z <= a.min.z && a.max.x <= b.max.x && a.max.y <= b.max.y && a.max.z <= b.max.z;
}

// The hierarchy's invariants; the number of violations (printed).
long verify(const std::vector<triangle3>& given, const scene3& s) {
    long bad = 0;
    auto fail = [&](const std::string& what) {
        if (++bad <= 5) std::printf("  %s\n", what.c_str());
    };
    if (s.size() != given.size()) fail("size");
    std::vector<int> seen(given.size(), 0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::size_t k = s.source(i);
        if (k >= given.size()) {
            fail("source out of range");
            continue;
        }
        ++seen[k];
        const triangle3& t = s.triangles()[i];
        const triangle3& u = given[k];
        if (!(t.a == u.a && t.b == u.b && t.c == u.c)) fail("triangle " + std::to_string(i) + " is not its source's");
    }
    for (int n : seen)
        if (n != 1) fail("a triangle is not held exactly once");
    if (given.empty()) return bad + (s.nodes().empty() ? 0 : 1);
    std::vector<int> in_leaf(s.size(), 0);
    struct item {
        std::uint32_t node;
        int depth;
    };
    std::vector<item> todo{{0, 0}};
    while (!todo.empty()) {
        const item it = todo.back();
        todo.pop_back();
        const scene3::node& n = s.nodes()[it.node];
        if (it.depth > scene3::max_depth) fail("deeper than max_depth");
        aabb3 exact_box{};
        if (n.leaf()) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                ++in_leaf[i];
                exact_box = i == n.first ? box_of(s.triangles()[i]) : join(exact_box, box_of(s.triangles()[i]));
            }
        } else {
            const aabb3 a = s.nodes()[n.first].box, b = s.nodes()[n.first + 1].box;
            exact_box = join(a, b);
            if (!inside(a, n.box) || !inside(b, n.box)) fail("a child outside its parent");
            todo.push_back({n.first, it.depth + 1});
            todo.push_back({n.first + 1, it.depth + 1});
        }
        if (!(exact_box.min == n.box.min && exact_box.max == n.box.max)) fail("a box is not its triangles' exact bounds");
    }
    for (int n : in_leaf)
        if (n != 1) fail("a triangle is not in exactly one leaf");
    return bad;
}

} // namespace

TEST_CASE("scene3: the hierarchy's invariants on random soups at every scale", "[scene]") {
    support::rng r(support::seed());
    long bad = 0, sets = support::cases(200), moderate = 0;
    for (long k = 0; k < sets; ++k) {
        support::transform tr = support::random_transform(r, true);
        if (k % 10 == 0) tr.k = r.coin() ? 1000 : -1070;
        std::vector<triangle3> ts;
        const int n = r.integer(0, 400);
        auto p = [&] { return point3{support::random_coord(r, tr, 0), support::random_coord(r, tr, 1), support::random_coord(r, tr, 2)}; };
        for (int i = 0; i < n; ++i) ts.push_back({p(), p(), p()});
        const auto s = scene3::make(ts);
        REQUIRE(s.has_value());
        bad += verify(ts, s.value());
        moderate += s.value().moderate();
    }
    std::printf("[cases] scene3 random: %ld scenes (%ld within the fast slab range), %ld violations\n", sets, moderate, bad);
    CHECK(bad == 0);
    CHECK(moderate < sets);
}

TEST_CASE("scene3: copies of one triangle, a long chain, the largest coordinates", "[scene]") {
    const std::vector<triangle3> copies(1000, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const auto c = scene3::make(copies);
    REQUIRE(c.has_value());
    CHECK(verify(copies, c.value()) == 0);
    std::vector<triangle3> chain; // sizes doubling: centroids that crowd into one bin
    for (int i = 0; i < 900; ++i) {
        const double x = std::ldexp(1.0, i - 450);
        chain.push_back({{x, 0, 0}, {x, 1, 0}, {x, 0, 1}});
    }
    const auto ch = scene3::make(chain);
    REQUIRE(ch.has_value());
    CHECK(verify(chain, ch.value()) == 0);
    const double big = 0x1.fffffffffffffp1023;
    const std::vector<triangle3> huge{{{-big, -big, -big}, {big, big, big}, {big, -big, 0}}, {{0, 0, 0}, {big, 0, 0}, {0, -big, big}}};
    const auto h = scene3::make(huge);
    REQUIRE(h.has_value());
    CHECK(!h.value().moderate());
    CHECK(verify(huge, h.value()) == 0);
    CHECK(intersects<exact>(ray3{{0, 0, -1}, {0, 0, 1}}, h.value()));
}

TEST_CASE("scene3: the hierarchy of the real meshes (libcgal-demo)", "[scene]") {
    if (support::real_meshes().empty() && support::meshes_required()) FAIL("the real meshes are missing (run.sh unpacks them)");
    const std::filesystem::path dir = std::filesystem::path(INCIDENCE_SOURCE_DIR) / "build/data/meshes";
    for (const char* name : {"bunny00", "armadillo", "elephant", "fandisk", "ChineseDragon-10kv"}) {
        const auto file = dir / (std::string(name) + ".off");
        if (!std::filesystem::exists(file)) continue;
        const audit::mesh m = audit::read_mesh(file.string());
        const auto s = scene3::make(m.vertices, m.faces);
        REQUIRE(s.has_value());
        std::vector<triangle3> ts;
        for (const auto& f : m.faces) ts.push_back({m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]});
        std::size_t leaves = 0;
        for (const auto& n : s.value().nodes()) leaves += n.leaf();
        std::printf("[cases] scene3 %s: %zu triangles, %zu nodes, %zu leaves\n", name, ts.size(), s.value().nodes().size(), leaves);
        CHECK(verify(ts, s.value()) == 0);
    }
}

} // namespace test_scene_scene3
