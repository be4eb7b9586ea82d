// Cases for the OBB pairs, and their conversion to the LP oracle's convex sets.
// Near-degenerate: a box with small dyadic centre and extents (zero extents included) and a frame
// that is a signed permutation of the unit axes, a dyadic near-rotation ((1, e, 0), (-e, 1, 0),
// (0, 0, 1 + e^2), exactly orthogonal), or small-integer skew axes (the box is the parallelepiped
// they span); a point of its boundary (a corner, an edge or face point, sometimes a quarter off)
// where the other shape is placed; then a random exact-or-nudged scale and translation.
// Random: a rotation from a random unit quaternion, random centre, extents and partner shape.
// Include after testing.hpp.
#pragma once
#include <array>
#include <cmath>
#include "lp_shapes.hpp"

namespace support {

using incidence::aabb3;
using incidence::line3;
using incidence::obb3;
using incidence::plane3;
using incidence::point3;
using incidence::ray3;
using incidence::segment3;
using incidence::tetrahedron3;
using incidence::triangle3;
using incidence::vec3;

inline std::array<vec3, 3> near_frame(rng& r) {
    std::array<vec3, 3> a{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
    const int kind = r.integer(0, 2);
    if (kind == 1) {
        const double e = std::ldexp(1.0, -r.integer(3, 12)) * (r.coin() ? 1 : -1);
        a = {vec3{1, e, 0}, vec3{-e, 1, 0}, vec3{0, 0, 1 + e * e}};
    } else if (kind == 2) {
        for (;;) { // small-integer skew axes, independent
            for (auto& v : a) v = {double(r.integer(-2, 2)), double(r.integer(-2, 2)), double(r.integer(-2, 2))};
            a[0].x += 3, a[1].y += 3, a[2].z += 3;
            const double d = a[0].x * (a[1].y * a[2].z - a[1].z * a[2].y) - a[0].y * (a[1].x * a[2].z - a[1].z * a[2].x) +
                             a[0].z * (a[1].x * a[2].y - a[1].y * a[2].x);
            if (d != 0) break;
        }
    }
    // a signed permutation of the axes, and of the coordinates
    const int p = r.integer(0, 5);
    const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    std::array<vec3, 3> b;
    for (int i = 0; i < 3; ++i) {
        const vec3 v = a[perm[p][i]];
        const double s = r.coin() ? 1.0 : -1.0;
        b[i] = vec3{s * v.x, s * v.y, s * v.z};
    }
    const int q = r.integer(0, 5);
    for (auto& v : b) {
        const double c[3] = {v.x, v.y, v.z};
        v = vec3{c[perm[q][0]], c[perm[q][1]], c[perm[q][2]]};
    }
    return b;
}
inline obb3 near_obb(rng& r) {
    obb3 b{{small(r), small(r), small(r)}, near_frame(r), {}};
    for (double& h : b.half_extents) h = r.integer(0, 8) * 0.5;
    return b;
}
// c + sum s_i h_i a_i with s_i in {-1, 0, 1} (mostly +-1) or +-1/2: a corner, edge or face point;
// moved 1/4 along x for a sixth of them, unless `on` asks for a point on the boundary always.
inline point3 boundary_point(rng& r, const obb3& b, bool on = false) {
    point3 p = b.center;
    for (unsigned i = 0; i < 3; ++i) {
        const int w = r.integer(0, 5);
        const double s = w < 4 ? (r.coin() ? 1.0 : -1.0) : (w == 4 ? 0.0 : (r.coin() ? 0.5 : -0.5));
        const double f = s * b.half_extents[i];
        p = point3{p.x + f * b.axes[i].x, p.y + f * b.axes[i].y, p.z + f * b.axes[i].z};
    }
    if (!on && r.integer(0, 5) == 0) p.x += r.coin() ? 0.25 : -0.25;
    return p;
}
inline vec3 small_vec(rng& r) {
    for (;;) {
        const vec3 v{double(r.integer(-4, 4)), double(r.integer(-4, 4)), double(r.integer(-4, 4))};
        if (!(v.x == 0 && v.y == 0 && v.z == 0)) return v;
    }
}
inline point3 moved(const transform& tr, point3 p) { return {tr.apply(p.x, 0), tr.apply(p.y, 1), tr.apply(p.z, 2)}; }
inline vec3 moved_dir(const transform& tr, vec3 v) { return {tr.dir(v.x), tr.dir(v.y), tr.dir(v.z)}; }
inline obb3 moved(const transform& tr, obb3 b) {
    b.center = moved(tr, b.center);
    for (double& h : b.half_extents) h = tr.scale_only(h);
    return b;
}

// A random rotation (rows of the matrix of a random unit quaternion): orthonormal to rounding.
inline std::array<vec3, 3> random_frame(rng& r) {
    double q[4], n = 0;
    do {
        n = 0;
        for (double& x : q) x = r.uniform(-1, 1), n += x * x;
    } while (n < 0.01 || n > 1);
    n = std::sqrt(n);
    for (double& x : q) x /= n;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return {vec3{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            vec3{2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            vec3{2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
}
inline obb3 random_obb(rng& r, const transform& tr) {
    obb3 b{{random_coord(r, tr, 0), random_coord(r, tr, 1), random_coord(r, tr, 2)}, random_frame(r), {}};
    for (double& h : b.half_extents) h = tr.scale_only(r.uniform(0, 0.5));
    return b;
}
inline point3 random_point(rng& r, const transform& tr) { return {random_coord(r, tr, 0), random_coord(r, tr, 1), random_coord(r, tr, 2)}; }

// The same box written differently: one axis negated, the axes rotated (with their extents).
inline obb3 rewritten(const obb3& b, int how) {
    obb3 c = b;
    if (how == 0) c.axes[1] = vec3{-b.axes[1].x, -b.axes[1].y, -b.axes[1].z};
    else
        for (unsigned i = 0; i < 3; ++i) c.axes[i] = b.axes[(i + 1) % 3], c.half_extents[i] = b.half_extents[(i + 1) % 3];
    return c;
}

// The start of every near case: a box, a point of its boundary, and the transform to apply.
struct near_box {
    obb3 o;
    point3 p;
    transform tr;
};
inline near_box near_start(rng& r, bool any_scale) {
    const obb3 o = near_obb(r);
    const point3 p = boundary_point(r, o);
    return {o, p, random_transform(r, true, any_scale)};
}

// The near-degenerate and random cases of each OBB pair (tests/query/<pair>.cpp, bench).
template <class A, class B>
struct obb_case;
template <>
struct obb_case<incidence::obb3, incidence::obb3> {
    static std::pair<incidence::obb3, incidence::obb3> near(rng& r, bool any_scale = true) {
        const obb3 a = near_obb(r);
        obb3 b = near_obb(r);
        // b's own boundary point q, placed at a's boundary point p
        const point3 p = boundary_point(r, a);
        const point3 q = boundary_point(r, b);
        b.center = point3{b.center.x + (p.x - q.x), b.center.y + (p.y - q.y), b.center.z + (p.z - q.z)};
        const auto tr = random_transform(r, true, any_scale);
        return {moved(tr, a), moved(tr, b)};
    }
    static std::pair<incidence::obb3, incidence::obb3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        return {random_obb(r, tr), random_obb(r, tr)};
    }
};

template <>
struct obb_case<incidence::aabb3, incidence::obb3> {
    static std::pair<incidence::aabb3, incidence::obb3> near(rng& r, bool any_scale = true) {
        const auto [o, p, tr] = near_start(r, any_scale);
        double w[3], c[3];
        const double pc[3] = {p.x, p.y, p.z};
        for (int i = 0; i < 3; ++i) {
            w[i] = r.integer(0, 4) * 0.5;
            c[i] = pc[i] - r.integer(-1, 1) * w[i];
        }
        const aabb3 b{moved(tr, point3{c[0] - w[0], c[1] - w[1], c[2] - w[2]}), moved(tr, point3{c[0] + w[0], c[1] + w[1], c[2] + w[2]})};
        return {ordered(b), moved(tr, o)};
    }
    static std::pair<incidence::aabb3, incidence::obb3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        return {ordered(aabb3{random_point(r, tr), random_point(r, tr)}), random_obb(r, tr)};
    }
};

template <>
struct obb_case<incidence::obb3, incidence::point3> {
    static std::pair<incidence::obb3, incidence::point3> near(rng& r, bool any_scale = true) {
        const auto [o, p, tr] = near_start(r, any_scale);
        return {moved(tr, o), moved(tr, p)};
    }
    static std::pair<incidence::obb3, incidence::point3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        return {random_obb(r, tr), random_point(r, tr)};
    }
};

template <>
struct obb_case<incidence::obb3, incidence::segment3> {
    static std::pair<incidence::obb3, incidence::segment3> near(rng& r, bool any_scale = true) {
        const auto [o, p, tr] = near_start(r, any_scale);
        const vec3 v = small_vec(r);
        const int k = r.integer(0, 2);
        const point3 s0 = k == 2 ? point3{p.x - v.x, p.y - v.y, p.z - v.z} : p;
        const point3 s1 = k == 1 ? p : point3{p.x + v.x, p.y + v.y, p.z + v.z};
        return {moved(tr, o), segment3{moved(tr, s0), moved(tr, s1)}};
    }
    static std::pair<incidence::obb3, incidence::segment3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        return {random_obb(r, tr), segment3{random_point(r, tr), random_point(r, tr)}};
    }
};

template <>
struct obb_case<incidence::obb3, incidence::ray3> {
    static std::pair<incidence::obb3, incidence::ray3> near(rng& r, bool any_scale = true) {
        const auto [o, p, tr] = near_start(r, any_scale);
        const vec3 v = small_vec(r);
        const bool start_on = r.integer(0, 2) == 0;
        const point3 origin = start_on ? p : point3{p.x + v.x, p.y + v.y, p.z + v.z};
        const vec3 d = start_on ? v : vec3{-v.x, -v.y, -v.z};
        return {moved(tr, o), ray3{moved(tr, origin), moved_dir(tr, d)}};
    }
    static std::pair<incidence::obb3, incidence::ray3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        const vec3 d{tr.scale_only(r.uniform(-1, 1)), tr.scale_only(r.uniform(-1, 1)), tr.scale_only(r.uniform(-1, 1))};
        return {random_obb(r, tr), ray3{random_point(r, tr), d}};
    }
};

template <>
struct obb_case<incidence::line3, incidence::obb3> {
    static std::pair<incidence::line3, incidence::obb3> near(rng& r, bool any_scale = true) {
        const auto [o, p, tr] = near_start(r, any_scale);
        const vec3 v = small_vec(r);
        return {line3{moved(tr, p), moved_dir(tr, v)}, moved(tr, o)};
    }
    static std::pair<incidence::line3, incidence::obb3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        const vec3 d{tr.scale_only(r.uniform(-1, 1)), tr.scale_only(r.uniform(-1, 1)), tr.scale_only(r.uniform(-1, 1))};
        return {line3{random_point(r, tr), d}, random_obb(r, tr)};
    }
};

