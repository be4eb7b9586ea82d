// Cases for the polygon pairs: simple star polygons, half of them with a hole, and the oracle's
// view of them. Include after flat_cases.hpp.
//
// A star polygon: the boundary points of the square [-n, n]^2 in order (8n of them), each point g
// pushed to centre + r g with r in {1/2, 1, 3/2} (dyadic, so exact): non-convex and simple, since
// every edge lies on one side of the square and projects from the centre onto that side. A hole:
// the same with n = 1 at an eighth of the size around the same centre (within 3/16 n of it, where
// the outer ring is at least n/2 away), in either orientation.
// Near-degenerate: the other shape placed at a point X of a ring (a vertex, an edge's midpoint or
// quarter point) as in flat_cases.hpp (through X, along that edge, or along a random direction),
// at the centre (in the hole, or inside) or between the rings (inside); then one random
// exact-or-nudged scale and translation for both. Random: a polygon around a random centre in
// [-1, 1]^2 of size about 1/2 and a random shape of flat_cases.hpp.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace support {

struct polygon_store {
    std::vector<incidence::point2> v;
    std::vector<std::uint32_t> ends; // empty: one ring
    [[nodiscard]] incidence::polygon2 view() const { return {v, ends}; }
};
inline oracle::polygon_data polygon_data_of(const incidence::polygon2& g) {
    oracle::polygon_data d;
    for (const auto& p : g.vertices) d.v.push_back({p.x, p.y});
    if (g.ring_ends.empty()) d.ring_ends.push_back(static_cast<unsigned>(g.vertices.size()));
    for (auto e : g.ring_ends) d.ring_ends.push_back(e);
    return d;
}

inline void star_ring(rng& r, int n, incidence::point2 centre, double unit, bool reversed, std::vector<incidence::point2>& out) {
    std::vector<incidence::point2> ring;
    auto add = [&](int x, int y) {
        static constexpr double radii[] = {0.5, 1.0, 1.5};
        const double k = radii[r.integer(0, 2)] * unit;
        ring.push_back({centre.x + k * x, centre.y + k * y});
    };
    for (int i = -n; i < n; ++i) add(i, -n); // bottom, left to right
    for (int i = -n; i < n; ++i) add(n, i);  // right, upwards
    for (int i = n; i > -n; --i) add(i, n);  // top, right to left
    for (int i = n; i > -n; --i) add(-n, i); // left, downwards
    if (reversed) std::reverse(ring.begin(), ring.end());
    out.insert(out.end(), ring.begin(), ring.end());
}
// The star polygon of grid size n around `centre`, with a hole half of the time.
inline void star_polygon(rng& r, int n, incidence::point2 centre, double unit, polygon_store& g) {
    g.v.clear();
    g.ends.clear();
    star_ring(r, n, centre, unit, r.coin(), g.v);
    if (r.coin()) {
        g.ends.push_back(static_cast<std::uint32_t>(g.v.size()));
        star_ring(r, 1, centre, unit * n / 8, r.coin(), g.v);
        g.ends.push_back(static_cast<std::uint32_t>(g.v.size()));
    } else if (r.coin()) {
        g.ends.push_back(static_cast<std::uint32_t>(g.v.size())); // one ring, its end listed
    }
}
inline void realise_polygon(polygon_store& g, transform& tr) {
    for (auto& p : g.v) p = moved(p, tr);
}
// A point of a ring: a vertex, an edge's midpoint or quarter point; `along` gets that edge.
inline incidence::point2 ring_point(rng& r, const polygon_store& g, incidence::vec2& along) {
    const incidence::polygon2 view = g.view();
    const std::size_t ring = static_cast<std::size_t>(r.integer(0, static_cast<int>(view.rings()) - 1));
    const std::size_t b = view.ring_begin(ring), e = view.ring_end(ring);
    const std::size_t j = b + static_cast<std::size_t>(r.integer(0, static_cast<int>(e - b) - 1));
    const incidence::point2 a = g.v[j], c = g.v[incidence::polygon2::next(j, b, e)];
    along = c - a;
    switch (r.integer(0, 2)) {
    case 0: return a;
    case 1: return a + 0.5 * (c - a);
    default: return a + 0.25 * (c - a);
    }
}

