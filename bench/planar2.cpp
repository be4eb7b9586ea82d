// Benchmarks: the 2D pairs: points, lines, rays, segments (CGAL Epeck as truth, Epick beside) and
// polygons; the disk (circle2) against each of them, containment in the disk and of the disk in a
// polygon; and the planar polygon in space against every shape.
#include "bench.hpp"
#include <optional>
#include <tuple>
#include <utility>
#include <vector>
#include "testkit/circle2_cases.hpp"

namespace bench {
namespace {

// A disk pair on the tests' generators (testkit/circle2_cases.hpp, at every scale the tests use),
// their oracle as truth; a polygon partner is a view of its case's store. Contains: the disk around
// B (the holding generator's cases for the near-degenerate set).
template <class B, bool Contains = false>
void disk_tiers(const std::string& pair, bool near) {
    struct disk_case {
        circle2 c{};
        B b{};
        support::polygon_store g; // a polygon partner's vertices
        B partner() const {
            if constexpr (std::is_same_v<B, polygon2>) return g.view();
            else return b;
        }
    };
    support::rng r = set_rng(near);
    std::vector<disk_case> cs;
    while (cs.size() < set_size) {
        disk_case d;
        if constexpr (Contains) {
            std::tie(d.c, d.b) = near ? support::disk_holding<B>(r, d.g) : support::disk_random_around<B>(r, d.g);
        } else {
            const auto c = near ? support::disk_near<B>(r, d.g) : support::disk_random<B>(r, d.g);
            if (!c) continue;
            std::tie(d.c, d.b) = *c;
        }
        cs.push_back(std::move(d));
    }
    tiers(
        pair, near ? "near_degenerate" : "random", cs,
        [](const disk_case& d) { return Contains ? support::disk_holds_truth(d.c, d.partner()) : support::disk_truth(d.c, d.partner()); },
        [](auto tier, const disk_case& d) {
            if constexpr (Contains) return contains<decltype(tier)>(d.c, d.partner());
            else return intersects<decltype(tier)>(d.c, d.partner());
        },
        Contains ? "contains" : "intersects");
}

// contains(polygon2, circle2): random disks, or a disk in a star polygon of radius its distance to
// the nearest edge (testkit/circle2_cases.hpp's disk_in_star) for the near-degenerate set.
void polygon_holds_disk_tiers(bool near) {
    struct held_case {
        circle2 c{};
        support::polygon_store g;
    };
    support::rng r = set_rng(near);
    std::vector<held_case> cs;
    while (cs.size() < set_size) {
        held_case d;
        d.c = near ? support::disk_in_star(r, d.g) : support::disk_random_around<polygon2>(r, d.g).first;
        cs.push_back(std::move(d));
    }
    tiers(
        "polygon2_circle2", near ? "near_degenerate" : "random", cs,
        [](const held_case& d) { return support::polygon_holds_disk_truth(d.g.view(), d.c); },
        [](auto tier, const held_case& d) { return contains<decltype(tier)>(d.g.view(), d.c); }, "contains");
}

} // namespace

void register_planar2(bool near) {
    flat_tiers<segment2, segment2>("segment2_segment2", near);
    flat_tiers<line2, line2>("line2_line2", near);
    flat_tiers<line2, point2>("line2_point2", near);
    flat_tiers<line2, ray2>("line2_ray2", near);
    flat_tiers<line2, segment2>("line2_segment2", near);
    flat_tiers<point2, point2>("point2_point2", near);
    flat_tiers<point2, ray2>("point2_ray2", near);
    flat_tiers<point2, segment2>("point2_segment2", near);
    flat_tiers<ray2, ray2>("ray2_ray2", near);
    flat_tiers<ray2, segment2>("ray2_segment2", near);
    polygon_tiers<point2>("point2_polygon2", near);
    polygon_tiers<segment2>("polygon2_segment2", near);
    polygon_tiers<ray2>("polygon2_ray2", near);
    polygon_tiers<line2>("line2_polygon2", near);
    polygon_tiers<polygon2>("polygon2_polygon2", near);
    disk_tiers<point2>("circle2_point2", near);
    disk_tiers<circle2>("circle2_circle2", near);
    disk_tiers<segment2>("circle2_segment2", near);
    disk_tiers<ray2>("circle2_ray2", near);
    disk_tiers<line2>("circle2_line2", near);
    disk_tiers<polygon2>("circle2_polygon2", near);
    disk_tiers<point2, true>("circle2_point2", near);
    disk_tiers<segment2, true>("circle2_segment2", near);
    disk_tiers<circle2, true>("circle2_circle2", near);
    disk_tiers<polygon2, true>("circle2_polygon2", near);
    polygon_holds_disk_tiers(near);
    polygon3_tiers<point3>("point_polygon", near);
    polygon3_tiers<segment3>("polygon_segment", near);
    polygon3_tiers<ray3>("polygon_ray", near);
    polygon3_tiers<line3>("line_polygon", near);
    polygon3_tiers<plane3>("plane_polygon", near);
    polygon3_tiers<triangle3>("polygon_triangle", near);
    polygon3_tiers<polygon3>("polygon_polygon", near);
    polygon3_tiers<aabb3>("aabb_polygon", near);
    polygon3_tiers<obb3>("obb_polygon", near);
    polygon3_tiers<tetrahedron3>("polygon_tetrahedron", near);
    polygon3_tiers<convex_polyhedron3>("convex_polyhedron_polygon", near);
    polygon3_tiers<frustum3>("frustum_polygon", near);
    polygon3_tiers<kdop<14>>("kdop_polygon_14", near);
    mesh_polygon3_tiers("mesh_polygon", near);
}
} // namespace bench
