// obb3 against capsule3 (closed box read as the parallelepiped its axes span; the closed capsule,
// the points within |r| of the closed segment ab), and a box corner within a capsule.
// Semantics: the points o + A s, |s_j| <= h_j (A's columns the axes exactly as given, so the box
// may be skew, flat or a point). Touching at a face, an edge or a corner counts.
// Method (exact tiers): the capsule meets the box iff the segment meets it (the caller's
// separating-axis test) or min |q|^2 <= r^2 over q = (a - o) - sum m_j z_j, with the columns
// m_0..m_2 the axes (z_j = s_j in [-h_j, h_j]) and m_3 = a - b (z_3 = t in [0, 1]): a convex
// quadratic program in four coordinates, as ball_obb.cppm's in three. When the segment misses the
// box, q != 0 at a minimiser, so its free coordinates' columns span at most a plane (three
// independent free columns would make q orthogonal to all of space), and moving along the null
// space of dependent free columns keeps q until a coordinate is bound: some minimiser has at most
// two free coordinates with independent columns. Each coordinate at its low bound, its high bound
// or free gives 72 such sets; KKT holds at a set when its free coordinates lie within their bounds
// and every bound coordinate's m_l . q has the bound's side (>= 0 at the high bound, <= 0 at the
// low), and any set where it holds is a minimiser's. With w = (a - o) 1 - sum over bound j of
// m_j z_j (degree 2):
//   none free:        q = w; sign(m_l . w) (degree 3); then r^2 - |w|^2 >= 0 decides (degree 4).
//   m_j free:         lo_j |m_j|^2 <= m_j . w <= hi_j |m_j|^2 (degree 3); for bound l,
//                     |m_j|^2 (m_l . w) - (m_l . m_j)(m_j . w) (degree 5); then
//                     |m_j|^2 (r^2 - |w|^2) + (m_j . w)^2 >= 0 decides (degree 6).
//   m_j, m_k free:    n = m_j x m_k != 0; the free coordinates times |n|^2 by Cramer's rule within
//                     their bounds times |n|^2 (degree 5); sign(n . w) sign(m_l . n) on the bound's
//                     side (degrees 4 and 3); then r^2 |n|^2 - (n . w)^2 >= 0 decides (degree 8).
// Every value is times a lifted 1 where its degree needs it, so each sign is homogeneous. The set
// that plain double names (alternating projections of the segment's point and the box's) is tried
// first, then the others.
// A corner x = o + sum f_j a_j (f_j = +-h_j) within |r| of segment ab: with e = x - a and
// d = b - a, e . d <= 0: |e|^2 <= r^2; e . d >= |d|^2: |x - b|^2 <= r^2; else
// r^2 |d|^2 - (|e|^2 |d|^2 - (e . d)^2) >= 0 (degree 6).
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.4 (closest point on an OBB),
// 5.1.2 (closest point on a segment) and 5.3.3 (segment against box); Boyd and Vandenberghe, Convex
// Optimization (2004), section 5.5.3 (KKT conditions).
// Approximate tier: the same signs in plain double. Error bound: while the signs' terms (degree
// <= 8) stay in double's normal range, that is for inputs and their differences of magnitude in
// [2^-120, 2^120], wrong only when a deciding sign is within 2^-40 of its permanent; beyond it
// plain double underflows or overflows and its answer is anything (tests/query/intersects/
// capsule_obb.cpp counts those with the margin of zero they then have).
module;
#include <array>
#include <type_traits>
export module incidence.detail:engines.capsule_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.ball_obb;

