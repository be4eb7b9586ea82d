// Containment of a point set in a sphere, checked with CGAL's exact rationals (independent of
// the library's predicates). Include after the oracle header, `import incidence;` and testing.hpp.
#pragma once
#include <span>
#include <vector>

namespace support {
inline std::vector<double> flat(std::span<const incidence::point3> pts) {
    std::vector<double> v;
    v.reserve(pts.size() * 3);
    for (const auto& p : pts) v.insert(v.end(), {p.x, p.y, p.z});
    return v;
}
inline bool all_inside(std::span<const incidence::point3> pts, const incidence::sphere3& s) {
    const auto v = flat(pts);
    const double c[3] = {s.center.x, s.center.y, s.center.z};
    return incidence::is_finite(s.center) && incidence::is_finite(s.radius) && oracle::all_in_ball(v.data(), pts.size(), c, s.radius);
}
} // namespace support
