// Benchmarks: the point, line, ray and segment pairs in 3D (tests/support/flat_cases.hpp), CGAL Epeck as truth and Epick beside.
#include "bench.hpp"

namespace bench {
void register_flat_lines(bool near) {
    flat_tiers<segment3, segment3>("segment_segment", near);
    flat_tiers<line3, line3>("line_line", near);
    flat_tiers<line3, point3>("line_point", near);
    flat_tiers<line3, ray3>("line_ray", near);
    flat_tiers<line3, segment3>("line_segment", near);
    flat_tiers<point3, point3>("point_point", near);
    flat_tiers<point3, ray3>("point_ray", near);
    flat_tiers<point3, segment3>("point_segment", near);
    flat_tiers<ray3, ray3>("ray_ray", near);
    flat_tiers<ray3, segment3>("ray_segment", near);
}
} // namespace bench
