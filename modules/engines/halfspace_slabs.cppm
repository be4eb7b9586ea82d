// convex_polyhedron3 against point3, contains(convex_polyhedron3, point3), and the generalised
// slab test every half-space pair shares (convex_polyhedron_segment, _ray, _line, and the frustum
// pairs, whose six planes are one such set).
// Semantics: the closed set { p : n_i . p <= c_i } (shapes/convex_polyhedron3.cppm), possibly
// empty or unbounded; a non-finite number or a count outside [0, capacity] makes no set: every
// query says no. A point on a face, an edge or a vertex counts.
// Method (exact tiers): the generalised slab method (Kay and Kajiya, SIGGRAPH 1986; Cyrus and
// Beck, Computers & Graphics 3(1), 1978, for clipping against any convex polyhedron) with its
// comparisons of quotients rewritten as signs of products. The object o + t u (t >= 0 for a ray,
// t in [0, 1] with u = e - o for a segment, every t for a line, u = 0 for a point) lies in
// half-space i for t <= (c_i - a_i) / b_i when b_i > 0 and t >= (c_i - a_i) / b_i when b_i < 0,
// where a_i = n_i . o, b_i = n_i . u; with b_i = 0 the origin must lie in it (a_i <= c_i). The
// sets meet iff the largest lower bound is <= the smallest upper bound, both found in one pass by
// sign((c_i - a_i) b_j - (c_j - a_j) b_i) (t_i - t_j times b_i b_j), and the upper bounds lie at
// t >= 0 (ray, segment: c_j - a_j >= 0) and the lower ones at t <= 1 (segment:
// c_i - n_i . e >= 0). Every sign is a polynomial of degree <= 4 in the inputs, no quotient is
// rounded; each offset is multiplied by a lifted 1 so every polynomial is homogeneous (degree 2
// or 4), which lets the exact fallback use expansions instead of big integers.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_point.cpp).
module;
#include <optional>
#include <type_traits>
export module incidence.detail:engines.halfspace_slabs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.box;