template <>
struct obb_case<incidence::obb3, incidence::triangle3> {
    static std::pair<incidence::obb3, incidence::triangle3> near(rng& r, bool any_scale = true) {
        const auto [o, p, tr] = near_start(r, any_scale);
        const vec3 v = small_vec(r), w = small_vec(r);
        const bool edge = r.coin(); // p a vertex, or the middle of an edge
        const point3 a = edge ? point3{p.x - v.x, p.y - v.y, p.z - v.z} : p;
        const point3 b{p.x + v.x, p.y + v.y, p.z + v.z}, c{p.x + w.x, p.y + w.y, p.z + w.z};
        return {moved(tr, o), triangle3{moved(tr, a), moved(tr, b), moved(tr, c)}};
    }
    static std::pair<incidence::obb3, incidence::triangle3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        return {random_obb(r, tr), triangle3{random_point(r, tr), random_point(r, tr), random_point(r, tr)}};
    }
};

template <>
struct obb_case<incidence::obb3, incidence::plane3> {
    static std::pair<incidence::obb3, incidence::plane3> near(rng& r, bool any_scale = true) {
        const auto [o, p, tr] = near_start(r, any_scale);
        const vec3 n = small_vec(r);
        const point3 q = moved(tr, p);
        return {moved(tr, o), plane3{n, n.x * q.x + n.y * q.y + n.z * q.z}};
    }
    static std::pair<incidence::obb3, incidence::plane3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        const vec3 n{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
        const point3 q = random_point(r, tr);
        return {random_obb(r, tr), plane3{n, n.x * q.x + n.y * q.y + n.z * q.z}};
    }
};

