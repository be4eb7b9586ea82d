// Benchmarks: the k-DOP pairs and the half-space pairs (convex_polyhedron3, frustum3), the LP as truth.
#include "bench.hpp"

namespace bench {
void register_halfspace(bool near) {
    kdop_tiers<14, point3>("kdop_point", near);
    kdop_tiers<14, segment3>("kdop_segment", near);
    kdop_tiers<14, ray3>("kdop_ray", near);
    kdop_tiers<14, line3>("kdop_line", near);
    kdop_tiers<26, ray3>("kdop_ray", near);
    kdop_tiers<14, kdop<14>>("kdop_kdop", near);
    kdop_tiers<26, kdop<26>>("kdop_kdop", near);
    kdop_tiers<14, aabb3>("aabb_kdop", near);
    halfspace_tiers<convex_polyhedron3, point3>("convex_polyhedron_point", near);
    halfspace_tiers<convex_polyhedron3, segment3>("convex_polyhedron_segment", near);
    halfspace_tiers<convex_polyhedron3, ray3>("convex_polyhedron_ray", near);
    halfspace_tiers<convex_polyhedron3, line3>("convex_polyhedron_line", near);
    halfspace_tiers<frustum3, point3>("frustum_point", near);
    halfspace_tiers<frustum3, segment3>("frustum_segment", near);
    halfspace_tiers<frustum3, ray3>("frustum_ray", near);
    halfspace_tiers<frustum3, line3>("frustum_line", near);
}
} // namespace bench
