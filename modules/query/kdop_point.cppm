// kdop<K> against point3, contains(kdop, point), and the generalised slab test every k-DOP linear
// pair shares (kdop_segment, kdop_ray, kdop_line).
// Semantics: the closed k-DOP { p : min_i <= d_i . p <= max_i } (shapes/kdop.cppm), possibly
// empty (slabs that never meet together); a slab with min > max, or a non-finite bound, makes it
// no set: every query says no. A point on a face, edge or corner counts.
// Method (exact tiers): the generalised slab method (Kay and Kajiya, SIGGRAPH 1986, for any set
// of slab normals; Klosowski et al., IEEE TVCG 4(1), 1998, for k-DOPs) with its
// comparisons of quotients rewritten as signs of products. The object o + t u (t >= 0 for a ray,
// t in [0, 1] with u = e - o for a segment, every t for a line, u = 0 for a point) lies in slab i
// for t between (N_i - a_i) / b_i and (F_i - a_i) / b_i, where a_i = d_i . o, b_i = d_i . u and
// N_i, F_i are the bounds met first and last; with b_i = 0 the origin must lie in the slab. The
// sets meet iff every near bound is <= every far bound: sign((F_j - a_j) b_i - (N_i - a_i) b_j)
// * sign(b_i) * sign(b_j) >= 0 for every ordered pair of moving slabs, and the far bounds lie at
// t >= 0 (ray, segment) and the near ones at t <= 1 (segment). Each d_i has components in
// {-1, 0, 1}, so d_i . p is a sum of three exactly negated coordinates: every sign is a
// homogeneous polynomial of degree <= 2 in the inputs.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_point.cpp).
module;
#include <array>
export module incidence.query:kdop_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :aabb_ray;

