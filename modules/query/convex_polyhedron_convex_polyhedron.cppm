// convex_polyhedron3 against convex_polyhedron3, and the test of two half-space sets that
// convex_polyhedron_frustum shares.
// Semantics: two closed half-space sets of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set). Touching at a vertex,
// an edge or a face counts.
// Method (exact tiers): the two sets meet iff the half-spaces of both together are feasible.
// At run time, with more than twelve planes in all, the exact feasibility test of all the
// half-spaces together at once (its linear program's guess first). Otherwise first, a face of
// either set with the other set wholly beyond it says no: the other set's vertex least along the
// face normal, guessed in double, short of the face, with its three planes' multipliers for the
// normal all positive (a Farkas certificate), signs of degree <= 4. Then a point strictly inside
// both says yes: the mean of the vertices of each set that lie in the other, guessed in double and
// proven with signs of degree 2. Otherwise the exact feasibility test of all the half-spaces
// together (polyq::feasible in aabb_convex_polyhedron.cppm: the minimal faces
// by the rank of the normals, signs of degree <= 5).
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, sections 7.3 (Farkas) and 8.5
// (minimal faces).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_convex_polyhedron.cpp).
module;
#include <array>
export module incidence.query:convex_polyhedron_convex_polyhedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :convex_polyhedron_point;
import :aabb_convex_polyhedron;
import :convex_polyhedron_plane;

export namespace incidence::pair {

namespace polyq {

// Is some half-space of `a` proven to have the whole set `b` beyond it (b's vertex least along its
// normal, guessed from vb, short of it with a Farkas certificate)?
template <class K>
[[nodiscard]] constexpr bool face_separates(K& k, const plane3* a, int ma, const plane3* b, int mb, const vertex_guesses& vb) {
    for (int r = 0; r < ma; ++r) {
        const plane3 h = a[r];
        int best = -1;
        double lo = 0;
        for (int v = 0; v < vb.n; ++v) {
            const point3 x = vb.at[static_cast<unsigned>(v)];
            const double t = h.normal.x * x.x + h.normal.y * x.y + h.normal.z * x.z;
            if (best < 0 || t < lo) best = v, lo = t;
        }
        if (best < 0 || !(lo > h.offset)) continue; // not beyond, as far as double can tell
        // has b a point with -n . x >= -c (n . x <= c)? no: separated
        if (side_at_vertex(k, b, mb, vb.triple[static_cast<unsigned>(best)], -h.normal, -h.offset) == 0) return true;
    }
    return false;
}

// Above this many planes in all, sets_meet goes to feasible() at once: its linear program's guess
// measured cheaper than every triple of each set, except for two frustums (6 + 6).
inline constexpr int guess_all_above = 12;
// Do the half-space sets a (ma planes) and b (mb planes) meet? ma, mb <= convex_polyhedron3::capacity.
template <class K>
[[nodiscard]] constexpr bool sets_meet(K& k, const plane3* a, int ma, const plane3* b, int mb) {
    constexpr int capacity = convex_polyhedron3::capacity;
    if (!well_formed(a, ma, capacity) || !well_formed(b, mb, capacity)) return false;
    std::array<plane3, 2 * capacity> rows{};
    for (int i = 0; i < ma; ++i) rows[static_cast<unsigned>(i)] = a[i];
    for (int i = 0; i < mb; ++i) rows[static_cast<unsigned>(ma + i)] = b[i];
    // at run time, many planes: the linear program's guess in feasible() first
    if (!__builtin_is_constant_evaluated() && ma + mb > guess_all_above) return feasible(k, rows.data(), static_cast<unsigned>(ma + mb));
    const vertex_guesses va = vertices_guess(a, ma), vb = vertices_guess(b, mb);
    if (face_separates(k, a, ma, b, mb, vb) || face_separates(k, b, mb, a, ma, va)) return false;
    // a point strictly inside both: the mean of the vertices of each set that look inside the other
    auto inside_all = [](const plane3* p, int m, point3 x) {
        for (int r = 0; r < m; ++r)
            if (!(dot(p[r].normal, x - point3{0, 0, 0}) <= p[r].offset)) return false;
        return true;
    };
    double sx = 0, sy = 0, sz = 0;
    int count = 0;
    auto add = [&](const vertex_guesses& g, const plane3* other, int mo) {
        for (int v = 0; v < g.n; ++v) {
            const point3 x = g.at[static_cast<unsigned>(v)];
            if (inside_all(other, mo, x)) sx += x.x, sy += x.y, sz += x.z, ++count;
        }
    };
    add(va, b, mb);
    add(vb, a, ma);
    if (count > 0) {
        const point3 w{sx / count, sy / count, sz / count};
        bool strictly = finite(w);
        auto strictly_in = [&](const plane3* p, int m) {
            for (int r = 0; r < m && strictly; ++r) {
                const plane3 h = p[r];
                strictly = arith::probe(k, [=](auto L) { return L(h.offset) * L(1.0) - arith::dot(arith::lift(L, h.normal), arith::lift(L, w)); }) ==
                           sign::positive;
            }
        };
        strictly_in(a, ma);
        strictly_in(b, mb);
        if (strictly) return true;
    }
    return feasible(k, rows.data(), static_cast<unsigned>(ma + mb));
}

} // namespace polyq

namespace polyq {
// A fixed order of two lists of n planes (the numbers in turn; NaN compares as equal), so a test
// of two sets runs on the same order of its arguments whichever way they come: the approximate
// tier then answers the same for both orders too.
[[nodiscard]] constexpr bool planes_before(const plane3* a, const plane3* b, int n) {
    for (int i = 0; i < n; ++i) {
        const plane3 p = a[i], q = b[i];
        const double x[4] = {p.normal.x, p.normal.y, p.normal.z, p.offset}, y[4] = {q.normal.x, q.normal.y, q.normal.z, q.offset};
        for (int j = 0; j < 4; ++j)
            if (x[j] != y[j] && x[j] == x[j] && y[j] == y[j]) return x[j] < y[j];
    }
    return false;
}
// Two polyhedra: the count, then the planes.
[[nodiscard]] constexpr bool before(const convex_polyhedron3& a, const convex_polyhedron3& b) {
    if (a.count != b.count) return a.count < b.count;
    const int n = a.count < 0 ? 0 : (a.count > convex_polyhedron3::capacity ? convex_polyhedron3::capacity : a.count);
    return planes_before(a.planes.data(), b.planes.data(), n);
}
} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& a, const convex_polyhedron3& b) {
    const bool swap = polyq::before(b, a);
    const convex_polyhedron3& p = swap ? b : a;
    const convex_polyhedron3& q = swap ? a : b;
    return polyq::sets_meet(k, p.planes.data(), p.count, q.planes.data(), q.count);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const convex_polyhedron3&);
} // namespace incidence::pair
