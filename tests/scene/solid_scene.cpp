// intersects<Tier>(solid, scene) for a box, an oriented box, a triangle, a tetrahedron and a
// frustum (from a camera), and
// intersecting<Tier>(shape, scene, out) (every triangle met, for those and a ray, a segment and a
// line), in the four tiers against the brute force (the scalar query of the same tier over every
// triangle, whose exact tier the pairs' own tests check against CGAL): on random soups at scales
// 2^-500..2^500, on grids touched exactly (a box face in the grid's plane, a corner on a vertex, a
// triangle sharing an edge, a tetrahedron's face on a cell), and on the real meshes with boxes
// and tetrahedra at their vertices.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>
#include <typeinfo>
#include <filesystem>
#include <set>
#include <string>
#include <type_traits>
#include <vector>
import incidence;
#include "testkit/testing.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/point_sets.hpp"
#include "testkit/scene_cases.hpp"

namespace test_scene_solid_scene { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {

struct counts {
    long cases = 0, met = 0, wrong = 0, approximate_other = 0;
};

template <class S>
aabb3 exact_box(const S& s) {
    if constexpr (std::is_same_v<S, aabb3>) return s;
    else if constexpr (std::is_same_v<S, triangle3>) return support::box_of(s);
    else if constexpr (std::is_same_v<S, tetrahedron3>) return support::box_of({s.a, s.b, s.c}); // with d below
    else return {{NAN, NAN, NAN}, {NAN, NAN, NAN}}; // an OBB, a frustum: no lower bound on the approximate set
}
template <class S>
bool boxes_may_meet(const S& s, const triangle3& t) {
    aabb3 a = exact_box(s);
    if constexpr (std::is_same_v<S, tetrahedron3>)
        a = {{std::min(a.min.x, s.d.x), std::min(a.min.y, s.d.y), std::min(a.min.z, s.d.z)},
             {std::max(a.max.x, s.d.x), std::max(a.max.y, s.d.y), std::max(a.max.z, s.d.z)}};
    if constexpr (std::is_same_v<S, ray3> || std::is_same_v<S, segment3> || std::is_same_v<S, line3>)
        return intersects<exact>(s, support::box_of(t));
    else return support::boxes_meet(a, support::box_of(t));
}

// One tier: the set intersecting lists and the yes/no answer, against the brute force's set.
template <class Tier, class S>
void check_tier(const std::vector<triangle3>& ts, const scene3& sc, const S& s, const std::set<std::size_t>& truth, counts& c) {
    std::set<std::size_t> brute, near;
    for (std::size_t i = 0; i < ts.size(); ++i)
        if (intersects<Tier>(s, ts[i])) {
            brute.insert(i);
            if (boxes_may_meet(s, ts[i])) near.insert(i);
        }
    std::vector<std::size_t> out{99};
    const std::size_t n = intersecting<Tier>(s, sc, out);
    const std::set<std::size_t> listed(out.begin() + 1, out.end());
    bool ok = out.front() == 99 && n == out.size() - 1 && listed.size() == n && support::set_contract<Tier>(listed, brute, truth, near);
    if constexpr (std::is_same_v<Tier, approximate>) c.approximate_other += listed != brute;
    if constexpr (!(std::is_same_v<S, ray3> || std::is_same_v<S, segment3> || std::is_same_v<S, line3>)) {
        const bool any = intersects<Tier>(s, sc);
        ok = ok && any == intersects<Tier>(sc, s) && any == !listed.empty();
    }
    if (!ok && ++c.wrong <= 5)
        std::printf("  a %s set unlike the brute force's: %zu listed, %zu by the brute force\n", typeid(Tier).name(), listed.size(),
                    brute.size());
}

template <class S>
void check(const std::vector<triangle3>& ts, const scene3& sc, const S& s, counts& c) {
    ++c.cases;
    std::set<std::size_t> truth;
    for (std::size_t i = 0; i < ts.size(); ++i)
        if (intersects<exact>(s, ts[i])) truth.insert(i);
    c.met += !truth.empty();
    check_tier<exact>(ts, sc, s, truth, c);
    check_tier<conservative>(ts, sc, s, truth, c);
    check_tier<aggressive>(ts, sc, s, truth, c);
    check_tier<approximate>(ts, sc, s, truth, c);
}

point3 random_point(support::rng& r, support::transform& tr, double reach) {
    return {tr.apply(reach * r.uniform(-1, 1), 0), tr.apply(reach * r.uniform(-1, 1), 1), tr.apply(reach * r.uniform(-1, 1), 2)};
}

// One of the shapes, at random in the soup's frame, with its kind picked by k.
template <class F>
void random_shape(support::rng& r, support::transform& tr, int k, F&& f) {
    auto p = [&] { return random_point(r, tr, 1.2); };
    auto q = [&](point3 m) {
        return point3{m.x + tr.scale_only(0.3 * r.uniform(-1, 1)), m.y + tr.scale_only(0.3 * r.uniform(-1, 1)),
                      m.z + tr.scale_only(0.3 * r.uniform(-1, 1))};
    };
    const point3 m = p();
    switch (k % 8) {
    case 0: {
        const point3 a = q(m);
        f(aabb3{{std::min(a.x, m.x), std::min(a.y, m.y), std::min(a.z, m.z)},
                {std::max(a.x, m.x), std::max(a.y, m.y), std::max(a.z, m.z)}});
        break;
    }
    case 1: f(support::random_obb(r, tr)); break;
    case 2: f(triangle3{m, q(m), q(m)}); break;
    case 3: f(tetrahedron3{m, q(m), q(m), q(m)}); break;
    case 4: f(ray3{m, vec3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}}); break;
    case 5: f(segment3{m, q(m)}); break;
    case 6: { // a camera at m looking at a random point
        const point3 at = p();
        const auto fr = frustum3::from_camera(m, at - m, r.coin() ? vec3{0, 0, 1} : vec3{0, 1, 0}, r.uniform(0.2, 2.0), r.uniform(0.5, 2.0),
                                              tr.scale_only(0.01), tr.scale_only(r.uniform(0.5, 3.0)));
        if (fr) f(fr.value());
        break;
    }
    default: f(line3{m, vec3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}}); break;
    }
}

} // namespace

