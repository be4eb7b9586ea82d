// Benchmarks: the triangle, plane and tetrahedron pairs of the flat generators, CGAL Epeck as truth and Epick beside.
#include "bench.hpp"

namespace bench {
void register_flat_solids(bool near) {
    flat_tiers<line3, triangle3>("line_triangle", near);
    flat_tiers<point3, triangle3>("point_triangle", near);
    flat_tiers<plane3, point3>("plane_point", near);
    flat_tiers<line3, plane3>("line_plane", near);
    flat_tiers<plane3, ray3>("plane_ray", near);
    flat_tiers<plane3, plane3>("plane_plane", near);
    flat_tiers<point3, tetrahedron3>("point_tetrahedron", near);
    flat_tiers<segment3, tetrahedron3>("segment_tetrahedron", near);
    flat_tiers<ray3, tetrahedron3>("ray_tetrahedron", near);
    flat_tiers<line3, tetrahedron3>("line_tetrahedron", near);
    flat_tiers<plane3, tetrahedron3>("plane_tetrahedron", near);
    flat_tiers<tetrahedron3, triangle3>("tetrahedron_triangle", near);
    flat_tiers<tetrahedron3, tetrahedron3>("tetrahedron_tetrahedron", near);
    flat_tiers<aabb3, tetrahedron3>("aabb_tetrahedron", near);
}
} // namespace bench
