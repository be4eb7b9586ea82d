// Benchmarks: the 2D pairs: points, lines, rays, segments (CGAL Epeck as truth, Epick beside) and polygons.
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
}
} // namespace bench
