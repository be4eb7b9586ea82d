// Each flat shape (point, segment, ray, line, plane, triangle, and the solids tetrahedron and box;
// and point2, segment2, ray2, line2 in
// the plane) as the oracle's oracle::flat (flat2), and
// the CGAL Epeck answer for a pair of them (tests/oracle/cgal_flat.cpp). Include after
// `import incidence;` and the CGAL oracle header.
#pragma once
#include <cmath>
#include <type_traits>

namespace support {

template <class S>
concept flat_shape =
    std::is_same_v<S, incidence::point3> || std::is_same_v<S, incidence::segment3> || std::is_same_v<S, incidence::ray3> ||
    std::is_same_v<S, incidence::line3> || std::is_same_v<S, incidence::plane3> || std::is_same_v<S, incidence::triangle3> ||
    std::is_same_v<S, incidence::tetrahedron3> || std::is_same_v<S, incidence::aabb3>;

inline oracle::flat to_flat(const incidence::point3& p) { return {oracle::flat::point, {p.x, p.y, p.z}}; }
inline oracle::flat to_flat(const incidence::segment3& s) { return {oracle::flat::segment, {s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z}}; }
inline oracle::flat to_flat(const incidence::ray3& r) {
    return {oracle::flat::ray, {r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z}};
}
inline oracle::flat to_flat(const incidence::line3& l) {
    return {oracle::flat::line, {l.origin.x, l.origin.y, l.origin.z, l.direction.x, l.direction.y, l.direction.z}};
}
inline oracle::flat to_flat(const incidence::plane3& p) { return {oracle::flat::plane, {p.normal.x, p.normal.y, p.normal.z, p.offset}}; }
inline oracle::flat to_flat(const incidence::triangle3& t) {
    return {oracle::flat::triangle, {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z}};
}
inline oracle::flat to_flat(const incidence::tetrahedron3& t) {
    return {oracle::flat::tetrahedron, {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z, t.d.x, t.d.y, t.d.z}};
}
inline oracle::flat to_flat(const incidence::aabb3& b) {
    return {oracle::flat::box, {b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z}};
}
template <class S>
concept flat2_shape = std::is_same_v<S, incidence::point2> || std::is_same_v<S, incidence::segment2> ||
                      std::is_same_v<S, incidence::ray2> || std::is_same_v<S, incidence::line2>;

inline oracle::flat2 to_flat(const incidence::point2& p) { return {oracle::flat2::point, {p.x, p.y}}; }
inline oracle::flat2 to_flat(const incidence::segment2& s) { return {oracle::flat2::segment, {s.a.x, s.a.y, s.b.x, s.b.y}}; }
inline oracle::flat2 to_flat(const incidence::ray2& r) {
    return {oracle::flat2::ray, {r.origin.x, r.origin.y, r.direction.x, r.direction.y}};
}
inline oracle::flat2 to_flat(const incidence::line2& l) {
    return {oracle::flat2::line, {l.origin.x, l.origin.y, l.direction.x, l.direction.y}};
}

template <class A, class B>
bool flat_truth(const A& a, const B& b) {
    return oracle::flat_intersect(to_flat(a), to_flat(b));
}
template <class A, class B>
bool flat_contains_truth(const A& a, const B& b) {
    return oracle::flat_contains(to_flat(a), to_flat(b));
}

// Every number of a point, segment, ray, line, plane, triangle, tetrahedron or box finite.
template <class S>
bool finite_shape(const S& s) {
    for (double x : to_flat(s).v)
        if (!std::isfinite(x)) return false;
    return true;
}

} // namespace support