export namespace incidence::detail {

namespace halfspaces {

// Every plane finite (a zero normal is a half-space too: all of space or nothing).
[[nodiscard]] constexpr bool well_formed(const plane3* planes, int m, int capacity) {
    if (m < 0 || m > capacity) return false;
    for (int i = 0; i < m; ++i)
        if (!finite(planes[i].normal) || !finite(planes[i].offset)) return false;
    return true;
}

// The sign of (c_i - a_i) b_j - (c_j - a_j) b_i, with a = n . o and b = n . u (b = n . (e - o) for
// a segment): t_i - t_j times b_i b_j, where t = (c - a) / b is where o + t u crosses the plane.
template <slab_extent X, class K>
[[nodiscard, gnu::always_inline]] constexpr sign bound_order(K& k, const plane3& pi, const plane3& pj, point3 o, vec3 u, point3 e) {
    return k.sgn([=](auto L) {
        const auto O = arith::lift(L, o);
        const auto ni = arith::lift(L, pi.normal), nj = arith::lift(L, pj.normal);
        const auto U = [&] {
            if constexpr (X == slab_extent::segment) return arith::lift(L, e) - O;
            else return arith::lift(L, u);
        }();
        const auto one = L(1.0);
        return (L(pi.offset) * one - arith::dot(ni, O)) * arith::dot(nj, U) - (L(pj.offset) * one - arith::dot(nj, O)) * arith::dot(ni, U);
    });
}

// Whether no coordinate a normal reads moves: a point, a zero direction, a zero normal, an
// axis-parallel object (comparisons only; b_i is then exactly zero).
template <slab_extent X>
[[nodiscard, gnu::always_inline]] constexpr bool still(vec3 n, point3 o, vec3 u, point3 e) {
    if constexpr (X == slab_extent::segment) return (n.x == 0.0 || e.x == o.x) && (n.y == 0.0 || e.y == o.y) && (n.z == 0.0 || e.z == o.z);
    else return (n.x == 0.0 || u.x == 0.0) && (n.y == 0.0 || u.y == 0.0) && (n.z == 0.0 || u.z == 0.0);
}

// The slab test below with a_i, b_i and c_i - n_i . e computed once per plane and kept for the
// tightest bounds instead of once per sign: the same signs, in the same order, each read by
// read_sign. Lift = arith::lift_double: the approximate tier, each sign that of the double.
// Lift = arith::lift_filter: the rounded stage of a filter pass at run time
// (arith::rounded_stage_applies), each sign proven by the filter's own bound (arith::filtered)
// or the whole stage undecided: yes they meet, no they are apart, uncertain some sign is too
// close to call. read_sign: nothing where the sign is not proven.
template <class Lift>
[[nodiscard, gnu::always_inline]] constexpr std::optional<sign> read_sign(const auto& v) {
    if constexpr (std::is_same_v<Lift, arith::lift_double>) return arith::sign_of_double(v);
    else if (const int s = arith::proven_sign(v); s != 0) return arith::to_sign(s);
    else return std::nullopt;
}
template <slab_extent X, class Lift>
[[nodiscard]] constexpr certainty stored_halfspaces(const plane3* planes, int m, point3 o, vec3 u, point3 e) {
    const Lift L{};
    const auto O = arith::lift(L, o);
    const auto U = [&] {
        if constexpr (X == slab_extent::segment) return arith::lift(L, e) - O;
        else return arith::lift(L, u);
    }();
    const auto one = L(1.0);
    using A = decltype(L(0.0) * one - arith::dot(arith::lift(L, vec3{}), O));
    using B = decltype(arith::dot(arith::lift(L, vec3{}), U));
    A a_lower{}, a_upper{}; // c - n . o of the tightest lower and upper bound so far
    B b_lower{}, b_upper{}; // n . u of the same
    bool lower = false, upper = false;
    for (int i = 0; i < m; ++i) {
        const vec3 n = planes[i].normal;
        const auto N = arith::lift(L, n);
        const A a = L(planes[i].offset) * one - arith::dot(N, O);
        const B b = arith::dot(N, U);
        const std::optional<sign> sb = still<X>(n, o, u, e) ? sign::zero : read_sign<Lift>(b);
        if (!sb) return certainty::uncertain;
        const sign s = *sb;
        if (s == sign::zero || (X != slab_extent::line && s == sign::positive)) { // parallel, or an upper bound at t >= 0
            const auto t = read_sign<Lift>(a);
            if (!t) return certainty::uncertain;
            if (*t == sign::negative) return certainty::no;
            if (s == sign::zero) continue;
        }
        if constexpr (X == slab_extent::segment)
            if (s == sign::negative) { // a lower bound at t <= 1
                const auto t = read_sign<Lift>(L(planes[i].offset) * one - arith::dot(N, arith::lift(L, e)));
                if (!t) return certainty::uncertain;
                if (*t == sign::negative) return certainty::no;
            }
        if (s == sign::negative) {
            if (lower) {
                const auto t = read_sign<Lift>(a * b_lower - a_lower * b); // t_i - t_lower, times b_i b_lower > 0
                if (!t) return certainty::uncertain;
                if (*t != sign::positive) continue;
            }
            a_lower = a, b_lower = b, lower = true;
        } else {
            if (upper) {
                const auto t = read_sign<Lift>(a * b_upper - a_upper * b); // t_i - t_upper, times b_i b_upper > 0
                if (!t) return certainty::uncertain;
                if (*t != sign::negative) continue;
            }
            a_upper = a, b_upper = b, upper = true;
        }
    }
    if (!lower || !upper) return certainty::yes;
    const auto t = read_sign<Lift>(a_lower * b_upper - a_upper * b_lower); // (t_lower - t_upper) b_lower b_upper
    if (!t) return certainty::uncertain;
    return *t != sign::negative ? certainty::yes : certainty::no;
}

// The generalised slab test for o + t u (X: ray, segment with end point e, or line) against the
// m <= capacity half-spaces n_i . x <= c_i: one instantiation per kernel and extent. One pass:
// every plane's own checks, and the tightest lower and upper bound so far (a lower bound i is
// tighter than lower bound j when t_i > t_j, an upper one when t_i < t_j); the sets meet iff the
// tightest lower bound is <= the tightest upper one. The approximate tier and the rounded stage
// of a filter pass keep the per-plane values (stored_halfspaces).
template <slab_extent X, class K>
[[nodiscard]] constexpr bool halfspaces(K& k, const plane3* planes, int m, point3 o, vec3 u, point3 e) {
    constexpr int capacity = convex_polyhedron3::capacity;
    if (!well_formed(planes, m, capacity) || !finite(o) || !finite(u) || !finite(e)) return false;
    if constexpr (std::is_same_v<K, arith::approx_kernel>)
        return stored_halfspaces<X, arith::lift_double>(planes, m, o, u, e) == certainty::yes;
    // not for a point (e = o): one sign per plane, nothing to keep
    if (arith::rounded_stage_applies<K>() && !(X == slab_extent::segment && o == e))
        if (const certainty r = stored_halfspaces<X, arith::lift_filter>(planes, m, o, u, e); r != certainty::uncertain)
            return r == certainty::yes;
    int lower = -1, upper = -1; // the tightest lower and upper bound so far
    for (int i = 0; i < m; ++i) {
        const vec3 n = planes[i].normal;
        const double c = planes[i].offset;
        sign s = sign::zero; // the sign of b_i: which bound half-space i gives
        if (!still<X>(n, o, u, e)) {
            if constexpr (X == slab_extent::segment)
                s = k.sgn([=](auto L) { return arith::dot(arith::lift(L, n), arith::lift(L, e) - arith::lift(L, o)); });
            else s = k.sgn([=](auto L) { return arith::dot(arith::lift(L, n), arith::lift(L, u)); });
        }
        // c - n . o: the origin's side (needed when parallel, or for an upper bound at t >= 0)
        auto inside_at_origin = [&] {
            return k.sgn([=](auto L) { return L(c) * L(1.0) - arith::dot(arith::lift(L, n), arith::lift(L, o)); });
        };
        if (s == sign::zero) {
            if (inside_at_origin() == sign::negative) return false;
            continue;
        }
        if constexpr (X != slab_extent::line) // an upper bound (c - a) / b >= 0: the half-space is not behind the origin
            if (s == sign::positive && inside_at_origin() == sign::negative) return false;
        if constexpr (X == slab_extent::segment) // a lower bound (c - a) / b <= 1: the end point lies in the half-space
            if (s == sign::negative &&
                k.sgn([=](auto L) { return L(c) * L(1.0) - arith::dot(arith::lift(L, n), arith::lift(L, e)); }) == sign::negative)
                return false;
        if (s == sign::negative) {
            if (lower < 0 || bound_order<X>(k, planes[i], planes[lower], o, u, e) == sign::positive) lower = i;
        } else if (upper < 0 || bound_order<X>(k, planes[i], planes[upper], o, u, e) == sign::negative) upper = i;
    }
    // the tightest lower bound <= the tightest upper one: (t_lower - t_upper) b_lower b_upper >= 0
    return lower < 0 || upper < 0 || bound_order<X>(k, planes[lower], planes[upper], o, u, e) != sign::negative;
}
template <slab_extent X, class K>
[[nodiscard]] constexpr bool halfspaces(K& k, const convex_polyhedron3& c, point3 o, vec3 u, point3 e) {
    return halfspaces<X>(k, c.planes.data(), c.count, o, u, e);
}

} // namespace halfspaces

} // namespace incidence::detail
