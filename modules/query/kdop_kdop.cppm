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
module;
#include <array>
export module incidence.query:kdop_kdop;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :kdop_point;

export namespace incidence::pair {

namespace kdopq {

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
                const ivec a = to_ivec(d[static_cast<unsigned>(i)]), b = to_ivec(d[static_cast<unsigned>(j)]), c = to_ivec(d[static_cast<unsigned>(l)]);
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
        if (arith::probe(k, [=](auto L) { return sum(L, t) - L(lo); }) != sign::positive) return false;
        if (arith::probe(k, [=](auto L) { return L(hi) - sum(L, t); }) != sign::positive) return false;
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
constexpr void narrow(Kern& k, const kdop<A>& a, std::array<double, U / 2>& lo, std::array<double, U / 2>& hi, std::array<bool, U / 2>& set) {
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

} // namespace kdopq

template <class K, int A, int B>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<A>& a, const kdop<B>& b) {
    return kdopq::meet(k, a, b);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const kdop<6>&);
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const kdop<14>&);
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const kdop<18>&);
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const kdop<26>&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const kdop<6>&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const kdop<14>&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const kdop<18>&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const kdop<26>&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const kdop<6>&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const kdop<14>&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const kdop<18>&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const kdop<26>&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const kdop<6>&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const kdop<14>&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const kdop<18>&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const kdop<26>&);
} // namespace incidence::pair
