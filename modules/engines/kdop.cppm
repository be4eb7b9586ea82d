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
//
// kdop<A> against kdop<B> for any A, B in {6, 14, 18, 26}, and the exact emptiness test of a set of
// k-DOP slabs that aabb_kdop shares.
// Semantics: closed k-DOPs (possibly empty; an empty slab or a non-finite bound: no set, so no);
// touching at a face, an edge or a corner counts.
// Method (exact tiers): the two meet iff the slabs of both have a common point. The directions of
// A and B together are always those of one of the four k-DOPs (U); per direction of U the larger
// lower and the smaller upper bound (comparisons). Slab overlap, the classic k-DOP test
// (Klosowski et al., IEEE TVCG 4(1), 1998, section 5), is the first step, but it is not enough:
// two k-DOPs can overlap in every slab and be disjoint. The rest is Farkas' lemma (Schrijver,
// Theory of Linear and Integer Programming, 1986, section 7.3): half-spaces n_h . x <= r_h have a
// common point iff sum_h m_h r_h >= 0 for every minimal m >= 0 with sum_h m_h n_h = 0 (the positive
// circuits of the normals; in 3D at most four half-spaces each). The normals are the fixed +-d_i,
// so their circuits are computed at compile time: 3 for the 6-DOP (slab overlap is exact there),
// 41 for 14, 119 for 18, 777 for 26, with integer multipliers of at most 4. Each certificate is
// the sign of sum_t m_t r_t over at most four bounds, the multipliers lifted as inputs: a
// homogeneous polynomial of degree 2. Before them, a double point shown strictly inside every
// slab (degree-1 signs) settles most meeting pairs.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_kdop.cpp).
//
// aabb3 against kdop<K>, and contains(kdop, aabb | segment).
// Semantics: the closed box and the closed k-DOP (possibly empty; an empty slab, an inverted box
// or a non-finite bound: no set, so no); touching at a face, an edge or a corner counts.
// Method (exact tiers): the box is the 6-DOP of its bounds, so the pair is kdop_kdop's exact
// emptiness test of the slabs of both (slab overlap, then Farkas certificates of degree 2).
// Contains: a convex shape lies in the k-DOP iff its vertices do (the slab test per vertex).
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 5; Schrijver, Theory of Linear and
// Integer Programming, 1986, section 7.3.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_kdop.cpp).
//
// kdop<K> against plane3.
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set, so no; slabs that are
// jointly empty: the empty set) and the plane n . x = offset (a zero normal is everything when the
// offset is 0 and nothing otherwise). Touching at a corner, an edge or a face counts.
// Method (exact tiers): the k-DOP is its K half-spaces d_i . x <= max_i and -d_i . x <= -min_i
// (integer directions: exact), so the pair is convex_polyhedron_plane's test: the k-DOP's vertices
// least and greatest along n proven on either side of the plane (or a Farkas certificate that
// nothing lies beyond), else a feasibility test of each side: signs of degree <= 5.
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 4 (the directions); Schrijver, Theory
// of Linear and Integer Programming, 1986, sections 7.3 and 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_plane.cpp).
module;
#include <array>
export module incidence.detail:engines.kdop;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.box;
import :engines.halfspace_lp;

