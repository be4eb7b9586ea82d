// obb3 against sphere3 (closed box read as the parallelepiped its axes span, closed ball).
// Semantics: the points o + A s, |s_j| <= h_j (A's columns the axes exactly as given, so the box
// may be skew, flat or a point), and |x - c| <= |r| (an unchecked negative radius acts as |r|, as
// in point_sphere). Touching at a face, an edge or a corner counts.
// Method (exact tiers): the ball meets the box iff min over the box of |c - o - A s|^2 <= r^2, a
// convex quadratic program in the box's coordinates s. Its minimiser satisfies KKT with each
// coordinate at -h_j, at +h_j or free (27 cases: the box's 8 corners, 12 edges, 6 faces and its
// inside), and some minimiser has independent free axes (move along A's null space within the free
// coordinates until one is bound), so only those sets are tried. With w = (c - o) 1 - sum over
// bound j of a_j (+-h_j) (degree 2) and q = c - x* the residual:
//   none free (corner): q = w; sign(a_l . w) agrees with the bound's side or is zero (degree 3);
//                       then r^2 - |w|^2 >= 0 decides (degree 4).
//   a_j free (edge):    a_j != 0; |a_j . w| <= h_j |a_j|^2 (degree 3); for bound l,
//                       |a_j|^2 (a_l . w) - (a_l . a_j)(a_j . w) on the bound's side (degree 5);
//                       then |a_j|^2 (r^2 - |w|^2) + (a_j . w)^2 >= 0 decides (degree 6).
//   a_j, a_k free:      n = a_j x a_k != 0; the free coordinates times |n|^2 by Cramer's rule,
//   (face)              |a_k|^2 (a_j . w) - (a_j . a_k)(a_k . w), within h_j |n|^2 (degree 5);
//                       q = (n . w) n / |n|^2, so sign(n . w) sign(a_l . n) on the bound's side;
//                       then r^2 |n|^2 - (n . w)^2 >= 0 decides (degree 8).
//   all free (inside):  det A != 0; |(a_k x a_l) . (c - o)| <= h_j |det A| for each j (degree 4,
//                       as contains(obb3, point3)): yes.
// Every value is times a lifted 1 where its degree needs it, so each sign is homogeneous. A first
// look (first_look below: slabs along the coordinate axes and the box's axes, the box's centre in
// the ball, the box's point of c's clamped coordinates in the ball, a slab along the direction from
// that point to c) settles most pairs before any set is tried. Then the set those coordinates name
// is tried first, then all 27.
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.4 (closest point on an OBB)
// and 5.2.5 (sphere against box); Boyd and Vandenberghe, Convex Optimization (2004), section
// 5.5.3 (KKT conditions).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/intersects/obb_sphere.cpp).
module;
#include <array>
#include <optional>
#include <type_traits>
#include <utility>
export module incidence.detail:engines.ball_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.separating_axes;
import :engines.sphere;