export namespace incidence::detail {

namespace swept_obb {

using ball_obb::agrees;
using ball_obb::corner_less;
// What a set says: whether it is the minimiser's (KKT holds) and then whether the capsule meets.
struct found {
    bool any = false;
    bool meets = false;
};

// Each coordinate: -1 (at its low bound), +1 (at its high bound) or 0 (free).
using active = std::array<int, 4>;

struct frame {
    point3 o, a, b;
    vec3 axis[3];
    double h[3];
    double r;
    [[nodiscard]] constexpr double lo(unsigned j) const { return j < 3 ? -h[j] : 0.0; }
    [[nodiscard]] constexpr double hi(unsigned j) const { return j < 3 ? h[j] : 1.0; }
    [[nodiscard]] constexpr double bound(const active& at, unsigned j) const { return at[j] == 0 ? 0.0 : at[j] > 0 ? hi(j) : lo(j); }
    // m_j as a difference of two points, so that every column has one lifted type
    [[nodiscard]] constexpr point3 plus(unsigned j) const { return j < 3 ? point3{axis[j].x, axis[j].y, axis[j].z} : a; }
    [[nodiscard]] constexpr point3 minus(unsigned j) const { return j < 3 ? point3{0, 0, 0} : b; }
};

template <class L>
[[nodiscard]] constexpr auto column(L l, const frame& f, unsigned j) {
    return arith::lift(l, f.plus(j)) - arith::lift(l, f.minus(j));
}

// w = (a - o) 1 - sum over bound j of m_j z_j.
template <class L>
[[nodiscard]] constexpr auto residual(L l, const frame& f, const active& at) {
    const auto e = arith::lift(l, f.a) - arith::lift(l, f.o);
    return arith::scaled(e, l(1.0)) - arith::scaled(column(l, f, 0), l(f.bound(at, 0))) -
           arith::scaled(column(l, f, 1), l(f.bound(at, 1))) - arith::scaled(column(l, f, 2), l(f.bound(at, 2))) -
           arith::scaled(column(l, f, 3), l(f.bound(at, 3)));
}

[[nodiscard]] constexpr bool zero_column(const frame& f, unsigned j) { return f.plus(j) == f.minus(j); }

template <class K>
[[nodiscard]] constexpr found corner(K& k, const frame& f, const active& at) {
    for (unsigned l = 0; l < 4; ++l)
        if (!agrees(k.sgn([=](auto L) { return arith::dot(column(L, f, l), residual(L, f, at)); }), at[l])) return {};
    const double r = f.r;
    return {true, k.sgn([=](auto L) {
                const auto w = residual(L, f, at);
                const auto one = L(1.0);
                return L(r) * L(r) * (one * one) - arith::dot(w, w);
            }) != sign::negative};
}

template <class K>
[[nodiscard]] constexpr found edge(K& k, const frame& f, const active& at, unsigned j) {
    if (zero_column(f, j)) return {};
    const double lo = f.lo(j), hi = f.hi(j);
    const auto along = [=](auto L) { return arith::dot(column(L, f, j), residual(L, f, at)); };
    const auto mm = [=](auto L) {
        const auto m = column(L, f, j);
        return arith::dot(m, m);
    };
    if (k.sgn([=](auto L) { return L(hi) * mm(L) - along(L); }) == sign::negative) return {};
    if (k.sgn([=](auto L) { return along(L) - L(lo) * mm(L); }) == sign::negative) return {};
    for (unsigned l = 0; l < 4; ++l) {
        if (l == j) continue;
        if (!agrees(k.sgn([=](auto L) {
                const auto M = column(L, f, j), B = column(L, f, l);
                return arith::dot(M, M) * arith::dot(B, residual(L, f, at)) - arith::dot(B, M) * along(L);
            }),
                    at[l]))
            return {};
    }
    const double r = f.r;
    return {true, k.sgn([=](auto L) {
                const auto w = residual(L, f, at);
                const auto one = L(1.0);
                const auto t = along(L);
                return mm(L) * (L(r) * L(r) * (one * one) - arith::dot(w, w)) + t * t;
            }) != sign::negative};
}

template <class K>
[[nodiscard]] constexpr found face(K& k, const frame& f, const active& at, unsigned j, unsigned m) {
    const auto normal = [=](auto L) { return arith::cross(column(L, f, j), column(L, f, m)); };
    const auto nn = [=](auto L) {
        const auto n = normal(L);
        return arith::dot(n, n);
    };
    if (arith::is_zero<arith::hint::often_zero>(k, nn)) return {}; // parallel columns
    const unsigned pairs[2][2] = {{j, m}, {m, j}};
    for (const auto& p : pairs) {
        const unsigned u = p[0], v = p[1];
        const double lo = f.lo(u), hi = f.hi(u);
        const auto coord = [=](auto L) { // z_u |n|^2
            const auto U = column(L, f, u), V = column(L, f, v);
            const auto w = residual(L, f, at);
            return arith::dot(V, V) * arith::dot(U, w) - arith::dot(U, V) * arith::dot(V, w);
        };
        if (k.sgn([=](auto L) { return L(hi) * nn(L) - coord(L); }) == sign::negative) return {};
        if (k.sgn([=](auto L) { return coord(L) - L(lo) * nn(L); }) == sign::negative) return {};
    }
    const sign across = k.sgn([=](auto L) { return arith::dot(normal(L), residual(L, f, at)); });
    if (across != sign::zero) {
        for (unsigned l = 0; l < 4; ++l) {
            if (l == j || l == m) continue;
            const sign turn = k.sgn([=](auto L) { return arith::dot(column(L, f, l), normal(L)); });
            const sign q = turn == sign::zero ? sign::zero : (across == turn ? sign::positive : sign::negative);
            if (!agrees(q, at[l])) return {};
        }
    }
    const double r = f.r;
    return {true, k.sgn([=](auto L) {
                const auto one = L(1.0);
                const auto t = arith::dot(normal(L), residual(L, f, at));
                return L(r) * L(r) * (one * one) * nn(L) - t * t;
            }) != sign::negative};
}

// Is the set `at` (at most two free) the minimiser's, and its verdict?
template <class K>
[[nodiscard]] constexpr found try_set(K& k, const frame& f, const active& at) {
    unsigned free[4], n = 0;
    for (unsigned j = 0; j < 4; ++j)
        if (at[j] == 0) free[n++] = j;
    switch (n) {
    case 0: return corner(k, f, at);
    case 1: return edge(k, f, at, free[0]);
    case 2: return face(k, f, at, free[0], free[1]);
    default: return {};
    }
}

// Plain double's guess: alternating projections between the segment and the box (the axes are
// near orthonormal for a checked box), the last one's bound coordinates, and its squared distance.
struct guess {
    active at{};
    double d2 = 0.0;
};
[[nodiscard]] constexpr guess first_guess(const frame& f) {
    const vec3 d = f.b - f.a;
    const double dd = dot(d, d);
    double t = 0.5, s[3] = {0, 0, 0};
    vec3 q{0, 0, 0};
    for (int it = 0; it < 6; ++it) {
        const vec3 e = (f.a + d * t) - f.o;
        vec3 x{0, 0, 0}; // the box's point, less o
        for (unsigned j = 0; j < 3; ++j) {
            const double aa = dot(f.axis[j], f.axis[j]);
            s[j] = aa > 0.0 ? clamp(dot(f.axis[j], e) / aa, -f.h[j], f.h[j]) : f.h[j];
            x = x + f.axis[j] * s[j];
        }
        t = dd > 0.0 ? clamp(dot((f.o + x) - f.a, d) / dd, 0.0, 1.0) : 0.0;
        q = ((f.a + d * t) - f.o) - x;
    }
    guess g;
    for (unsigned j = 0; j < 3; ++j) g.at[j] = s[j] >= f.h[j] ? 1 : (s[j] <= -f.h[j] ? -1 : 0);
    g.at[3] = t <= 0.0 ? -1 : (t >= 1.0 ? 1 : 0);
    g.d2 = dot(q, q);
    return g;
}

// Does the capsule (segment ab, a != b, radius r >= 0) meet the box, given that the segment misses
// it (finite, extents >= 0: the caller checks)?
template <class K>
[[nodiscard]] constexpr bool meets(K& k, const obb3& box, point3 a, point3 b, double r) {
    const frame f{
        box.center, a, b, {box.axes[0], box.axes[1], box.axes[2]}, {box.half_extents[0], box.half_extents[1], box.half_extents[2]}, r};
    const guess g = first_guess(f);
    if (const found x = try_set(k, f, g.at); x.any) return x.meets;
    for (int code = 0; code < 81; ++code) {
        const active at{code % 3 - 1, code / 3 % 3 - 1, code / 9 % 3 - 1, code / 27 - 1};
        if (at == g.at) continue;
        if (const found x = try_set(k, f, at); x.any) return x.meets;
    }
    // only plain double's signs, within rounding of zero, can refute every set (some set is the
    // minimiser's): the guess's distance then
    if constexpr (std::is_same_v<K, arith::approx_kernel>) return g.d2 <= r * r;
    return false;
}

// Is the box's corner of signed extents f within r of the segment ab?
template <class K>
[[nodiscard]] constexpr bool corner_within(K& k, const obb3& box, const double (&f)[3], point3 a, point3 b, double r) {
    const double g[3] = {f[0], f[1], f[2]};
    const auto near_end = [&](point3 p) {
        return k.sgn([=](auto L) {
            const auto e = corner_less(L, box, g, p);
            const auto one = L(1.0);
            return L(r) * L(r) * (one * one) - arith::dot(e, e);
        }) != sign::negative;
    };
    const auto along = [=](auto L) { return arith::dot(corner_less(L, box, g, a), arith::lift(L, b) - arith::lift(L, a)); };
    const auto dd = [=](auto L) {
        const auto d = arith::lift(L, b) - arith::lift(L, a);
        return arith::dot(d, d);
    };
    if (k.sgn(along) != sign::positive) return near_end(a);
    if (k.sgn([=](auto L) { return along(L) - L(1.0) * dd(L); }) != sign::negative) return near_end(b);
    return k.sgn([=](auto L) {
        const auto e = corner_less(L, box, g, a);
        const auto one = L(1.0);
        const auto t = along(L);
        return L(r) * L(r) * (one * one) * dd(L) - (arith::dot(e, e) * dd(L) - t * t);
    }) != sign::negative;
}

} // namespace swept_obb

} // namespace incidence::detail
