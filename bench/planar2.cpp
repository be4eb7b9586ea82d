// Benchmarks: the 2D pairs: points, lines, rays, segments (CGAL Epeck as truth, Epick beside) and
// polygons; and the planar polygon in space against every shape.
#include "bench.hpp"

namespace bench {
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