export namespace incidence::detail {

namespace kdop_slabs {

// Every bound finite and every slab non-empty (comparisons only).
[[nodiscard]] constexpr bool well_formed(const double* mn, const double* mx, int m) {
    for (int i = 0; i < m; ++i)
        if (!finite(mn[i]) || !finite(mx[i]) || !(mn[i] <= mx[i])) return false;
    return true;
}
template <int N>
[[nodiscard]] constexpr bool well_formed(const kdop<N>& b) {
    return well_formed(b.min.data(), b.max.data(), N / 2);
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
[[nodiscard]] constexpr auto sum(L l, const terms& t) {
    return l(t.x) + l(t.y) + l(t.z);
}

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
            else v = k.sgn([=](auto L) { return (L(Fj) - sum(L, Aj)) * sum(L, Bi) - (L(Ni) - sum(L, Ai)) * sum(L, Bj); });
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

} // namespace kdop_slabs

namespace kdop_slabs {

// One certificate: sum_t mult[t] * (upper[t] ? max[slab[t]] : -min[slab[t]]) >= 0.
struct circuit {
    int n = 0;
    std::array<int, 4> slab{}, mult{};
    std::array<bool, 4> upper{};
};

struct ivec {
    long long x, y, z;
};
[[nodiscard]] constexpr ivec to_ivec(direction3 d) { return {d.x, d.y, d.z}; }
[[nodiscard]] constexpr ivec icross(ivec a, ivec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
[[nodiscard]] constexpr long long idot(ivec a, ivec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
[[nodiscard]] constexpr long long idet(ivec a, ivec b, ivec c) { return idot(a, icross(b, c)); }
[[nodiscard]] constexpr long long iabs(long long v) { return v < 0 ? -v : v; }
[[nodiscard]] constexpr long long igcd(long long a, long long b) { return b == 0 ? a : igcd(b, a % b); }

// Calls emit(circuit) for every positive circuit of the normals +-d_i of kdop<K>: first the m
// pairs {d_i, -d_i} (slab overlap), then the circuits of three coplanar and of four directions.
// sum_j v_j d_j = 0 with every v_j != 0 gives two circuits, signs s_j = sign(v_j) and the opposite.
template <int K, class F>
constexpr void for_each_circuit(F emit) {
    constexpr int m = K / 2;
    const auto d = kdop<K>::directions();
    auto signed_pair = [&](const int* idx, const long long* v, int n) {
        long long g = 0;
        for (int t = 0; t < n; ++t) {
            if (v[t] == 0) return; // not minimal: a smaller circuit covers it
            g = igcd(g, iabs(v[t]));
        }
        for (int s = 1; s >= -1; s -= 2) {
            circuit c;
            c.n = n;
            for (int t = 0; t < n; ++t) {
                const auto u = static_cast<unsigned>(t);
                c.slab[u] = idx[t];
                c.mult[u] = static_cast<int>(iabs(v[t]) / g);
                c.upper[u] = (v[t] > 0) == (s > 0);
            }
            emit(c);
        }
    };
    for (int i = 0; i < m; ++i) {
        circuit c;
        c.n = 2;
        c.slab = {i, i, 0, 0};
        c.mult = {1, 1, 0, 0};
        c.upper = {true, false, false, false};
        emit(c);
    }
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            for (int l = j + 1; l < m; ++l) {
                const ivec a = to_ivec(d[static_cast<unsigned>(i)]), b = to_ivec(d[static_cast<unsigned>(j)]),
                           c = to_ivec(d[static_cast<unsigned>(l)]);
                if (idet(a, b, c) != 0) continue;
                const ivec nrm = icross(a, b); // the directions are pairwise independent
                const long long v[3] = {idot(nrm, icross(b, c)), idot(nrm, icross(c, a)), idot(nrm, icross(a, b))};
                const int idx[3] = {i, j, l};
                signed_pair(idx, v, 3);
            }
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            for (int l = j + 1; l < m; ++l)
                for (int q = l + 1; q < m; ++q) {
                    const ivec a = to_ivec(d[static_cast<unsigned>(i)]), b = to_ivec(d[static_cast<unsigned>(j)]),
                               c = to_ivec(d[static_cast<unsigned>(l)]), e = to_ivec(d[static_cast<unsigned>(q)]);
                    // sum_j (-1)^j det(the other three) a_j = 0
                    const long long v[4] = {idet(b, c, e), -idet(a, c, e), idet(a, b, e), -idet(a, b, c)};
                    const int idx[4] = {i, j, l, q};
                    signed_pair(idx, v, 4);
                }
}
template <int K>
[[nodiscard]] consteval int circuit_count() {
    int n = 0;
    for_each_circuit<K>([&](const circuit&) { ++n; });
    return n;
}
template <int K>
[[nodiscard]] consteval std::array<circuit, static_cast<unsigned>(circuit_count<K>())> make_circuits() {
    std::array<circuit, static_cast<unsigned>(circuit_count<K>())> out{};
    unsigned n = 0;
    for_each_circuit<K>([&](const circuit& c) { out[n++] = c; });
    return out;
}
template <int K>
inline constexpr auto circuits = make_circuits<K>();
// Evaluated once here for the four k-DOPs, so a user's translation unit never re-evaluates them
// (and may use a lower -fconstexpr-steps limit than these tables need).
template <>
inline constexpr auto circuits<6> = make_circuits<6>();
template <>
inline constexpr auto circuits<14> = make_circuits<14>();
template <>
inline constexpr auto circuits<18> = make_circuits<18>();
template <>
inline constexpr auto circuits<26> = make_circuits<26>();

// A candidate common point in double: the centre of the axis slabs, moved for a few rounds to the
// middle of each slab it is not strictly inside (alternating projections, Bregman 1965). Only a
// guess: the caller checks it with signs.
template <int K>
[[nodiscard]] constexpr point3 witness_guess(const std::array<double, K / 2>& mn, const std::array<double, K / 2>& mx) {
    const auto d = kdop<K>::directions();
    double p[3] = {mn[0] / 2 + mx[0] / 2, mn[1] / 2 + mx[1] / 2, mn[2] / 2 + mx[2] / 2};
    for (int round = 0; round < 8; ++round) {
        bool moved = false;
        for (unsigned i = 3; i < d.size(); ++i) {
            const double v = d[i].x * p[0] + d[i].y * p[1] + d[i].z * p[2];
            if (v > mn[i] && v < mx[i]) continue;
            const double step = (mn[i] / 2 + mx[i] / 2 - v) / (d[i].x * d[i].x + d[i].y * d[i].y + d[i].z * d[i].z);
            p[0] += d[i].x * step, p[1] += d[i].y * step, p[2] += d[i].z * step;
            moved = true;
        }
        for (unsigned a = 0; a < 3; ++a)
            if (!(p[a] > mn[a] && p[a] < mx[a])) p[a] = mn[a] / 2 + mx[a] / 2, moved = true;
        if (!moved) break;
    }
    return {p[0], p[1], p[2]};
}
// p lies strictly inside every slab, by probed signs (a failure only means "not shown").
template <int K, class Kern>
[[nodiscard]] constexpr bool strictly_inside(Kern& k, const std::array<double, K / 2>& mn, const std::array<double, K / 2>& mx, point3 p) {
    if (!finite(p)) return false;
    const auto d = kdop<K>::directions();
    for (unsigned i = 0; i < d.size(); ++i) {
        const terms t = times(d[i], p.x, p.y, p.z);
        const double lo = mn[i], hi = mx[i];
        if (arith::sgn<arith::hint::optional>(k, [=](auto L) { return sum(L, t) - L(lo); }) != sign::positive) return false;
        if (arith::sgn<arith::hint::optional>(k, [=](auto L) { return L(hi) - sum(L, t); }) != sign::positive) return false;
    }
    return true;
}

// The slabs mn[i] <= d_i . x <= mx[i] of kdop<K> (finite bounds) have a common point. First slab
// overlap; then a witness, a double point strictly inside every slab (most meeting pairs have a
// common interior), settles yes; else the certificates decide.
template <int K, class Kern>
[[nodiscard]] constexpr bool nonempty(Kern& k, const std::array<double, K / 2>& mn, const std::array<double, K / 2>& mx) {
    for (int i = 0; i < K / 2; ++i) // slab overlap: the circuits {d_i, -d_i}
        if (arith::compare(k, mn[static_cast<unsigned>(i)], mx[static_cast<unsigned>(i)]) == sign::positive) return false;
    if (strictly_inside<K>(k, mn, mx, witness_guess<K>(mn, mx))) return true;
    for (unsigned c = K / 2; c < circuits<K>.size(); ++c) {
        const circuit& ci = circuits<K>[c];
        std::array<double, 4> m{}, r{};
        for (unsigned t = 0; t < static_cast<unsigned>(ci.n); ++t) {
            const auto s = static_cast<unsigned>(ci.slab[t]);
            m[t] = static_cast<double>(ci.mult[t]);
            r[t] = ci.upper[t] ? mx[s] : -mn[s];
        }
        if (k.sgn([=](auto L) { return (L(m[0]) * L(r[0]) + L(m[1]) * L(r[1])) + (L(m[2]) * L(r[2]) + L(m[3]) * L(r[3])); }) ==
            sign::negative)
            return false;
    }
    return true;
}

// The directions of kdop<A> and kdop<B> together: those of kdop<union_k<A, B>>.
template <int A, int B>
inline constexpr int union_k = A == B ? A : (A == 6 ? B : (B == 6 ? A : 26));

// Narrows the bounds lo, hi of kdop<U> (set[j]: bounded yet) by those of a, a k-DOP whose
// directions are among U's.
template <int U, int A, class Kern>
constexpr void narrow(Kern& k, const kdop<A>& a, std::array<double, U / 2>& lo, std::array<double, U / 2>& hi,
                      std::array<bool, U / 2>& set) {
    const auto da = kdop<A>::directions();
    const auto du = kdop<U>::directions();
    for (unsigned i = 0; i < da.size(); ++i) {
        unsigned j = 0;
        while (du[j].x != da[i].x || du[j].y != da[i].y || du[j].z != da[i].z) ++j;
        if (!set[j] || arith::compare(k, a.min[i], lo[j]) == sign::positive) lo[j] = a.min[i];
        if (!set[j] || arith::compare(k, a.max[i], hi[j]) == sign::negative) hi[j] = a.max[i];
        set[j] = true;
    }
}

template <class Kern, int A, int B>
[[nodiscard]] constexpr bool meet(Kern& k, const kdop<A>& a, const kdop<B>& b) {
    if (!well_formed(a.min.data(), a.max.data(), A / 2) || !well_formed(b.min.data(), b.max.data(), B / 2)) return false;
    constexpr int U = union_k<A, B>;
    std::array<double, U / 2> lo{}, hi{};
    std::array<bool, U / 2> set{};
    narrow<U>(k, a, lo, hi, set);
    narrow<U>(k, b, lo, hi, set);
    return nonempty<U>(k, lo, hi);
}

} // namespace kdop_slabs

namespace kdop_slabs {
[[nodiscard]] constexpr kdop<6> as_kdop(const aabb3& b) { return kdop<6>{{b.min.x, b.min.y, b.min.z}, {b.max.x, b.max.y, b.max.z}}; }
} // namespace kdop_slabs

namespace kdop_slabs {
// The k-DOP's K half-spaces d_i . x <= max_i and -d_i . x <= -min_i (integer directions: exact).
template <int N>
[[nodiscard]] constexpr std::array<plane3, N> halfspaces(const kdop<N>& b) {
    const auto d = kdop<N>::directions();
    std::array<plane3, N> rows{};
    for (unsigned i = 0; i < N / 2; ++i) {
        const vec3 n{double(d[i].x), double(d[i].y), double(d[i].z)};
        rows[2 * i] = plane3{n, b.max[i]};
        rows[2 * i + 1] = plane3{-n, -b.min[i]};
    }
    return rows;
}
} // namespace kdop_slabs

} // namespace incidence::detail