// Every case: the polygon in `store` (and a second one in `other` for polygon against polygon),
// the other shape returned (for a polygon, its view of `other`).
template <class B>
B polygon_near(rng& r, polygon_store& store, polygon_store& other) {
    using namespace incidence;
    const point2 centre{small(r), small(r)};
    const int n = r.integer(1, 3);
    star_polygon(r, n, centre, 1.0, store);
    vec2 along{};
    const int where = r.integer(0, 7);
    const point2 X = where == 0 ? centre : (where == 1 ? centre + vec2{0.375 * n, 0.0} : ring_point(r, store, along));
    const vec2 d = where < 2 || r.coin() ? small_dir2(r) : along;
    transform tr = random_transform(r, true, true);
    if constexpr (std::is_same_v<B, polygon2>) {
        star_polygon(r, 1, point2{0, 0}, 1.0, other);
        vec2 unused{};
        const point2 Y = ring_point(r, other, unused);
        for (auto& p : other.v) p = p + (X - Y); // the other polygon's ring point Y at X (exact: small numbers)
        realise_polygon(store, tr);
        realise_polygon(other, tr);
        return other.view();
    } else {
        const auto b = place2<B>(r, X, d);
        realise_polygon(store, tr);
        return realise(b, tr);
    }
}
template <class B>
B polygon_random(rng& r, polygon_store& store, polygon_store& other) {
    using namespace incidence;
    star_polygon(r, r.integer(1, 3), point2{r.uniform(-1, 1), r.uniform(-1, 1)}, 0.125, store);
    transform tr = random_transform(r, false, true);
    realise_polygon(store, tr);
    if constexpr (std::is_same_v<B, polygon2>) {
        star_polygon(r, r.integer(1, 2), point2{r.uniform(-1, 1), r.uniform(-1, 1)}, 0.125, other);
        realise_polygon(other, tr);
        return other.view();
    } else {
        const auto b = random_shape2<B>(r);
        return realise(b, tr);
    }
}

// For contains(polygon, segment | triangle), in the polygon's own small coordinates: a star
// polygon (a hole half of the time) and three points: a ring point X, then along that ring's edge,
// another ring point, or from the point between the rings (inside) towards X, a little short of or
// past it, or along a random direction; the last two points are X's partners (a segment's end, a
// triangle's corners), the second nudged by ulps half of the time.
inline std::array<incidence::point2, 3> points_in_star(rng& r, polygon_store& store) {
    using namespace incidence;
    const point2 centre{small(r), small(r)};
    const int n = r.integer(1, 3);
    star_polygon(r, n, centre, 1.0, store);
    vec2 along{}, unused{};
    const point2 X = ring_point(r, store, along);
    const point2 P = centre + vec2{0.375 * n, 0.0}; // between the rings: inside
    std::array<point2, 3> out{X, X, X};
    for (int i = 1; i < 3; ++i) switch (r.integer(0, 3)) {
        case 0: out[i] = X + (r.integer(-4, 4) * 0.25) * along; break;
        case 1: out[i] = ring_point(r, store, unused); break;
        case 2: out[0] = P, out[i] = X + (r.integer(-2, 2) * 0.125) * (X - P); break;
        default: out[i] = P + (r.integer(1, 4) * 0.125) * small_dir2(r); break;
        }
    if (r.coin()) out[1] = {nudge(out[1].x, r.integer(-2, 2)), nudge(out[1].y, r.integer(-2, 2))};
    return out;
}
// contains(polygon, segment): points_in_star's first two points, then one exact-or-nudged scale
// 2^-500..2^500 and translation.
inline incidence::segment2 segment_in_polygon_near(rng& r, polygon_store& store) {
    const auto p = points_in_star(r, store);
    incidence::segment2 s{p[0], p[1]};
    if (r.coin()) std::swap(s.a, s.b);
    transform tr = random_transform(r, r.integer(0, 3) == 0, true);
    realise_polygon(store, tr);
    return realise(s, tr);
}
// A random star polygon (as polygon_random) and a segment between two points of its vertices'
// box, or an eighth of one.
inline incidence::segment2 segment_in_polygon_random(rng& r, polygon_store& store) {
    using namespace incidence;
    star_polygon(r, r.integer(1, 3), point2{r.uniform(-1, 1), r.uniform(-1, 1)}, 0.125, store);
    transform tr = random_transform(r, false, true);
    realise_polygon(store, tr);
    const auto box = detail::polygon2d::bounds(store.view());
    auto at = [&] {
        return point2{box.min.x + (box.max.x - box.min.x) * r.uniform(0, 1), box.min.y + (box.max.y - box.min.y) * r.uniform(0, 1)};
    };
    const point2 a = at(), b = at();
    return r.coin() ? segment2{a, b} : segment2{a, a + 0.125 * (b - a)};
}
inline bool segment_in_polygon_truth(const incidence::polygon2& g, const incidence::segment2& s) {
    return oracle::polygon_contains_segment(polygon_data_of(g), {s.a.x, s.a.y}, {s.b.x, s.b.y});
}

// The oracle's answer (tests/oracle/cgal_polygon.cpp).
template <class B>
bool polygon_truth(const incidence::polygon2& g, const B& b) {
    using namespace incidence;
    const auto gd = polygon_data_of(g);
    if constexpr (std::is_same_v<B, polygon2>) return oracle::polygon_polygon_intersect(gd, polygon_data_of(b));
    else return oracle::polygon_intersect(gd, to_flat(b));
}

} // namespace support
