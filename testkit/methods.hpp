// The methods the audit compares for a family of incidence::catalog: the four tiers, the exact
// tier's sign algorithm in plain double, the family's textbook alternatives, and CGAL Epick where
// CGAL has the pair. Include after `import incidence;` and the CGAL oracle header.
#pragma once
#include <string>
#include <vector>
#include "flat_shapes.hpp"

namespace audit {

using namespace incidence;

template <class A, class B>
struct method {
    std::string name;
    std::string kind; // tier | sign algorithm | alternative | peer
    std::string source;
    bool (*test)(const A&, const B&);
};

namespace peer {
inline void arr(point3 p, double* o) { o[0] = p.x, o[1] = p.y, o[2] = p.z; }
inline void arr(vec3 p, double* o) { o[0] = p.x, o[1] = p.y, o[2] = p.z; }
inline bool epick(const ray3& r, const triangle3& t) {
    double o[3], d[3], a[3], b[3], c[3];
    arr(r.origin, o), arr(r.direction, d), arr(t.a, a), arr(t.b, b), arr(t.c, c);
    return oracle::ray_triangle_epick(o, d, a, b, c);
}
inline bool epick(const segment3& s, const triangle3& t) {
    double p[3], q[3], a[3], b[3], c[3];
    arr(s.a, p), arr(s.b, q), arr(t.a, a), arr(t.b, b), arr(t.c, c);
    return oracle::segment_triangle_epick(p, q, a, b, c);
}
inline bool epick(const triangle3& t, const triangle3& u) {
    double a[3], b[3], c[3], d[3], e[3], f[3];
    arr(t.a, a), arr(t.b, b), arr(t.c, c), arr(u.a, d), arr(u.b, e), arr(u.c, f);
    return oracle::triangle_triangle_epick(a, b, c, d, e, f);
}
inline bool epick(const aabb3& b, const plane3& p) {
    double mn[3], mx[3], n[3];
    arr(b.min, mn), arr(b.max, mx), arr(p.normal, n);
    return oracle::box_plane_epick(mn, mx, n, p.offset);
}
inline bool epick(const plane3& p, const segment3& s) {
    double n[3], a[3], b[3];
    arr(p.normal, n), arr(s.a, a), arr(s.b, b);
    return oracle::plane_segment_epick(n, p.offset, a, b);
}
inline bool epick(const plane3& p, const triangle3& t) {
    double n[3], a[3], b[3], c[3];
    arr(p.normal, n), arr(t.a, a), arr(t.b, b), arr(t.c, c);
    return oracle::plane_triangle_epick(n, p.offset, a, b, c);
}
inline bool epick(const aabb3& b, const segment3& s) {
    double mn[3], mx[3], p[3], q[3];
    arr(b.min, mn), arr(b.max, mx), arr(s.a, p), arr(s.b, q);
    return oracle::box_segment_epick(mn, mx, p, q);
}
inline bool epick(const aabb3& b, const line3& l) {
    double mn[3], mx[3], p[3], d[3];
    arr(b.min, mn), arr(b.max, mx), arr(l.origin, p), arr(l.direction, d);
    return oracle::box_line_epick(mn, mx, p, d);
}
inline bool epick(const aabb3& b, const triangle3& t) {
    double mn[3], mx[3], a[3], c[3], d[3];
    arr(b.min, mn), arr(b.max, mx), arr(t.a, a), arr(t.b, c), arr(t.c, d);
    return oracle::box_triangle_epick(mn, mx, a, c, d);
}
inline bool epick(const aabb3& b, const ray3& r) {
    double o[3], d[3], mn[3], mx[3];
    arr(r.origin, o), arr(r.direction, d), arr(b.min, mn), arr(b.max, mx);
    return oracle::ray_box_epick(o, d, mn, mx);
}
inline bool epick(const aabb3& a, const aabb3& b) {
    double amn[3], amx[3], bmn[3], bmx[3];
    arr(a.min, amn), arr(a.max, amx), arr(b.min, bmn), arr(b.max, bmx);
    return oracle::box_box_epick(amn, amx, bmn, bmx);
}
inline bool epick(const aabb3& b, const point3& p) {
    double q[3], mn[3], mx[3];
    arr(p, q), arr(b.min, mn), arr(b.max, mx);
    return oracle::point_in_box_epick(q, mn, mx);
}
// The other flat pairs (points, lines, rays, segments, planes, triangles): CGAL's do_intersect
// over Epick, as a user would call it (tests/oracle/cgal_flat.cpp).
template <class A, class B>
requires(support::flat_shape<A> && support::flat_shape<B>)
bool epick(const A& a, const B& b) {
    return oracle::flat_intersect_epick(support::to_flat(a), support::to_flat(b));
}
template <class A, class B>
requires(support::flat2_shape<A> && support::flat2_shape<B>)
bool epick(const A& a, const B& b) {
    return oracle::flat_intersect_epick(support::to_flat(a), support::to_flat(b));
}
template <class A, class B>
concept has_epick = requires(const A& a, const B& b) { epick(a, b); };
// CGAL's triangle predicates require non-degenerate triangles.
inline bool epick_accepts(const triangle3& t) {
    double a[3], b[3], c[3];
    arr(t.a, a), arr(t.b, b), arr(t.c, c);
    return !oracle::triangle_is_degenerate(a, b, c);
}
inline bool epick_accepts(const plane3& p) { return !(p.normal.x == 0 && p.normal.y == 0 && p.normal.z == 0); }
inline bool epick_accepts(const line3& l) { return !(l.direction.x == 0 && l.direction.y == 0 && l.direction.z == 0); }
template <class S>
bool epick_accepts(const S&) {
    return true;
}
} // namespace peer

template <class A, class B>
[[nodiscard]] bool peer_accepts(const A& a, const B& b) {
    return peer::epick_accepts(a) && peer::epick_accepts(b);
}

// A method's test, or none when only the names are wanted (the generic lambda is then never
// instantiated).
template <bool WithTests, class A, class B>
[[nodiscard]] auto test_of(auto f) -> bool (*)(const A&, const B&) {
    if constexpr (WithTests) return f;
    else return nullptr;
}
// The methods of one family; the exact tier comes first (it is the reference). With WithTests
// false they carry names only, for a file that lists the methods without running them.
template <bool WithTests = true, class Family>
[[nodiscard]] auto methods_of(const Family& f) {
    using A = typename Family::first_type;
    using B = typename Family::second_type;
    const auto test = [](auto l) { return test_of<WithTests, A, B>(l); };
    std::vector<method<A, B>> m;
    m.push_back({"exact", "tier", "filter, then expansions, then exact dyadic integers",
                 test([](const auto& a, const auto& b) { return intersects<exact>(a, b); })});
    m.push_back({"conservative", "tier", "filter; uncertain answers yes",
                 test([](const auto& a, const auto& b) { return intersects<conservative>(a, b); })});
    m.push_back({"aggressive", "tier", "filter; uncertain answers no",
                 test([](const auto& a, const auto& b) { return intersects<aggressive>(a, b); })});
    m.push_back(
        {"approximate", "tier", f.approximate_method, test([](const auto& a, const auto& b) { return intersects<approximate>(a, b); })});
    m.push_back({"signs_in_double", "sign algorithm", "the exact tier's sign algorithm evaluated in plain double",
                 test([](const auto& a, const auto& b) { return catalog::signs_in_double(a, b); })});
    for (const auto& alt : f.alternatives) m.push_back({alt.name, "alternative", alt.source, alt.test});
    if constexpr (peer::has_epick<A, B>)
        m.push_back({"cgal_epick", "peer", "CGAL 5.5 do_intersect, Exact_predicates_inexact_constructions_kernel",
                     test([](const auto& a, const auto& b) { return peer::epick(a, b); })});
    return m;
}

} // namespace audit