export namespace incidence::detail {

namespace ball_obb {

// Each box coordinate: -1 (at -h_j), +1 (at +h_j) or 0 (free).
using active = std::array<int, 3>;

// What a set says: whether it is the minimiser's (KKT holds).
struct found {
    bool any = false;
};

struct frame {
    point3 o, c;
    vec3 a[3];
    double h[3];
    double r;
};

// (c - o) 1 - sum over j of a_j t_j: c less the box's point of coordinates t (degree 2).
template <class L>
[[nodiscard]] constexpr auto residual_at(L l, const frame& f, double t0, double t1, double t2) {
    const auto e = arith::lift(l, f.c) - arith::lift(l, f.o);
    return arith::scaled(e, l(1.0)) - arith::scaled(arith::lift(l, f.a[0]), l(t0)) - arith::scaled(arith::lift(l, f.a[1]), l(t1)) -
           arith::scaled(arith::lift(l, f.a[2]), l(t2));
}
// w = (c - o) 1 - sum over bound j of a_j (+-h_j): c less the bound coordinates' part of x*.
template <class L>
[[nodiscard]] constexpr auto residual(L l, const frame& f, const active& at) {
    return residual_at(l, f, at[0] * f.h[0], at[1] * f.h[1], at[2] * f.h[2]);
}

// A value's side agrees with the bound's (+1: >= 0, -1: <= 0).
[[nodiscard]] constexpr bool agrees(sign s, int side) { return s == sign::zero || (side > 0) == (s == sign::positive); }

template <class K>
[[nodiscard]] constexpr found corner(K& k, const frame& f, const active& at) {
    for (unsigned l = 0; l < 3; ++l) {
        const vec3 al = f.a[l];
        if (!agrees(k.sgn([=](auto L) { return arith::dot(arith::lift(L, al), residual(L, f, at)); }), at[l])) return {};
    }
    return {true};
}

template <class K>
[[nodiscard]] constexpr found edge(K& k, const frame& f, const active& at, unsigned j) {
    const vec3 aj = f.a[j];
    if (aj.x == 0.0 && aj.y == 0.0 && aj.z == 0.0) return {};
    const double h = f.h[j];
    const auto along = [=](auto L) { return arith::dot(arith::lift(L, aj), residual(L, f, at)); };
    const auto room = [=](auto L) { return L(h) * arith::dot(arith::lift(L, aj), arith::lift(L, aj)); };
    if (k.sgn([=](auto L) { return room(L) - along(L); }) == sign::negative) return {};
    if (k.sgn([=](auto L) { return room(L) + along(L); }) == sign::negative) return {};
    for (unsigned l = 0; l < 3; ++l) {
        if (l == j) continue;
        const vec3 al = f.a[l];
        if (!agrees(k.sgn([=](auto L) {
                const auto A = arith::lift(L, aj), B = arith::lift(L, al);
                return arith::dot(A, A) * arith::dot(B, residual(L, f, at)) - arith::dot(B, A) * along(L);
            }),
                    at[l]))
            return {};
    }
    return {true};
}

template <class K>
[[nodiscard]] constexpr found face(K& k, const frame& f, const active& at, unsigned j, unsigned m, unsigned l) {
    const vec3 aj = f.a[j], am = f.a[m], al = f.a[l];
    const auto normal = [=](auto L) { return arith::cross(arith::lift(L, aj), arith::lift(L, am)); };
    const auto nn = [=](auto L) {
        const auto n = normal(L);
        return arith::dot(n, n);
    };
    if (arith::is_zero<arith::hint::often_zero>(k, nn)) return {}; // parallel axes
    // the free coordinates times |n|^2, against +-h |n|^2
    const vec3 free[2][2] = {{aj, am}, {am, aj}};
    const double hs[2] = {f.h[j], f.h[m]};
    for (unsigned x = 0; x < 2; ++x) {
        const vec3 u = free[x][0], v = free[x][1];
        const double h = hs[x];
        const auto coord = [=](auto L) {
            const auto U = arith::lift(L, u), V = arith::lift(L, v);
            const auto w = residual(L, f, at);
            return arith::dot(V, V) * arith::dot(U, w) - arith::dot(U, V) * arith::dot(V, w);
        };
        if (k.sgn([=](auto L) { return L(h) * nn(L) - coord(L); }) == sign::negative) return {};
        if (k.sgn([=](auto L) { return L(h) * nn(L) + coord(L); }) == sign::negative) return {};
    }
    const sign across = k.sgn([=](auto L) { return arith::dot(normal(L), residual(L, f, at)); });
    if (across != sign::zero) {
        const sign turn = k.sgn([=](auto L) { return arith::dot(arith::lift(L, al), normal(L)); });
        const sign q = turn == sign::zero ? sign::zero : (across == turn ? sign::positive : sign::negative);
        if (!agrees(q, at[l])) return {};
    }
    return {true};
}

// Is c inside the box? (No answer for a flat box: its faces cover it.)
template <class K>
[[nodiscard]] constexpr found inside(K& k, const frame& f) {
    const vec3 a0 = f.a[0], a1 = f.a[1], a2 = f.a[2];
    const auto det = [=](auto L) { return arith::det3(arith::lift(L, a0), arith::lift(L, a1), arith::lift(L, a2)); };
    if (arith::is_zero<arith::hint::often_zero>(k, det)) return {};
    for (unsigned j = 0; j < 3; ++j) {
        const vec3 u = f.a[(j + 1) % 3], v = f.a[(j + 2) % 3];
        const double h = f.h[j];
        if (k.sgn([=](auto L) {
                const auto n = arith::cross(arith::lift(L, u), arith::lift(L, v));
                return L(h) * sat::magnitude(det(L)) - L(1.0) * sat::magnitude(arith::dot(n, arith::lift(L, f.c) - arith::lift(L, f.o)));
            }) == sign::negative)
            return {};
    }
    return {true};
}

// Is the set `at` the minimiser's?
template <class K>
[[nodiscard]] constexpr found try_set(K& k, const frame& f, const active& at) {
    unsigned free[3], n = 0, bound = 0;
    for (unsigned j = 0; j < 3; ++j)
        if (at[j] == 0) free[n++] = j;
        else bound = j;
    switch (n) {
    case 0: return corner(k, f, at);
    case 1: return edge(k, f, at, free[0]);
    case 2: return face(k, f, at, free[0], free[1], bound);
    default: return inside(k, f);
    }
}

// The set plain double names: the centre's coordinates along each axis (the axes are near
// orthonormal for a checked box), clamped; a zero axis is bound.
[[nodiscard]] constexpr active guess(const frame& f) {
    active at{};
    const vec3 e = f.c - f.o;
    for (unsigned j = 0; j < 3; ++j) {
        const double aa = dot(f.a[j], f.a[j]);
        const double s = aa > 0.0 ? dot(f.a[j], e) / aa : 0.0;
        at[j] = !(aa > 0.0) ? 1 : s >= f.h[j] ? 1 : s <= -f.h[j] ? -1 : 0;
    }
    return at;
}

// The squared distance from c to x* under a set that is not the inside (some coordinate bound), as
// g(q) for q(L) -> ratio{P, S} (one type of q per number of free coordinates):
//   corner:  P = |w|^2, S = 1 1;
//   edge j:  P = |a_j|^2 |w|^2 - (a_j . w)^2, S = |a_j|^2 1 1;
//   face jk: P = (n . w)^2, S = |n|^2 1 1, n = a_j x a_k.
template <class G>
constexpr decltype(auto) with_distance(const frame& f, const active& at, G&& g) {
    unsigned free[3], n = 0;
    for (unsigned j = 0; j < 3; ++j)
        if (at[j] == 0) free[n++] = j;
    if (n == 0)
        return g([=](auto L) {
            const auto w = residual(L, f, at);
            const auto one = L(1.0);
            return arith::ratio{arith::dot(w, w), one * one};
        });
    if (n == 1) {
        const vec3 aj = f.a[free[0]];
        return g([=](auto L) {
            const auto A = arith::lift(L, aj);
            const auto w = residual(L, f, at);
            const auto one = L(1.0);
            const auto t = arith::dot(A, w);
            const auto aa = arith::dot(A, A);
            return arith::ratio{aa * arith::dot(w, w) - t * t, aa * (one * one)};
        });
    }
    const vec3 aj = f.a[free[0]], ak = f.a[free[1]];
    return g([=](auto L) {
        const auto nv = arith::cross(arith::lift(L, aj), arith::lift(L, ak));
        const auto t = arith::dot(nv, residual(L, f, at));
        const auto one = L(1.0);
        return arith::ratio{t * t, arith::dot(nv, nv) * (one * one)};
    });
}

// Is the distance under set `at` at most f.r: r^2 S - P >= 0 (degree 4, 6 or 8)? The inside: yes.
template <class K>
[[nodiscard]] constexpr bool within(K& k, const frame& f, const active& at) {
    if (at == active{}) return true;
    const double r = f.r;
    return with_distance(f, at, [&](auto q) {
        return k.sgn([=](auto L) {
            const auto x = q(L);
            return L(r) * L(r) * x.den - x.num;
        }) != sign::negative;
    });
}

// The set of the minimiser: the one plain double names first, then all 27 (`any` false only where
// plain double's signs refute every set, within rounding of zero: the approximate kernel).
template <class K>
[[nodiscard]] constexpr std::pair<bool, active> minimiser(K& k, const frame& f) {
    const active first = guess(f);
    if (try_set(k, f, first).any) return {true, first};
    for (int code = 0; code < 27; ++code) {
        const active at{code % 3 - 1, code / 3 % 3 - 1, code / 9 - 1};
        if (at == first) continue;
        if (try_set(k, f, at).any) return {true, at};
    }
    return {false, first};
}

// The first look, before the box coordinates: five kinds of sign that settle most pairs of a broad
// phase or a culling pass at once, each deciding only where it is proven positive (a value
// returned here; the batch of oriented boxes against one ball, modules/batch/ball_obbs_simd.cpp,
// evaluates the same values in lanes and relies on their form):
//   coordinate axis m: |c_m - o_m| 1 - ((h_0 |a_0m| + h_1 |a_1m|) + h_2 |a_2m|) - |r| 1 > 0: no,
//     since the box lies within o_m +- the sum (degree 2);
//   centre:            r r - |o - c|^2 > 0: yes, the box's centre is in the ball (degree 2);
//   box axis j:        |a_j . (c - o)| 1 - ((h_0 |a_j . a_0| + h_1 |a_j . a_1|) + h_2 |a_j . a_2|)
//                      - |r| ((|a_jx| + |a_jy|) + |a_jz|) 1 > 0: no, since along a_j the box spans
//                      a_j . o +- the h sum and the ball a_j . c +- |r| |a_j| (degree 3).
//   a point of the box: r r (1 1) - |(c - o) 1 - sum a_j t_j|^2 > 0 with |t_j| <= h_j (plain
//                      double's nearest, clamped): yes, that point is in the ball (degree 4).
//   slab along d:      with d = c - o - sum a_j t_j in plain double (that point to c), the gap
//                      g = (d . (c - o)) 1 - ((h_0 |d . a_0| + h_1 |d . a_1|) + h_2 |d . a_2|) > 0
//                      (degree 3) and g g - r r (d . d) (1 1) > 0 (degree 6): no, since along d
//                      the box reaches d . o + the h sum and the ball starts at d . c - |r| |d|.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.2.1 (separating-axis test).
[[nodiscard]] constexpr double component(const vec3& v, unsigned m) { return m == 0 ? v.x : (m == 1 ? v.y : v.z); }
[[nodiscard]] constexpr double component(const point3& p, unsigned m) { return m == 0 ? p.x : (m == 1 ? p.y : p.z); }

template <class L>
[[nodiscard]] constexpr auto look_coordinate(L l, const frame& f, unsigned m) {
    const double h0 = f.h[0], h1 = f.h[1], h2 = f.h[2];
    const auto reach = (l(h0) * l(ball::magnitude(component(f.a[0], m))) + l(h1) * l(ball::magnitude(component(f.a[1], m)))) +
                       l(h2) * l(ball::magnitude(component(f.a[2], m)));
    return sat::magnitude(l(component(f.c, m)) - l(component(f.o, m))) * l(1.0) - reach - l(ball::magnitude(f.r)) * l(1.0);
}
template <class L>
[[nodiscard]] constexpr auto look_centre(L l, const frame& f) {
    const auto g = arith::lift(l, f.o) - arith::lift(l, f.c);
    return l(f.r) * l(f.r) - arith::dot(g, g);
}
template <class L>
[[nodiscard]] constexpr auto look_box_axis(L l, const frame& f, unsigned j) {
    const auto aj = arith::lift(l, f.a[j]);
    const auto reach = (l(f.h[0]) * sat::magnitude(arith::dot(aj, arith::lift(l, f.a[0]))) +
                        l(f.h[1]) * sat::magnitude(arith::dot(aj, arith::lift(l, f.a[1])))) +
                       l(f.h[2]) * sat::magnitude(arith::dot(aj, arith::lift(l, f.a[2])));
    const vec3 a = f.a[j];
    const auto norm1 = (l(ball::magnitude(a.x)) + l(ball::magnitude(a.y))) + l(ball::magnitude(a.z));
    return sat::magnitude(arith::dot(aj, arith::lift(l, f.c) - arith::lift(l, f.o))) * l(1.0) - reach -
           l(ball::magnitude(f.r)) * norm1 * l(1.0);
}

// The box's point nearest c by plain double (c's coordinates along each axis, clamped to +-h_j; 0
// for a zero axis or a NaN): any coordinates within the extents name a point of the box exactly.
[[nodiscard]] constexpr std::array<double, 3> clamped(const frame& f) {
    std::array<double, 3> t{};
    const vec3 e = f.c - f.o;
    for (unsigned j = 0; j < 3; ++j) {
        const double aa = dot(f.a[j], f.a[j]), h = f.h[j];
        const double s = aa > 0.0 ? dot(f.a[j], e) / aa : 0.0;
        t[j] = s >= h ? h : (s <= -h ? -h : (s == s ? s : 0.0));
    }
    return t;
}
template <class L>
[[nodiscard]] constexpr auto look_clamped(L l, const frame& f, const std::array<double, 3>& t) {
    const auto w = residual_at(l, f, t[0], t[1], t[2]);
    return l(f.r) * l(f.r) * (l(1.0) * l(1.0)) - arith::dot(w, w);
}
// The direction from that point to c, in plain double (any direction serves as a slab's).
[[nodiscard]] constexpr vec3 apart_direction(const frame& f, const std::array<double, 3>& t) {
    return f.c - f.o - t[0] * f.a[0] - t[1] * f.a[1] - t[2] * f.a[2];
}
template <class L>
[[nodiscard]] constexpr auto look_apart_gap(L l, const frame& f, const vec3& d) {
    const auto dd = arith::lift(l, d);
    const auto reach = (l(f.h[0]) * sat::magnitude(arith::dot(dd, arith::lift(l, f.a[0]))) +
                        l(f.h[1]) * sat::magnitude(arith::dot(dd, arith::lift(l, f.a[1])))) +
                       l(f.h[2]) * sat::magnitude(arith::dot(dd, arith::lift(l, f.a[2])));
    return arith::dot(dd, arith::lift(l, f.c) - arith::lift(l, f.o)) * l(1.0) - reach;
}
template <class L>
[[nodiscard]] constexpr auto look_apart(L l, const frame& f, const vec3& d) {
    const auto dd = arith::lift(l, d);
    const auto gap = look_apart_gap(l, f, d);
    return gap * gap - l(f.r) * l(f.r) * arith::dot(dd, dd) * (l(1.0) * l(1.0));
}

// The first look's verdict: no, yes, or nothing where no sign of it is proven positive (its signs
// are hint::optional: an unproven one fails no pass).
template <class K>
[[nodiscard]] constexpr std::optional<bool> first_look(K& k, const frame& f) {
    for (unsigned m = 0; m < 3; ++m)
        if (arith::sgn<arith::hint::optional>(k, [=](auto L) { return look_coordinate(L, f, m); }) == sign::positive) return false;
    if (arith::sgn<arith::hint::optional>(k, [=](auto L) { return look_centre(L, f); }) == sign::positive) return true;
    for (unsigned j = 0; j < 3; ++j)
        if (arith::sgn<arith::hint::optional>(k, [=](auto L) { return look_box_axis(L, f, j); }) == sign::positive) return false;
    const std::array<double, 3> t = clamped(f);
    if (arith::sgn<arith::hint::optional>(k, [=](auto L) { return look_clamped(L, f, t); }) == sign::positive) return true;
    const vec3 d = apart_direction(f, t);
    if (arith::sgn<arith::hint::optional>(k, [=](auto L) { return look_apart_gap(L, f, d); }) == sign::positive &&
        arith::sgn<arith::hint::optional>(k, [=](auto L) { return look_apart(L, f, d); }) == sign::positive)
        return false;
    return std::nullopt;
}

// (o - p) 1 + sum f_j a_j: the box's corner of signed extents f, less p (degree 2).
template <class L>
[[nodiscard]] constexpr auto corner_less(L l, const obb3& box, const double (&f)[3], point3 p) {
    const auto e = arith::lift(l, box.center) - arith::lift(l, p);
    return arith::scaled(e, l(1.0)) + arith::scaled(arith::lift(l, box.axes[0]), l(f[0])) +
           arith::scaled(arith::lift(l, box.axes[1]), l(f[1])) + arith::scaled(arith::lift(l, box.axes[2]), l(f[2]));
}

// Does the ball meet the box (finite, extents >= 0: the caller checks)?
template <class K>
[[nodiscard]] constexpr bool meets(K& k, const obb3& b, const sphere3& s) {
    const frame f{
        b.center, s.center, {b.axes[0], b.axes[1], b.axes[2]}, {b.half_extents[0], b.half_extents[1], b.half_extents[2]}, s.radius};
    if (const std::optional<bool> seen = first_look(k, f)) return *seen;
    const auto [any, at] = minimiser(k, f);
    if (any) return within(k, f, at);
    const active first = at;
    // only plain double's signs, within rounding of zero, can refute every set (some set is the
    // minimiser's): the guess's bound coordinates' corner distance then, or yes when it is inside
    if constexpr (std::is_same_v<K, arith::approx_kernel>) {
        if (first == active{}) return true;
        const double r = f.r;
        return k.sgn([=](auto L) {
            const auto w = residual(L, f, first);
            const auto one = L(1.0);
            return L(r) * L(r) * (one * one) - arith::dot(w, w);
        }) != sign::negative;
    }
    return false;
}

} // namespace ball_obb

// The classic test, an alternative to obb_sphere (method::obb_sphere_closest_point): the box's point
// nearest the centre by clamping the centre's coordinates along each axis (exact for orthonormal
// axes only), then |q - c|^2 <= r^2, in plain double.
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.4 (ClosestPtPointOBB) and
// 5.2.5 (TestSphereOBB).
[[nodiscard]] constexpr bool obb_sphere_closest_point(const obb3& b, const sphere3& s) {
    const vec3 d = s.center - b.center;
    vec3 q{0, 0, 0}; // the nearest point, less the centre
    for (unsigned i = 0; i < 3; ++i) {
        const double h = b.half_extents[i];
        double t = dot(d, b.axes[i]);
        t = t > h ? h : (t < -h ? -h : t);
        q = q + b.axes[i] * t;
    }
    const vec3 v = d - q;
    return dot(v, v) <= s.radius * s.radius;
}

} // namespace incidence::detail