export namespace incidence::pair {

namespace kdopq {

// Every bound finite and every slab non-empty (comparisons only).
[[nodiscard]] constexpr bool well_formed(const double* mn, const double* mx, int m) {
    for (int i = 0; i < m; ++i)
        if (!finite(mn[i]) || !finite(mx[i]) || !(mn[i] <= mx[i])) return false;
    return true;
}
// The three terms of d . p, each exact (d's components are -1, 0 or 1).
struct terms {
    double x, y, z;
};
[[nodiscard]] constexpr terms times(direction3 d, double x, double y, double z) {
    auto t = [](int c, double v) { return c > 0 ? v : (c < 0 ? -v : 0.0); };
    return {t(d.x, x), t(d.y, y), t(d.z, z)};
}
template <class L>
[[nodiscard]] constexpr auto sum(L l, const terms& t) { return l(t.x) + l(t.y) + l(t.z); }

// The generalised slab test for o + t u (X: ray, segment with end point e, or line) against the
// m <= 13 slabs mn[i] <= dirs[i] . x <= mx[i]: one instantiation per kernel for every K.
// Non-finite input and an empty slab: no.
template <slab_extent X, class K>
[[nodiscard]] constexpr bool slabs(K& k, const direction3* dirs, int m, const double* mn, const double* mx, point3 o, vec3 u, point3 e) {
    if (!well_formed(mn, mx, m) || !finite(o) || !finite(u) || !finite(e)) return false;
    constexpr int capacity = 13;
    if (m > capacity) return false;
    std::array<terms, capacity> a{}, mv{}; // d . o, and d . u (ray, line) or d . e (segment)
    std::array<sign, capacity> s{};
    std::array<double, capacity> near{}, far{};
    for (int i = 0; i < m; ++i) {
        const auto ui = static_cast<unsigned>(i);
        const direction3 d = dirs[i];
        const terms A = times(d, o.x, o.y, o.z);
        const terms B = X == slab_extent::segment ? times(d, e.x, e.y, e.z) : times(d, u.x, u.y, u.z);
        a[ui] = A, mv[ui] = B;
        // no movement across the slab when every coordinate d reads stays put (comparisons: a
        // point, a zero direction, an axis-parallel object), else the sign of d . u
        const bool still = X == slab_extent::segment ? (d.x == 0 || e.x == o.x) && (d.y == 0 || e.y == o.y) && (d.z == 0 || e.z == o.z)
                                                     : (d.x == 0 || u.x == 0.0) && (d.y == 0 || u.y == 0.0) && (d.z == 0 || u.z == 0.0);
        if (still) s[ui] = sign::zero;
        else if constexpr (X == slab_extent::segment) s[ui] = k.sgn([=](auto L) { return sum(L, B) - sum(L, A); });
        else s[ui] = k.sgn([=](auto L) { return sum(L, B); });
        near[ui] = s[ui] == sign::negative ? mx[i] : mn[i];
        far[ui] = s[ui] == sign::negative ? mn[i] : mx[i];
        if (s[ui] == sign::zero) { // parallel to the slab: the origin must lie in it
            const double lo = mn[i], hi = mx[i];
            if (k.sgn([=](auto L) { return sum(L, A) - L(lo); }) == sign::negative) return false;
            if (k.sgn([=](auto L) { return L(hi) - sum(L, A); }) == sign::negative) return false;
            continue;
        }
        const double F = far[ui], Nb = near[ui];
        if constexpr (X != slab_extent::line) // (F - a) / b >= 0: the slab is not behind the origin
            if (k.sgn([=](auto L) { return L(F) - sum(L, A); }) == -s[ui]) return false;
        if constexpr (X == slab_extent::segment) // (N - a) / (d.e - a) <= 1: the end point reaches the slab
            if (k.sgn([=](auto L) { return L(Nb) - sum(L, B); }) == s[ui]) return false;
    }
    for (int i = 0; i < m; ++i) {
        const auto ui = static_cast<unsigned>(i);
        if (s[ui] == sign::zero) continue;
        for (int j = 0; j < m; ++j) {
            const auto uj = static_cast<unsigned>(j);
            if (j == i || s[uj] == sign::zero) continue;
            // N_i / b_i <= F_j / b_j (relative to the origin)
            const terms Ai = a[ui], Aj = a[uj], Bi = mv[ui], Bj = mv[uj];
            const double Ni = near[ui], Fj = far[uj];
            sign v;
            if constexpr (X == slab_extent::segment)
                v = k.sgn([=](auto L) {
                    return (L(Fj) - sum(L, Aj)) * (sum(L, Bi) - sum(L, Ai)) - (L(Ni) - sum(L, Ai)) * (sum(L, Bj) - sum(L, Aj));
                });
            else
                v = k.sgn([=](auto L) { return (L(Fj) - sum(L, Aj)) * sum(L, Bi) - (L(Ni) - sum(L, Ai)) * sum(L, Bj); });
            if (v * s[ui] * s[uj] == sign::negative) return false;
        }
    }
    return true;
}
template <slab_extent X, class K, int N>
[[nodiscard]] constexpr bool slabs(K& k, const kdop<N>& b, point3 o, vec3 u, point3 e) {
    const auto dirs = kdop<N>::directions();
    return slabs<X>(k, dirs.data(), N / 2, b.min.data(), b.max.data(), o, u, e);
}

} // namespace kdopq

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const point3& p) {
    return kdopq::slabs<slab_extent::segment>(k, b, p, vec3{0, 0, 0}, p);
}
// contains(kdop, point): the same set.
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const point3& p) { return intersects(k, b, p); }

namespace kdopq {
// Every one of the n points in the k-DOP: a convex shape with those vertices lies inside it.
template <class K, int N>
[[nodiscard]] constexpr bool contains_all(K& k, const kdop<N>& b, const point3* pts, int n) {
    for (int i = 0; i < n; ++i)
        if (!intersects(k, b, pts[i])) return false;
    return true;
}
} // namespace kdopq

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const point3&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const point3&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const point3&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const point3&);
extern template bool contains(arith::exact_kernel&, const kdop<6>&, const point3&);
extern template bool contains(arith::exact_kernel&, const kdop<14>&, const point3&);
extern template bool contains(arith::exact_kernel&, const kdop<18>&, const point3&);
extern template bool contains(arith::exact_kernel&, const kdop<26>&, const point3&);
} // namespace incidence::pair
