// Containment of a point set in an obb3, checked with CGAL's exact rationals (independent of the
// library's predicates). Include after the oracle header, `import incidence;` and testing.hpp.
#pragma once
#include <span>
#include <vector>

namespace support {
inline bool all_inside(std::span<const incidence::point3> pts, const incidence::obb3& b) {
    std::vector<double> v;
    for (const auto& p : pts) v.insert(v.end(), {p.x, p.y, p.z});
    const double c[3] = {b.center.x, b.center.y, b.center.z};
    const double a[9] = {b.axes[0].x, b.axes[0].y, b.axes[0].z, b.axes[1].x, b.axes[1].y, b.axes[1].z, b.axes[2].x, b.axes[2].y, b.axes[2].z};
    return oracle::all_in_box(v.data(), pts.size(), c, a, b.half_extents.data());
}
} // namespace support
