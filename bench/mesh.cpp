// Benchmarks: the mesh pairs (tests/support/mesh_cases.hpp), the mesh oracle as truth; a ball and
// a capsule against a mesh or a polygon (testkit/ball_view_cases.hpp).
#include "bench.hpp"

namespace bench {
void register_mesh(bool near) {
    mesh_tiers<point3>("mesh_point", near);
    mesh_tiers<segment3>("mesh_segment", near);
    mesh_tiers<ray3>("mesh_ray", near);
    mesh_tiers<line3>("line_mesh", near);
    mesh_tiers<plane3>("mesh_plane", near);
    mesh_tiers<triangle3>("mesh_triangle", near);
    mesh_tiers<tetrahedron3>("mesh_tetrahedron", near);
    mesh_tiers<aabb3>("aabb_mesh", near);
    mesh_tiers<mesh3>("mesh_mesh", near);
    mesh_tiers<convex_polyhedron3>("convex_polyhedron_mesh", near);
    mesh_tiers<frustum3>("frustum_mesh", near);
    mesh_tiers<kdop<14>>("kdop_mesh", near);
    round_view_tiers<mesh3, sphere3>("mesh_sphere", near);
    round_view_tiers<mesh3, capsule3>("capsule_mesh", near);
    round_view_tiers<polygon3, sphere3>("polygon_sphere", near);
    round_view_tiers<polygon3, capsule3>("capsule_polygon", near);
}
} // namespace bench
