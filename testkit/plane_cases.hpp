// Cases for a plane against a box, a segment or a triangle. Near-degenerate: small dyadic
// vertices, a small integer normal, and the plane through the vertex extreme along -n (touching
// at a vertex, an edge or a face), or through another vertex (crossing); then a random exact-or-
// nudged scale and translation of the vertices, the offset recomputed through the moved vertex
// (exact when the transform only scales). Random: random vertices, normal and offset. Include
// after testing.hpp.
#pragma once
#include <array>
#include <vector>

namespace support {
// The plane n . p = n . q through q (rounded when not exact).
inline incidence::plane3 plane_through(incidence::vec3 n, incidence::point3 q) { return {n, n.x * q.x + n.y * q.y + n.z * q.z}; }
inline incidence::vec3 small_normal(rng& r) {
    for (;;) {
        const incidence::vec3 n{double(r.integer(-4, 4)), double(r.integer(-4, 4)), double(r.integer(-4, 4))};
        if (!(n.x == 0 && n.y == 0 && n.z == 0)) return n;
    }
}
// The index of the vertex with the least n . v, or a random one (1 in 4).
inline std::size_t plane_vertex(rng& r, incidence::vec3 n, const std::vector<incidence::point3>& v) {
    if (r.integer(0, 3) == 0) return std::size_t(r.integer(0, int(v.size()) - 1));
    std::size_t best = 0;
    for (std::size_t i = 1; i < v.size(); ++i)
        if (n.x * v[i].x + n.y * v[i].y + n.z * v[i].z < n.x * v[best].x + n.y * v[best].y + n.z * v[best].z) best = i;
    return best;
}
// Transformed vertices of a near case, and the plane through the chosen one.
struct plane_case {
    std::vector<incidence::point3> v;
    incidence::plane3 plane;
};
inline plane_case plane_near(rng& r, std::vector<incidence::point3> v) {
    const incidence::vec3 n = small_normal(r);
    const std::size_t k = plane_vertex(r, n, v);
    transform tr = random_transform(r, true);
    for (auto& p : v) p = {tr.apply(p.x, 0), tr.apply(p.y, 1), tr.apply(p.z, 2)};
    return {v, plane_through(n, v[k])};
}
inline plane_case plane_random(rng& r, std::size_t count) {
    const transform tr = random_transform(r, false);
    auto q = [&] { return incidence::point3{random_coord(r, tr, 0), random_coord(r, tr, 1), random_coord(r, tr, 2)}; };
    plane_case c;
    for (std::size_t i = 0; i < count; ++i) c.v.push_back(q());
    const incidence::vec3 n{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
    c.plane = plane_through(n, q());
    return c;
}
} // namespace support
