// convex_hull: the convex hull of a point set by Quickhull with exact predicates. Every
// visibility decision is an exact orient3d sign (a point is outside a face only when strictly
// above its plane), so duplicates, collinear and coplanar sets, cospherical points and points
// one ulp apart need no tolerance. A 3D hull is a closed triangle mesh whose faces are
// counterclockwise seen from outside; coplanar faces are kept as triangles. Its vertex set is
// exactly the set of extreme points (a vertex lying inside a flat region or on a straight edge is
// removed by a second pass over the extreme points). Flat input gives the 2D hull polygon (a
// triangle fan), collinear input the segment, a single point the point.
// Source: Barber, Dobkin and Huhdanpaa, "The Quickhull algorithm for convex hulls", ACM TOMS
// 22(4), 1996, sections 3-4 (without its merging of nearly coplanar facets: exact signs make it
// unnecessary); 2D case: Andrew's monotone chain (IPL 9(5), 1979).
module;
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>
export module incidence.bound:convex_hull;
import incidence.core;
import incidence.arith;
import incidence.predicates;

export namespace incidence::bound {

struct hull {
    int dimension = 0;                                   // 0 point, 1 segment, 2 polygon, 3 polytope
    std::vector<point3> vertices;                        // the extreme points
    std::vector<std::array<std::uint32_t, 3>> triangles; // 3: closed, outward; 2: a fan of the polygon
};

namespace hull_detail {
inline bool lex_less(point3 a, point3 b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}
inline double approx_orient(point3 a, point3 b, point3 c, point3 d) {
    const vec3 u = a - d, v = b - d, w = c - d;
    return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
}
inline bool collinear(point3 a, point3 b, point3 c) {
    return orient2d(point2{a.x, a.y}, point2{b.x, b.y}, point2{c.x, c.y}) == sign::zero &&
           orient2d(point2{a.y, a.z}, point2{b.y, b.z}, point2{c.y, c.z}) == sign::zero &&
           orient2d(point2{a.z, a.x}, point2{b.z, b.x}, point2{c.z, c.x}) == sign::zero;
}

struct face {
    std::array<std::uint32_t, 3> v;
    std::array<std::uint32_t, 3> nb; // neighbour across edge v[e] -> v[e + 1]
    std::vector<std::uint32_t> outside;
    bool alive = true;
};

// 2D hull of coplanar points (not all collinear), projected along an axis where the plane's
// normal is nonzero: Andrew's monotone chain with exact orient2d. Returns indices, in order.
inline std::vector<std::uint32_t> polygon(const std::vector<point3>& p, int drop) {
    auto proj = [&](std::uint32_t i) {
        return drop == 0 ? point2{p[i].y, p[i].z} : (drop == 1 ? point2{p[i].z, p[i].x} : point2{p[i].x, p[i].y});
    };
    std::vector<std::uint32_t> idx(p.size());
    for (std::uint32_t i = 0; i < idx.size(); ++i) idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](std::uint32_t a, std::uint32_t b) {
        const point2 x = proj(a), y = proj(b);
        return x.x != y.x ? x.x < y.x : x.y < y.y;
    });
    std::vector<std::uint32_t> h(2 * idx.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < idx.size(); ++i) { // lower chain
        while (k >= 2 && orient2d(proj(h[k - 2]), proj(h[k - 1]), proj(idx[i])) != sign::positive) --k;
        h[k++] = idx[i];
    }
    for (std::size_t i = idx.size() - 1, t = k + 1; i-- > 0;) { // upper chain
        while (k >= t && orient2d(proj(h[k - 2]), proj(h[k - 1]), proj(idx[i])) != sign::positive) --k;
        h[k++] = idx[i];
    }
    h.resize(k - 1);
    return h;
}