TEST_CASE("scene: boxes, oriented boxes, triangles, tetrahedra, frusta, and every triangle met, against the brute force: random soups",
          "[scene]") {
    support::rng r(support::seed());
    counts c;
    const long sets = support::cases(2000);
    for (long k = 0; k < sets; ++k) {
        support::transform tr = support::random_transform(r, false);
        const std::vector<triangle3> ts = support::random_soup(r, tr, r.integer(1, 120));
        const auto sc = scene3::make(ts);
        REQUIRE(sc.has_value());
        for (int j = 0; j < 8; ++j) random_shape(r, tr, j, [&](const auto& s) { check(ts, sc.value(), s, c); });
    }
    std::printf("[cases] scene solids, soups: %ld shapes (%ld meeting the soup); %ld wrong; approximate sets unlike the brute force %ld\n",
                c.cases, c.met, c.wrong, c.approximate_other);
    CHECK(c.wrong == 0);
    CHECK(c.met * 4 > c.cases);
}

TEST_CASE("scene: boxes, triangles, tetrahedra touching a grid exactly, against the brute force", "[scene]") {
    support::rng r(support::seed());
    counts c;
    const long sets = support::cases(3000);
    for (long k = 0; k < sets; ++k) {
        const support::grid g = support::make_grid(r);
        const auto sc = scene3::make(g.ts);
        REQUIRE(sc.has_value());
        const double x = r.integer(-4, 3), y = r.integer(-4, 3), z = r.integer(0, 1);
        const double below = r.coin() ? -1 : 0; // resting on the plane from below or lying across it
        auto corners = [&](point3 a, point3 b) {
            return aabb3{{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                         {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
        };
        switch (k % 4) {
        case 0:
            check(g.ts, sc.value(), corners(g.at(x + 0.5, y + 0.25, z + below), g.at(x + 1, y + 1, z + below + 0.5)), c);
            break; // a corner on a vertex or a face on the plane
        case 1:
            check(g.ts, sc.value(), triangle3{g.at(x, y, z), g.at(x + 1, y, z), g.at(x + 0.5, y - 0.5, z + below)}, c);
            break; // an edge shared
        case 2:
            check(g.ts, sc.value(), tetrahedron3{g.at(x, y, z), g.at(x + 1, y, z), g.at(x + 1, y + 1, z), g.at(x, y, z - 1)}, c);
            break; // a face on a cell
        default: check(g.ts, sc.value(), ray3{g.at(x + 0.5, y + 0.5, z + 2), vec3{0, 0, -1}}, c); break;
        }
    }
    std::printf("[cases] scene solids, grids: %ld shapes (%ld meeting the grid); %ld wrong; approximate sets unlike the brute force %ld "
                "(near-degenerate: allowed)\n",
                c.cases, c.met, c.wrong, c.approximate_other);
    CHECK(c.wrong == 0);
    CHECK(c.met * 2 > c.cases);
}

TEST_CASE("scene: boxes, tetrahedra and narrow frusta at the real meshes' vertices (libcgal-demo), against the brute force", "[scene]") {
    if (support::real_meshes().empty() && support::meshes_required()) FAIL("the real meshes are missing (run.sh unpacks them)");
    support::rng r(support::seed());
    const std::filesystem::path dir = std::filesystem::path(INCIDENCE_SOURCE_DIR) / "build/data/meshes";
    const auto file = dir / "fandisk.off";
    if (!std::filesystem::exists(file)) return;
    const audit::mesh m = audit::read_mesh(file.string());
    std::vector<triangle3> ts;
    for (const auto& f : m.faces) ts.push_back({m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]});
    const auto sc = scene3::make(ts);
    REQUIRE(sc.has_value());
    counts c;
    const long shapes = support::cases(400) / 4;
    for (long k = 0; k < shapes; ++k) {
        const point3 v = m.vertices[static_cast<std::size_t>(r.integer(0, static_cast<int>(m.vertices.size()) - 1))];
        const double h = 0.01 * r.uniform(0.1, 1);
        if (k % 3 == 0) check(ts, sc.value(), aabb3{v, {v.x + h, v.y + h, v.z + h}}, c); // a corner at a vertex
        else if (k % 3 == 1) check(ts, sc.value(), tetrahedron3{v, {v.x + h, v.y, v.z}, {v.x, v.y + h, v.z}, {v.x, v.y, v.z - h}}, c);
        else if (const auto fr = frustum3::from_camera({v.x + 1, v.y + 0.5, v.z + 2}, {-1, -0.5, -2}, {0, 1, 0}, 0.05, 1.0, 0.1, 10.0))
            check(ts, sc.value(), fr.value(), c); // a narrow view centred on the vertex
    }
    std::printf("[cases] scene solids, fandisk (%zu triangles): %ld shapes (%ld meeting it); %ld wrong\n", ts.size(), c.cases, c.met,
                c.wrong);
    CHECK(c.wrong == 0);
    CHECK(c.met == c.cases); // each touches the mesh at a vertex at least
}

TEST_CASE("scene: solids, bad input", "[scene]") {
    const std::vector<triangle3> one{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    const auto sc = scene3::make(one);
    REQUIRE(sc.has_value());
    const double nan = std::nan("");
    std::vector<std::size_t> out;
    CHECK(!intersects<exact>(aabb3{{nan, 0, 0}, {1, 1, 1}}, sc.value()));
    CHECK(!intersects<conservative>(tetrahedron3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, INFINITY}}, sc.value()));
    CHECK(intersecting<exact>(triangle3{{nan, 0, 0}, {1, 0, 0}, {0, 1, 0}}, sc.value(), out) == 0);
    CHECK(!intersects<exact>(aabb3{{0, 0, 1}, {1, 1, 0}}, sc.value())); // inverted: empty
    CHECK(intersects<exact>(aabb3{{0, 0, 0}, {0, 0, 0}}, sc.value()));  // the corner point
    CHECK(out.empty());
}

} // namespace test_scene_solid_scene
