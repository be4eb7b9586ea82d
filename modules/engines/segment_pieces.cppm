// A segment a + t (b - a), 0 <= t <= 1, split at exact rational parameters (breakpoints), and one
// point of each open piece between two consecutive ones: what contains(mesh, segment) and
// contains(polygon, segment) share. A breakpoint is any value whose kernel-generic fraction(L, p)
// gives {N, D} with D > 0 (the caller negates both where needed); two are ordered by the sign of
// N1 D2 - N2 D1. A piece's point is a + t (b - a) for a double t proven strictly between its two
// ends (t D - N against each, by hint::optional: a failure only sends the piece to the exact point),
// or else the exact midpoint t = (N1 D2 + N2 D1) / (2 D1 D2).
// Source: the segment classification by its crossings with a boundary, as in point-in-polyhedron
// segment tests (O'Rourke, Computational Geometry in C, 2nd ed., 7.5); the breakpoints compared as
// signs of products, never as rounded quotients.
module;
#include <cstddef>
#include <utility>
#include <vector>
export module incidence.detail:engines.segment_pieces;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::detail::pieces {

// Sorts v by less(x, y) (a merge sort: an inconsistent order from an inexact kernel leaves v
// unsorted, never reads out of range).
template <class T, class Less>
constexpr void merge_sort(std::vector<T>& v, const Less& less) {
    if (v.size() < 2) return; // (no scratch allocation for what is already sorted)
    std::vector<T> tmp(v.size());
    for (std::size_t w = 1; w < v.size(); w *= 2) {
        for (std::size_t lo = 0; lo < v.size(); lo += 2 * w) {
            const std::size_t mid = lo + w < v.size() ? lo + w : v.size(), hi = lo + 2 * w < v.size() ? lo + 2 * w : v.size();
            std::size_t i = lo, j = mid, o = lo;
            while (i < mid && j < hi) tmp[o++] = less(v[j], v[i]) ? v[j++] : v[i++];
            while (i < mid) tmp[o++] = v[i++];
            while (j < hi) tmp[o++] = v[j++];
        }
        v.swap(tmp);
    }
}

// Is the breakpoint p strictly inside (0, 1)? (D > 0: N > 0 and D - N > 0.)
template <class K, class Frac, class P>
[[nodiscard]] constexpr bool inside_unit(K& k, const Frac& fraction, const P& p) {
    return k.sgn([=](auto L) { return fraction(L, p).first; }) == sign::positive && k.sgn([=](auto L) {
        const auto [n, d] = fraction(L, p);
        return d - n;
    }) == sign::positive;
}

// Adds the parameter p to `params` (made D > 0 by its `flip`) when it lies strictly inside (0, 1);
// false when its D is zero (no parameter: the line is parallel to what defined it).
template <class K, class Frac, class P>
[[nodiscard]] constexpr bool keep(K& k, const Frac& fraction, P p, std::vector<P>& params) {
    p.flip = false;
    const sign d = k.sgn([=](auto L) { return fraction(L, p).second; });
    if (d == sign::zero) return false;
    p.flip = d == sign::negative;
    if (inside_unit(k, fraction, p)) params.push_back(p);
    return true;
}

// Sorts `params` (breakpoints strictly inside (0, 1)) and calls at_double(t) or at_midpoint(lo,
// hi) for one point of every open piece between start (t = 0), the breakpoints and end (t = 1);
// false as soon as one of them is.
template <class K, class P, class Frac, class AtDouble, class AtMidpoint>
[[nodiscard]] constexpr bool all_pieces(K& k, std::vector<P>& params, const P& start, const P& end, const Frac& fraction,
                                        const AtDouble& at_double, const AtMidpoint& at_midpoint) {
    auto order = [&](const P& x, const P& y) {
        return k.sgn([=](auto L) {
            const auto [nx, dx] = fraction(L, x);
            const auto [ny, dy] = fraction(L, y);
            return nx * dy - ny * dx;
        });
    };
    merge_sort(params, [&](const P& x, const P& y) { return order(x, y) == sign::negative; });
    for (std::size_t i = 0; i <= params.size(); ++i) {
        const P& lo = i == 0 ? start : params[i - 1];
        const P& hi = i == params.size() ? end : params[i];
        if (order(lo, hi) == sign::zero) continue; // no piece between them
        const auto [nl, dl] = fraction(arith::lift_double{}, lo);
        const auto [nh, dh] = fraction(arith::lift_double{}, hi);
        const double t = dl > 0.0 && dh > 0.0 ? 0.5 * (nl / dl + nh / dh) : -1.0;
        auto beyond = [&](const P& p) { // the sign of t D - N
            return arith::sgn<arith::hint::optional>(k, [=](auto L) {
                const auto [n, d] = fraction(L, p);
                return L(t) * d - L(1.0) * n;
            });
        };
        const bool between = t > 0.0 && t < 1.0 && beyond(lo) == sign::positive && beyond(hi) == sign::negative;
        if (!(between ? at_double(t) : at_midpoint(lo, hi))) return false;
    }
    return true;
}

} // namespace incidence::detail::pieces