// Quickhull on distinct points not all coplanar. Returns the alive faces.
inline std::vector<face> quickhull(const std::vector<point3>& p, std::array<std::uint32_t, 4> tet) {
    std::vector<face> f;
    const auto [a, b, c, d] = tet;
    const std::array<std::array<std::uint32_t, 4>, 4> start = {{{a, b, c, d}, {a, d, b, c}, {b, d, c, a}, {c, d, a, b}}};
    for (const auto& s : start) {
        face x;
        x.v = {s[0], s[1], s[2]};
        if (orient3d(p[x.v[0]], p[x.v[1]], p[x.v[2]], p[s[3]]) == sign::negative) std::swap(x.v[1], x.v[2]);
        f.push_back(x);
    }
    auto link = [&](std::uint32_t fi) { // neighbours among the four initial faces, by shared edges
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t u = f[fi].v[std::size_t(e)], w = f[fi].v[std::size_t((e + 1) % 3)];
            for (std::uint32_t g = 0; g < 4; ++g)
                for (int k = 0; k < 3; ++k)
                    if (g != fi && f[g].v[std::size_t(k)] == w && f[g].v[std::size_t((k + 1) % 3)] == u) f[fi].nb[std::size_t(e)] = g;
        }
    };
    for (std::uint32_t i = 0; i < 4; ++i) link(i);
    auto visible = [&](const face& x, std::uint32_t q) { return orient3d(p[x.v[0]], p[x.v[1]], p[x.v[2]], p[q]) == sign::negative; };
    for (std::uint32_t q = 0; q < p.size(); ++q) {
        if (q == a || q == b || q == c || q == d) continue;
        for (auto& x : f)
            if (visible(x, q)) {
                x.outside.push_back(q);
                break;
            }
    }
    std::vector<std::uint32_t> work = {0, 1, 2, 3}, vis, stack, horizon_face;
    std::vector<std::array<std::uint32_t, 2>> horizon;
    std::vector<char> mark;
    std::vector<std::uint32_t> start_of(p.size(), ~std::uint32_t{0});
    while (!work.empty()) {
        const std::uint32_t fi = work.back();
        work.pop_back();
        if (!f[fi].alive || f[fi].outside.empty()) continue;
        // the eye: the outside point farthest from the face's plane (approximately)
        std::uint32_t eye = f[fi].outside[0];
        double best = 0;
        for (std::uint32_t q : f[fi].outside)
            if (const double o = -approx_orient(p[f[fi].v[0]], p[f[fi].v[1]], p[f[fi].v[2]], p[q]); o > best) best = o, eye = q;
        // visible faces by depth-first search; the horizon in the visible faces' orientation
        mark.assign(f.size(), 0);
        vis.clear(), horizon.clear(), horizon_face.clear();
        stack = {fi};
        mark[fi] = 1;
        while (!stack.empty()) {
            const std::uint32_t g = stack.back();
            stack.pop_back();
            vis.push_back(g);
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t h = f[g].nb[std::size_t(e)];
                if (mark[h] == 1) continue;
                if (mark[h] == 0 && visible(f[h], eye)) {
                    mark[h] = 1;
                    stack.push_back(h);
                } else {
                    mark[h] = 2;
                    horizon.push_back({f[g].v[std::size_t(e)], f[g].v[std::size_t((e + 1) % 3)]});
                    horizon_face.push_back(h);
                }
            }
        }
        // one new face (u, v, eye) per horizon edge u -> v
        const auto first_new = static_cast<std::uint32_t>(f.size());
        for (std::size_t k = 0; k < horizon.size(); ++k) {
            face x;
            x.v = {horizon[k][0], horizon[k][1], eye};
            x.nb[0] = horizon_face[k];
            const std::uint32_t id = first_new + static_cast<std::uint32_t>(k);
            face& out = f[horizon_face[k]]; // the kept neighbour now borders the new face
            for (int e = 0; e < 3; ++e)
                if (out.v[std::size_t(e)] == horizon[k][1] && out.v[std::size_t((e + 1) % 3)] == horizon[k][0]) out.nb[std::size_t(e)] = id;
            start_of[horizon[k][0]] = id;
            f.push_back(x);
        }
        for (std::uint32_t id = first_new; id < f.size(); ++id) {
            const std::uint32_t v = f[id].v[1], u = f[id].v[0];
            const std::uint32_t next = start_of[v]; // the new face (v, w, eye) shares edge v-eye
            f[id].nb[1] = next;
            f[next].nb[2] = id;
            (void)u;
        }
        // hand the visible faces' outside points to the new faces
        for (std::uint32_t g : vis) {
            f[g].alive = false;
            for (std::uint32_t q : f[g].outside) {
                if (q == eye) continue;
                for (std::uint32_t id = first_new; id < f.size(); ++id)
                    if (visible(f[id], q)) {
                        f[id].outside.push_back(q);
                        break;
                    }
            }
            std::vector<std::uint32_t>().swap(f[g].outside);
        }
        for (std::uint32_t id = first_new; id < f.size(); ++id)
            if (!f[id].outside.empty()) work.push_back(id);
    }
    std::vector<face> alive;
    for (auto& x : f)
        if (x.alive) alive.push_back(x);
    return alive;
}

// A hull vertex is extreme unless all its faces lie in at most two planes.
inline std::vector<char> extreme(const std::vector<point3>& p, const std::vector<face>& faces) {
    std::vector<std::vector<std::uint32_t>> around(p.size());
    for (std::uint32_t i = 0; i < faces.size(); ++i)
        for (std::uint32_t v : faces[i].v) around[v].push_back(i);
    std::vector<char> out(p.size(), 0);
    for (std::uint32_t v = 0; v < p.size(); ++v) {
        std::vector<std::uint32_t> planes;
        for (std::uint32_t i : around[v]) {
            bool same = false;
            for (std::uint32_t r : planes) {
                const auto& a = faces[r].v;
                same = same || (orient3d(p[a[0]], p[a[1]], p[a[2]], p[faces[i].v[0]]) == sign::zero &&
                                orient3d(p[a[0]], p[a[1]], p[a[2]], p[faces[i].v[1]]) == sign::zero &&
                                orient3d(p[a[0]], p[a[1]], p[a[2]], p[faces[i].v[2]]) == sign::zero);
            }
            if (!same) planes.push_back(i);
            if (planes.size() >= 3) break;
        }
        out[v] = planes.size() >= 3;
    }
    return out;
}
} // namespace hull_detail

