// Cases and the exact truth for the containment queries of the boxes and the ball:
// contains(obb3 | aabb3, x) and contains(sphere3, box). Each generator places the inner shape inside
// the outer one, on its boundary from inside, or just beyond it (exactly, in the near boxes' small
// dyadic frames), then moves both by a random exact-or-nudged scale and translation; the random
// cases are the pairs' random cases. No test harness here (the benchmarks use these too): the
// checks are contain_checks.hpp.
#pragma once
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>
#include "obb_cases.hpp"
#include "flat_cases.hpp"
#include "flat_shapes.hpp"
#include "sphere_points.hpp"

namespace support {

using incidence::sphere3;

// t in [-1, 1]: on the boundary a third of the time.
inline double inside_t(rng& r) {
    const int w = r.integer(0, 8);
    return w < 3 ? (r.coin() ? 1.0 : -1.0) : r.integer(-4, 4) * 0.25;
}
inline double beyond_t(rng& r) { return (r.coin() ? 1.0 : -1.0) * (1.0 + std::ldexp(1.0, -r.integer(4, 30))); }
// c + sum t_i h_i a_i: exact for the near boxes (small dyadic centre, extents and frames).
inline point3 frame_point(const obb3& o, const double t[3]) {
    point3 p = o.center;
    for (unsigned i = 0; i < 3; ++i) {
        const double f = t[i] * o.half_extents[i];
        p = point3{p.x + f * o.axes[i].x, p.y + f * o.axes[i].y, p.z + f * o.axes[i].z};
    }
    return p;
}
// A point of o (beyond: one coordinate just past a face).
inline point3 inside_point(rng& r, const obb3& o, bool beyond = false) {
    double t[3] = {inside_t(r), inside_t(r), inside_t(r)};
    if (beyond) t[r.integer(0, 2)] = beyond_t(r);
    return frame_point(o, t);
}
// The box's extent along each coordinate axis: sum_j h_j |a_j . e|.
inline vec3 reach(const obb3& o) {
    vec3 e{0, 0, 0};
    for (unsigned j = 0; j < 3; ++j) {
        e.x += o.half_extents[j] * std::fabs(o.axes[j].x);
        e.y += o.half_extents[j] * std::fabs(o.axes[j].y);
        e.z += o.half_extents[j] * std::fabs(o.axes[j].z);
    }
    return e;
}
// Half extents a, b, c >= 0 with a^2 + b^2 + c^2 = d^2 (sphere_points.hpp's quadruples, scaled by
// 2^-k), so a box of these half extents in a unit frame has its corners exactly at distance d.
inline std::array<double, 4> pythagorean_extents(rng& r) {
    const quad q = pythagorean(r);
    const double s = std::ldexp(1.0, -r.integer(0, 3));
    return {std::fabs(q.x) * s, std::fabs(q.y) * s, std::fabs(q.z) * s, q.w * s};
}
// A near box whose frame is a signed permutation of the unit axes (unit length, so distances to
// its faces and corners are exact).
inline obb3 unit_frame_obb(rng& r) {
    for (;;) {
        const obb3 o = near_obb(r);
        bool unit = true;
        for (const vec3& a : o.axes) unit = unit && std::fabs(a.x) + std::fabs(a.y) + std::fabs(a.z) == 1.0;
        if (unit) return o;
    }
}
// A box inside o: a shrunk copy touching o's faces from inside (each extent a fraction of o's, the
// centre moved by what was taken off), or in a third of the cases, turned to another near frame.
inline obb3 box_within(rng& r, const obb3& o) {
    obb3 b = o;
    double t[3];
    for (unsigned i = 0; i < 3; ++i) {
        const double f = r.integer(0, 4) * 0.25;
        b.half_extents[i] = f * o.half_extents[i];
        t[i] = r.integer(-1, 1) * (1 - f);
        if (r.integer(0, 11) == 0) t[i] *= 1.0 + std::ldexp(1.0, -r.integer(4, 30)); // just beyond
    }
    b.center = frame_point(o, t);
    if (r.integer(0, 2) == 0) b = rewritten(b, r.integer(0, 1));
    else if (r.integer(0, 2) == 0) b.axes = near_frame(r);
    return b;
}
inline segment3 moved(const transform& tr, const segment3& s) { return {moved(tr, s.a), moved(tr, s.b)}; }
inline triangle3 moved(const transform& tr, const triangle3& t) { return {moved(tr, t.a), moved(tr, t.b), moved(tr, t.c)}; }
inline tetrahedron3 moved(const transform& tr, const tetrahedron3& t) {
    return {moved(tr, t.a), moved(tr, t.b), moved(tr, t.c), moved(tr, t.d)};
}
inline aabb3 moved(const transform& tr, const aabb3& b) { return ordered(aabb3{moved(tr, b.min), moved(tr, b.max)}); }
inline sphere3 moved(const transform& tr, const sphere3& s) { return {moved(tr, s.center), tr.scale_only(s.radius)}; }
inline transform contain_transform(rng& r) { return random_transform(r, r.coin(), true); }

// contains(o, x) cases with o an obb3: x within o (exactly, before the transform) or just beyond.
template <class B>
std::pair<obb3, B> obb_holding(rng& r) {
    const obb3 o = std::is_same_v<B, aabb3> && r.integer(0, 3) != 0 ? unit_frame_obb(r) : near_obb(r);
    const bool out = r.integer(0, 3) == 0; // the first vertex just beyond a face
    auto v = [&](bool first) { return inside_point(r, o, first && out); };
    B x{};
    if constexpr (std::is_same_v<B, point3>) x = v(true);
    else if constexpr (std::is_same_v<B, segment3>) x = {v(true), v(false)};
    else if constexpr (std::is_same_v<B, triangle3>) x = {v(true), v(false), v(false)};
    else if constexpr (std::is_same_v<B, tetrahedron3>) x = {v(true), v(false), v(false), v(false)};
    else if constexpr (std::is_same_v<B, aabb3>) x = ordered(aabb3{v(true), v(false)}); // inside when o's frame is a unit one
    else if constexpr (std::is_same_v<B, obb3>) x = box_within(r, o);
    const auto tr = contain_transform(r);
    return {moved(tr, o), moved(tr, x)};
}
// contains(aabb, obb): the box is the oriented box's bounding box, padded by 0, by a quarter or by
// 2^-k on each side, and in a quarter of the cases one side moved in by 2^-k (the box pokes out).
inline std::pair<aabb3, obb3> aabb_holding_obb(rng& r) {
    const obb3 o = near_obb(r);
    const vec3 e = reach(o);
    auto pad = [&] {
        const int w = r.integer(0, 3);
        return w < 2 ? 0.0 : (w == 2 ? 0.25 : std::ldexp(1.0, -r.integer(2, 30)));
    };
    double lo[3] = {o.center.x - e.x - pad(), o.center.y - e.y - pad(), o.center.z - e.z - pad()};
    double hi[3] = {o.center.x + e.x + pad(), o.center.y + e.y + pad(), o.center.z + e.z + pad()};
    if (r.integer(0, 3) == 0) { // one side moved in: the oriented box pokes out
        const int i = r.integer(0, 2);
        const double in = std::ldexp(1.0, -r.integer(2, 30));
        if (r.coin()) lo[i] += in;
        else hi[i] -= in;
    }
    const aabb3 b{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    const auto tr = contain_transform(r);
    return {moved(tr, ordered(b)), moved(tr, o)};
}
// A ball inside a box of a unit frame: its centre a frame point, its radius the distance to the
// nearest face (touching it), or less, or a little more.
inline double radius_near(rng& r, double d) {
    const int w = r.integer(0, 3);
    if (w == 0) return d * 0.5;
    if (w == 3) return d * (1.0 + std::ldexp(1.0, -r.integer(4, 30)));
    return d;
}
inline std::pair<obb3, sphere3> obb_holding_ball(rng& r) {
    const obb3 o = r.integer(0, 3) == 0 ? near_obb(r) : unit_frame_obb(r);
    double t[3], d = INFINITY;
    for (unsigned i = 0; i < 3; ++i) {
        t[i] = r.integer(-4, 4) * 0.25;
        d = std::fmin(d, (1 - std::fabs(t[i])) * o.half_extents[i]);
    }
    const sphere3 s{frame_point(o, t), radius_near(r, d)};
    const auto tr = contain_transform(r);
    return {moved(tr, o), moved(tr, s)};
}
inline std::pair<aabb3, sphere3> aabb_holding_ball(rng& r) {
    const point3 c{small(r), small(r), small(r)};
    double lo[3], hi[3], d = INFINITY;
    const double cc[3] = {c.x, c.y, c.z};
    for (int i = 0; i < 3; ++i) {
        lo[i] = cc[i] - r.integer(0, 8) * 0.25;
        hi[i] = cc[i] + r.integer(0, 8) * 0.25;
        d = std::fmin(d, std::fmin(cc[i] - lo[i], hi[i] - cc[i]));
    }
    const aabb3 b{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    const sphere3 s{c, radius_near(r, d)};
    const auto tr = contain_transform(r);
    return {moved(tr, b), moved(tr, s)};
}
// A box in a ball: half extents a, b, c with a^2 + b^2 + c^2 = d^2, so the corners lie exactly on
// the sphere of radius d about the box's centre (a unit frame for the oriented box).
inline std::pair<sphere3, obb3> ball_holding_obb(rng& r) {
    obb3 o = r.integer(0, 3) == 0 ? near_obb(r) : unit_frame_obb(r);
    const auto q = pythagorean_extents(r);
    for (unsigned i = 0; i < 3; ++i) o.half_extents[i] = q[i];
    const sphere3 s{o.center, radius_near(r, q[3])};
    const auto tr = contain_transform(r);
    return {moved(tr, s), moved(tr, o)};
}
inline std::pair<sphere3, aabb3> ball_holding_aabb(rng& r) {
    const point3 c{small(r), small(r), small(r)};
    const auto q = pythagorean_extents(r);
    const aabb3 b{{c.x - q[0], c.y - q[1], c.z - q[2]}, {c.x + q[0], c.y + q[1], c.z + q[2]}};
    const sphere3 s{c, radius_near(r, q[3])};
    const auto tr = contain_transform(r);
    return {moved(tr, s), moved(tr, b)};
}
// contains(tetrahedron, obb): a corner p of a near box and its three edges e_j into the box span
// the tetrahedron p, p + s e_1, p + s e_2, p + s e_3, which holds the box exactly for s >= 3 (the far
// corner p + e_1 + e_2 + e_3 on the far face at s = 3); s is 3, a little more or a little less, or
// 4. A quarter of the cases is flat: one extent zero, the tetrahedron p, p + s e_1, p + s e_2 and a
// fourth point in their plane (the box's far corner on the hypotenuse at s = 2). The vertices come
// in a random order, so both orientations occur.
inline std::pair<tetrahedron3, obb3> tetrahedron_holding_obb(rng& r) {
    obb3 o = near_obb(r);
    const bool flat = r.integer(0, 3) == 0;
    const unsigned z = static_cast<unsigned>(r.integer(0, 2)); // the flat box's zero extent
    if (flat) o.half_extents[z] = 0;
    double t[3];
    for (double& x : t) x = r.coin() ? 1.0 : -1.0; // the corner p
    const int w = r.integer(0, 3);
    const double base = flat ? 2.0 : 3.0;
    const double s = w == 0 ? base
                            : (w == 1 ? base * (1.0 + std::ldexp(1.0, -r.integer(4, 30)))
                                      : (w == 2 ? base * (1.0 - std::ldexp(1.0, -r.integer(4, 30))) : base + 1));
    auto along = [&](unsigned j, double f) { // p + f e_j
        double u[3] = {t[0], t[1], t[2]};
        u[j] = t[j] * (1 - 2 * f);
        return frame_point(o, u);
    };
    point3 v[4];
    v[0] = frame_point(o, t);
    if (!flat) {
        for (unsigned j = 0; j < 3; ++j) v[j + 1] = along(j, s);
    } else {
        const unsigned j = (z + 1) % 3, k = (z + 2) % 3;
        v[1] = along(j, s), v[2] = along(k, s);
        double u[3] = {t[0], t[1], t[2]};
        u[j] = t[j] * (1 - 2 * 0.5 * r.integer(0, 4) * 0.5), u[k] = t[k] * (1 - 2 * 0.5 * r.integer(0, 4) * 0.5);
        v[3] = frame_point(o, u); // a point of the plane, inside the triangle or not
    }
    for (int i = 3; i > 0; --i) std::swap(v[i], v[r.integer(0, i)]);
    const auto tr = contain_transform(r);
    return {moved(tr, tetrahedron3{v[0], v[1], v[2], v[3]}), moved(tr, o)};
}
// contains(aabb, x) cases: the box of a unit-frame near box (its reach along each coordinate), x's
// vertices inside it, on its boundary or just beyond.
template <class B>
std::pair<aabb3, B> aabb_holding(rng& r) {
    const obb3 o = unit_frame_obb(r);
    const vec3 e = reach(o);
    const aabb3 b{{o.center.x - e.x, o.center.y - e.y, o.center.z - e.z}, {o.center.x + e.x, o.center.y + e.y, o.center.z + e.z}};
    const bool out = r.integer(0, 3) == 0;
    B x{};
    if constexpr (std::is_same_v<B, segment3>) x = {inside_point(r, o, out), inside_point(r, o)};
    else x = {inside_point(r, o, out), inside_point(r, o), inside_point(r, o)};
    const auto tr = contain_transform(r);
    return {moved(tr, b), moved(tr, x)};
}
// intersects(aabb, sphere) near cases: a ball touching a small dyadic box at a face, an edge or a
// corner from outside (the centre's offset from the box along the active axes is d (1 axis),
// (3, 4) s (2 axes) or (1, 2, 2) s (3 axes), the radius its exact length), a little short of it or
// a little past it, or a ball around a point inside the box.
inline std::pair<aabb3, sphere3> ball_touching_aabb(rng& r) {
    double lo[3], hi[3], c[3];
    for (int i = 0; i < 3; ++i) {
        lo[i] = small(r);
        hi[i] = lo[i] + r.integer(0, 8) * 0.25;
    }
    int side[3], active = 0;
    for (int i = 0; i < 3; ++i) side[i] = r.integer(-1, 1), active += side[i] != 0;
    const double s = std::ldexp(1.0, -r.integer(0, 3));
    static constexpr double legs[4][3] = {{0, 0, 0}, {1, 0, 0}, {3, 4, 0}, {1, 2, 2}};
    static constexpr double length[4] = {0, 1, 5, 3};
    int k = 0;
    for (int i = 0; i < 3; ++i) {
        if (side[i] == 0) c[i] = lo[i] + (hi[i] - lo[i]) * r.integer(0, 4) * 0.25;
        else c[i] = side[i] < 0 ? lo[i] - legs[active][k++] * s : hi[i] + legs[active][k++] * s;
    }
    const double d = active == 0 ? r.integer(0, 4) * 0.25 : length[active] * s;
    const int w = r.integer(0, 3);
    const double radius = w < 2 ? d : d * (1.0 + (w == 2 ? 1.0 : -1.0) * std::ldexp(1.0, -r.integer(4, 30)));
    const auto tr = contain_transform(r);
    return {moved(tr, aabb3{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}), moved(tr, sphere3{{c[0], c[1], c[2]}, radius})};
}
inline sphere3 random_ball(rng& r, const transform& tr) { return {random_point(r, tr), tr.scale_only(r.uniform(0, 0.75))}; }
inline aabb3 random_aabb(rng& r, const transform& tr) { return ordered(aabb3{random_point(r, tr), random_point(r, tr)}); }

// --- the oracle ---------------------------------------------------------------------------------
inline void box_arrays(const obb3& b, double c[3], double axes[9]) {
    arr(b.center, c);
    for (unsigned i = 0; i < 3; ++i) arr(b.axes[i], axes + 3 * i);
}
inline bool points_in(const obb3& o, const std::vector<point3>& pts) {
    std::vector<double> v;
    for (const auto& p : pts) v.insert(v.end(), {p.x, p.y, p.z});
    double c[3], a[9];
    box_arrays(o, c, a);
    return oracle::all_in_box(v.data(), pts.size(), c, a, o.half_extents.data());
}
inline std::vector<point3> corners(const aabb3& b) {
    std::vector<point3> v;
    for (int j = 0; j < 8; ++j) v.push_back({(j & 1) ? b.max.x : b.min.x, (j & 2) ? b.max.y : b.min.y, (j & 4) ? b.max.z : b.min.z});
    return v;
}
inline std::vector<point3> vertices(const point3& p) { return {p}; }
inline std::vector<point3> vertices(const segment3& s) { return {s.a, s.b}; }
inline std::vector<point3> vertices(const triangle3& t) { return {t.a, t.b, t.c}; }
inline std::vector<point3> vertices(const tetrahedron3& t) { return {t.a, t.b, t.c, t.d}; }
inline std::vector<point3> vertices(const aabb3& b) { return corners(b); }

// Is b inside a? Exact rationals: vertices or corners by Cramer's rule in the outer box's frame,
// the ball by its centre's distances to the faces, a box in a ball by its corners.
template <class A, class B>
bool contains_truth(const A& a, const B& b) {
    if constexpr (std::is_same_v<A, obb3> && std::is_same_v<B, obb3>) {
        double c[3], x[9], ic[3], ix[9];
        box_arrays(a, c, x);
        box_arrays(b, ic, ix);
        return oracle::box_in_box(c, x, a.half_extents.data(), ic, ix, b.half_extents.data());
    } else if constexpr (std::is_same_v<A, obb3> && std::is_same_v<B, sphere3>) {
        double c[3], x[9], sc[3];
        box_arrays(a, c, x);
        arr(b.center, sc);
        return oracle::ball_in_box(c, x, a.half_extents.data(), sc, b.radius);
    } else if constexpr (std::is_same_v<A, obb3>) {
        return points_in(a, vertices(b));
    } else if constexpr (std::is_same_v<A, aabb3> && std::is_same_v<B, obb3>) {
        double c[3], x[9];
        box_arrays(b, c, x);
        oracle::convex_set s;
        const double mn[3] = {a.min.x, a.min.y, a.min.z}, mx[3] = {a.max.x, a.max.y, a.max.z};
        for (int i = 0; i < 3; ++i) s.slabs.push_back({{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0}, mn[i], mx[i]});
        return oracle::box_in_constraints(c, x, b.half_extents.data(), s);
    } else if constexpr (std::is_same_v<A, aabb3> && std::is_same_v<B, sphere3>) {
        double mn[3], mx[3], sc[3];
        arr(a.min, mn), arr(a.max, mx), arr(b.center, sc);
        return oracle::ball_in_aabb(mn, mx, sc, b.radius);
    } else if constexpr (std::is_same_v<A, sphere3> && std::is_same_v<B, obb3>) {
        double c[3], x[9], sc[3];
        box_arrays(b, c, x);
        arr(a.center, sc);
        return oracle::box_in_ball(c, x, b.half_extents.data(), sc, a.radius);
    } else if constexpr (std::is_same_v<A, tetrahedron3> && std::is_same_v<B, obb3>) {
        double c[3], x[9];
        box_arrays(b, c, x);
        const double tv[12] = {a.a.x, a.a.y, a.a.z, a.b.x, a.b.y, a.b.z, a.c.x, a.c.y, a.c.z, a.d.x, a.d.y, a.d.z};
        return oracle::box_in_tetrahedron(c, x, b.half_extents.data(), tv);
    } else if constexpr (std::is_same_v<A, sphere3>) { // a box, a segment, a triangle or a tetrahedron: its vertices
        const auto v = vertices(b);
        std::vector<double> xyz;
        for (const auto& p : v) xyz.insert(xyz.end(), {p.x, p.y, p.z});
        double sc[3];
        arr(a.center, sc);
        return oracle::all_in_ball(xyz.data(), v.size(), sc, a.radius);
    } else { // an aabb3 around a segment or triangle: CGAL Epeck (Iso_cuboid_3 has_on per vertex)
        return flat_contains_truth(a, b);
    }
}
} // namespace support