template <>
struct obb_case<incidence::obb3, incidence::tetrahedron3> {
    static std::pair<incidence::obb3, incidence::tetrahedron3> near(rng& r, bool any_scale = true) {
        const auto [o, p, tr] = near_start(r, any_scale);
        // p at a vertex, an edge or face point, inside or just outside the tetrahedron
        const vec3 e1 = small_vec(r), e2 = small_vec(r);
        vec3 e3 = small_vec(r);
        if (r.integer(0, 11) == 0) e3 = vec3{e1.x + e2.x, e1.y + e2.y, e1.z + e2.z}; // coplanar
        static constexpr double w[][3] = {{0, 0, 0}, {0.5, 0, 0}, {0.25, 0.25, 0}, {0.25, 0.25, 0.25}, {-0.25, 0.5, 0}, {0.5, 0.5, 0.25}};
        const auto& c = w[r.integer(0, 5)];
        const point3 a{p.x - c[0] * e1.x - c[1] * e2.x - c[2] * e3.x, p.y - c[0] * e1.y - c[1] * e2.y - c[2] * e3.y,
                       p.z - c[0] * e1.z - c[1] * e2.z - c[2] * e3.z};
        auto at = [&](vec3 e) { return moved(tr, point3{a.x + e.x, a.y + e.y, a.z + e.z}); };
        return {moved(tr, o), tetrahedron3{moved(tr, a), at(e1), at(e2), at(e3)}};
    }
    static std::pair<incidence::obb3, incidence::tetrahedron3> random(rng& r, bool any_scale = true) {
        const auto tr = random_transform(r, false, any_scale);
        return {random_obb(r, tr), tetrahedron3{random_point(r, tr), random_point(r, tr), random_point(r, tr), random_point(r, tr)}};
    }
};

} // namespace support