[[nodiscard]] inline result<hull> convex_hull(std::span<const point3> points) {
    using namespace hull_detail;
    if (points.empty()) return error{errc::empty_input};
    for (const point3& q : points)
        if (!is_finite(q)) return error{errc::not_finite};
    std::vector<point3> p(points.begin(), points.end());
    std::sort(p.begin(), p.end(), lex_less);
    p.erase(std::unique(p.begin(), p.end()), p.end());
    hull h;
    if (p.size() == 1) {
        h.vertices = p;
        return h;
    }
    const std::uint32_t a = 0, b = static_cast<std::uint32_t>(p.size() - 1); // lexicographic extremes
    // c: not collinear with a, b (the approximately farthest, else any exact one)
    std::uint32_t c = a;
    double best = -1;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (const double l = squared_length(cross(p[b] - p[a], p[i] - p[a])); l > best) best = l, c = i;
    if (collinear(p[a], p[b], p[c])) {
        c = a;
        for (std::uint32_t i = 0; i < p.size() && c == a; ++i)
            if (!collinear(p[a], p[b], p[i])) c = i;
    }
    if (c == a) { // collinear: the segment between the lexicographic extremes
        h.dimension = 1;
        h.vertices = {p[a], p[b]};
        return h;
    }
    std::uint32_t d = a;
    best = -1;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (const double o = arith::abs(approx_orient(p[a], p[b], p[c], p[i])); o > best) best = o, d = i;
    if (orient3d(p[a], p[b], p[c], p[d]) == sign::zero) {
        d = a;
        for (std::uint32_t i = 0; i < p.size() && d == a; ++i)
            if (orient3d(p[a], p[b], p[c], p[i]) != sign::zero) d = i;
    }
    if (d == a) { // coplanar: drop an axis along which the plane's normal is nonzero
        int drop = 2;
        if (orient2d(point2{p[a].x, p[a].y}, point2{p[b].x, p[b].y}, point2{p[c].x, p[c].y}) == sign::zero)
            drop = orient2d(point2{p[a].y, p[a].z}, point2{p[b].y, p[b].z}, point2{p[c].y, p[c].z}) != sign::zero ? 0 : 1;
        const auto ring = polygon(p, drop);
        h.dimension = 2;
        for (std::uint32_t i : ring) h.vertices.push_back(p[i]);
        for (std::uint32_t k = 1; k + 1 < ring.size(); ++k) h.triangles.push_back({0, k, k + 1});
        return h;
    }
    auto faces = quickhull(p, {a, b, c, d});
    auto keep = extreme(p, faces);
    std::vector<point3> ext;
    bool all = true;
    std::vector<char> used(p.size(), 0);
    for (const auto& x : faces)
        for (std::uint32_t v : x.v) used[v] = 1;
    for (std::uint32_t v = 0; v < p.size(); ++v)
        if (used[v]) {
            if (keep[v]) ext.push_back(p[v]);
            else all = false;
        }
    if (!all) { // a second pass over the extreme points only: every vertex is then extreme
        p = ext;
        std::uint32_t t[4] = {0, 0, 0, 0};
        // a non-degenerate tetrahedron among the extreme points
        t[1] = 1;
        for (std::uint32_t i = 2; i < p.size() && t[2] == 0; ++i)
            if (!collinear(p[t[0]], p[t[1]], p[i])) t[2] = i;
        for (std::uint32_t i = 2; i < p.size() && t[3] == 0; ++i)
            if (orient3d(p[t[0]], p[t[1]], p[t[2]], p[i]) != sign::zero) t[3] = i;
        faces = quickhull(p, {t[0], t[1], t[2], t[3]});
        std::fill(used.begin(), used.end(), 0);
        used.resize(p.size(), 0);
        for (const auto& x : faces)
            for (std::uint32_t v : x.v) used[v] = 1;
    }
    std::vector<std::uint32_t> index(p.size(), 0);
    h.dimension = 3;
    for (std::uint32_t v = 0; v < p.size(); ++v)
        if (used[v]) index[v] = static_cast<std::uint32_t>(h.vertices.size()), h.vertices.push_back(p[v]);
    for (const auto& x : faces) h.triangles.push_back({index[x.v[0]], index[x.v[1]], index[x.v[2]]});
    return h;
}

} // namespace incidence::bound
