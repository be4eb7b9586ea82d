// Each shape as the LP oracle's convex set (tests/oracle/cgal_lp.cpp), every coefficient one of
// the shape's own doubles. Include after `import incidence;`.
#pragma once
#include <array>
#include "../oracle/cgal_oracle.hpp"

namespace support {

inline std::array<double, 3> a3(incidence::point3 p) { return {p.x, p.y, p.z}; }
inline std::array<double, 3> a3(incidence::vec3 p) { return {p.x, p.y, p.z}; }
inline oracle::convex_set lp(const incidence::obb3& b) {
    oracle::convex_set s;
    s.points = {a3(b.center)};
    for (unsigned i = 0; i < 3; ++i) s.generators.push_back({a3(b.axes[i]), true, true, -b.half_extents[i], b.half_extents[i]});
    return s;
}
inline oracle::convex_set lp(const incidence::aabb3& b) {
    oracle::convex_set s;
    s.points = {{0, 0, 0}};
    s.generators = {{{1, 0, 0}, true, true, b.min.x, b.max.x}, {{0, 1, 0}, true, true, b.min.y, b.max.y}, {{0, 0, 1}, true, true, b.min.z, b.max.z}};
    return s;
}
inline oracle::convex_set lp(const incidence::point3& p) { return {{a3(p)}, {}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::segment3& g) { return {{a3(g.a), a3(g.b)}, {}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::triangle3& t) { return {{a3(t.a), a3(t.b), a3(t.c)}, {}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::ray3& g) { return {{a3(g.origin)}, {{a3(g.direction), true, false, 0, 0}}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::line3& g) { return {{a3(g.origin)}, {{a3(g.direction), false, false, 0, 0}}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::tetrahedron3& t) { return {{a3(t.a), a3(t.b), a3(t.c), a3(t.d)}, {}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::plane3& p) { return {{}, {}, true, a3(p.normal), p.offset, {}, {}}; }
template <int N>
oracle::convex_set lp(const incidence::kdop<N>& b) {
    oracle::convex_set s;
    const auto dirs = incidence::kdop<N>::directions();
    for (unsigned i = 0; i < dirs.size(); ++i)
        s.slabs.push_back({{double(dirs[i].x), double(dirs[i].y), double(dirs[i].z)}, b.min[i], b.max[i]});
    return s;
}


// A convex polyhedron or a frustum: its half-spaces n . x <= offset.
inline oracle::convex_set lp(const incidence::convex_polyhedron3& c) {
    oracle::convex_set s;
    for (int i = 0; i < c.count; ++i) s.halfspaces.push_back({a3(c.planes[static_cast<unsigned>(i)].normal), c.planes[static_cast<unsigned>(i)].offset});
    return s;
}
inline oracle::convex_set lp(const incidence::frustum3& f) {
    oracle::convex_set s;
    for (const auto& p : f.planes) s.halfspaces.push_back({a3(p.normal), p.offset});
    return s;
}

} // namespace support
