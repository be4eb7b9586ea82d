// Each shape as the LP oracle's convex set (tests/oracle/cgal_lp.cpp), every coefficient one of
// the shape's own doubles. Include after `import incidence;`.
#pragma once
#include <array>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>
#include "testkit/oracle/cgal_oracle.hpp"

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
    s.generators = {
        {{1, 0, 0}, true, true, b.min.x, b.max.x}, {{0, 1, 0}, true, true, b.min.y, b.max.y}, {{0, 0, 1}, true, true, b.min.z, b.max.z}};
    return s;
}
inline oracle::convex_set lp(const incidence::point3& p) { return {{a3(p)}, {}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::segment3& g) { return {{a3(g.a), a3(g.b)}, {}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::triangle3& t) { return {{a3(t.a), a3(t.b), a3(t.c)}, {}, false, {}, 0, {}, {}}; }
inline oracle::convex_set lp(const incidence::ray3& g) {
    return {{a3(g.origin)}, {{a3(g.direction), true, false, 0, 0}}, false, {}, 0, {}, {}};
}
inline oracle::convex_set lp(const incidence::line3& g) {
    return {{a3(g.origin)}, {{a3(g.direction), false, false, 0, 0}}, false, {}, 0, {}, {}};
}
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
    for (int i = 0; i < c.count; ++i)
        s.halfspaces.push_back({a3(c.planes[static_cast<unsigned>(i)].normal), c.planes[static_cast<unsigned>(i)].offset});
    return s;
}
inline oracle::convex_set lp(const incidence::frustum3& f) {
    oracle::convex_set s;
    for (const auto& p : f.planes) s.halfspaces.push_back({a3(p.normal), p.offset});
    return s;
}

// The points whose hull is the shape: contains(P, shape) holds iff each is in the convex set P.
inline std::vector<incidence::point3> hull_points(const incidence::point3& p) { return {p}; }
inline std::vector<incidence::point3> hull_points(const incidence::segment3& g) { return {g.a, g.b}; }
inline std::vector<incidence::point3> hull_points(const incidence::triangle3& t) { return {t.a, t.b, t.c}; }
inline std::vector<incidence::point3> hull_points(const incidence::tetrahedron3& t) { return {t.a, t.b, t.c, t.d}; }
inline std::vector<incidence::point3> hull_points(const incidence::aabb3& b) {
    std::vector<incidence::point3> v;
    for (int j = 0; j < 8; ++j) v.push_back({(j & 1) ? b.max.x : b.min.x, (j & 2) ? b.max.y : b.min.y, (j & 4) ? b.max.z : b.min.z});
    return v;
}

// contains(a, b) by the oracle: each of b's hull points in the convex set a (the LP), or for an
// oriented box, whose corners are not doubles, its eight corners in exact rationals.
template <class A, class B>
bool contained_truth(const A& a, const B& b) {
    if constexpr (std::is_same_v<B, incidence::obb3>) {
        const double c[3] = {b.center.x, b.center.y, b.center.z};
        const double axes[9] = {b.axes[0].x, b.axes[0].y, b.axes[0].z, b.axes[1].x, b.axes[1].y,
                                b.axes[1].z, b.axes[2].x, b.axes[2].y, b.axes[2].z};
        return oracle::box_in_constraints(c, axes, b.half_extents.data(), lp(a));
    } else {
        bool truth = true;
        for (const auto& p : hull_points(b)) truth = truth && oracle::lp_intersect(lp(a), lp(p));
        return truth;
    }
}

// A tetrahedron holding the convex set a whole: they meet (truth), yet no face of the tetrahedron
// meets a, so the test's last step (a vertex of a inside the tetrahedron) decides. The oracle tests
// count these cases, to show that step runs; for an oriented box, the cases its vertex search decides.
template <class A, class B>
bool held_whole(const A& a, const B& b, bool truth) {
    if constexpr (std::is_same_v<B, incidence::tetrahedron3>) {
        if (!truth) return false;
        for (int f = 0; f < 4; ++f)
            if (intersects(a, b.face(f))) return false;
        return true;
    } else if constexpr (std::is_same_v<B, incidence::obb3>) {
        // a box meeting the set with its centre outside it: neither early answer (a plane with the
        // whole box beyond it, the centre inside every plane) decides, the vertex search does
        return truth && !intersects(a, b.center);
    } else return false;
}
inline void print_held_whole(const std::string& name, long held) {
    std::printf(
        "[cases] %s: decided by the last step (a tetrahedron holding the set whole, a box meeting the set with its centre outside it) in "
        "%ld cases\n",
        name.c_str(), held);
}

} // namespace support
