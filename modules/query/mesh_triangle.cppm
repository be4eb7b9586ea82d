// mesh3 against triangle3 (a collinear triangle is its hull), and contains(mesh, triangle).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any mesh triangle meeting it (triangle_triangle), else the parity
// of a vertex.
// contains: every point of the triangle t = a b c in the set. A collinear t is its three edges
// (contains(mesh, segment)); otherwise its vertices first, and with no mesh triangle meeting t,
// one vertex decides. Else t's plane H is cut by the surface into lines: a triangle crossing H
// gives the segment where it does (its crossing flips the parity: toggle 1), a triangle with one
// edge in H gives that edge (toggle 1 when it rises on the positive side of H, else nothing),
// and a triangle lying in H covers its area (on the surface, so in the set). Chords from an apex
// a to e(s) = b + s (c - b) sweep t. The directions of the lines' end points (mesh vertices in H,
// edges crossing H), of the points where lines meet b c, and of the points where a line crosses an
// edge of a covering triangle, are exact rationals s = N / D (degree 3/3; a crossing on such an
// edge 5/5, the order of two of them degree 10); one double chord strictly inside each open
// interval between them meets every cell of the arrangement: within a sector no line ends, so
// every line there crosses that chord, and (apart from the covering triangles' edges, whose
// crossings are directions too) the cells' parities are sums of toggles that the chord sees in
// order. The chord's s is a double, or where a sector holds none, a sum of two or three (each
// lifted as an input, so no degree grows), or a pair chord (below). Along a chord (degree 2: a + t ((b - a) + s (c - b))),
// the lines are crossed at t = N / D (degree 4/4, or 3/3 for an edge in H; compared at degree 8);
// the parity starts inside at a free
// apex (a vertex on no triangle, inside), or else outside the mesh's box, the chord's line being
// followed from t = -infinity through every triangle (at a itself a half-open rule: only the lines
// leaving a to the chord's left are crossed). Every piece of the chord inside t must be covered or
// of odd parity. A chord through a point where two lines cross (only on a self-intersecting
// surface) is moved to the next double; after 32 such moves, or where a sector holds no sum of
// three doubles (two directions closer than about 2^-159 apart: nearly coincident line ends, as
// on two shells glued face to face and nudged by ulps), the chord is w0 V0 + w1 V1, a positive
// combination of the sector's two bounding directions (each of degree 4), strictly inside the
// sector however thin: along it a cut's parameter is n / d with n of degree 3 and d of 7 (ordered
// at degree 10), and a cut before the chord's end is one on a's side of b c (degree 9). Each point
// where two lines cross rules out one ratio w1 / w0, so one of lines^2 + 2 ratios gives a clean
// chord, and one apex decides (free apexes first, then a vertex with the line followed from
// outside; the next apex, and after all of them "not contained", only for an inexact kernel).
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); the sweep of a plane section by a pencil of lines through a vertex, cut
// at the arrangement's vertices (Bentley and Ottmann, IEEE Trans. Computers 28(9), 1979, in
// angular form); the surface perturbed to one side of H for its in-plane edges as in Edelsbrunner
// and Muecke, "Simulation of Simplicity", ACM TOG 9(1), 1990.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent, or (contains) when a deciding sign's permanent leaves [2^-900, 2^900], where plain
// double under- or overflows: its signs have degree up to 10, so from inputs beyond about 2^+-90
// on (tests/query/mesh_triangle.cpp).
module;
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>
export module incidence.query:mesh_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.predicates;
import :segment_segment;
import :mesh_point;
import :mesh_segment;
import :triangle_triangle;
import :point_triangle;
import :point_tetrahedron;
import :segment_pieces;
import :segment_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const triangle3& t) {
    if (!meshq::well_formed(m) || !finite(t)) return false;
    const point3 pts[3] = {t.a, t.b, t.c};
    const aabb3 xb = meshq::bounds(pts, 3);
    if (!meshq::boxes_meet(meshq::bounds(m), xb)) return false;
    return meshq::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, f, t); }, t.a, &xb);
}

namespace meshq {

// The k-th component of u x v: the cross product of the projections along axis k.
template <class U, class V>
[[nodiscard]] constexpr auto cross_along(int k, const arith::v3<U>& u, const arith::v3<V>& v) {
    return k == 0 ? u.y * v.z - u.z * v.y : (k == 1 ? u.z * v.x - u.x * v.z : u.x * v.y - u.y * v.x);
}

// A chord's parameter s = c0 + c1 + c2, a sum of doubles (lifted as three inputs: the degrees do not
// change), so that a sector too thin to hold a double still holds an s.
struct sweep_s {
    double c[3] = {0.0, 0.0, 0.0};
    template <class L>
    [[nodiscard]] constexpr auto lift(L l) const { return l(c[0]) + l(c[1]) + l(c[2]); }
};

// The triangle a b c swept from its apex a by chords to e(s) = b + s (c - b), seen along `axis`
// (its normal's component there is nonzero).
struct sweep_frame {
    point3 a, b, c;
    int axis;
    // (b - a) + s (c - b), of degree 2 (with 1 lifted as an input)
    template <class L>
    [[nodiscard]] constexpr auto dir(L lift, const sweep_s& s) const {
        const auto one = lift(1.0);
        const auto S = s.lift(lift);
        const auto u = arith::lift(lift, b) - arith::lift(lift, a), w = arith::lift(lift, c) - arith::lift(lift, b);
        using T = decltype(u.x * one + S * w.x);
        return arith::v3<T>{u.x * one + S * w.x, u.y * one + S * w.y, u.z * one + S * w.z};
    }
    // The plane through a, b, c, as a segment_param's plane (the parameter where p q crosses it).
    [[nodiscard]] constexpr segment_param plane() const { return {a, a, b, a, c}; }
};

// A direction from the apex, as the s of the point where its line meets b c: a plane through
// the apex (or a plane b c crosses), s = det(E, F, x - b) / det(E, F, c - b) (degree 3/3); or
// (`on_edge`) the point z where the edge p q crosses `plane`, s = cross(b - a, Z) / cross(Z, c -
// b) along the axis with Z = (z - a) D (degree 5/5; D's sign cancels in the quotient). Negated
// so that the denominator is positive when `flip`.
struct sweep_dir {
    segment_param plane;
    bool on_edge = false;
    segment3 edge{};
    bool flip = false;
};
// (z - a) D for the point z = p + (N / D) (q - p) of the edge p q where it crosses the plane
// `at`: degree 4, of z - a's direction when D > 0 (at's flip).
template <class L>
[[nodiscard]] constexpr auto offset_on_edge(L lift, const segment_param& at, const segment3& e, const point3& a) {
    const auto [n, d] = at.fraction(lift, e);
    const auto P = arith::lift(lift, e.a), Q = arith::lift(lift, e.b), A = arith::lift(lift, a);
    using T = decltype((P.x - A.x) * d + (Q.x - P.x) * n);
    return arith::v3<T>{(P.x - A.x) * d + (Q.x - P.x) * n, (P.y - A.y) * d + (Q.y - P.y) * n, (P.z - A.z) * d + (Q.z - P.z) * n};
}
// use(f) with f(L) = {N, D} of the direction d (its own expression type for each kind).
template <class Use>
[[nodiscard]] constexpr auto with_dir(const sweep_frame& fr, const sweep_dir& d, const Use& use) {
    if (!d.on_edge) {
        segment_param p = d.plane;
        p.flip = d.flip;
        return use([p, bc = segment3{fr.b, fr.c}](auto L) { return p.fraction(L, bc); });
    }
    return use([fr, d](auto L) {
        const auto Z = offset_on_edge(L, d.plane, d.edge, fr.a);
        const auto n = cross_along(fr.axis, arith::lift(L, fr.b) - arith::lift(L, fr.a), Z);
        const auto den = cross_along(fr.axis, Z, arith::lift(L, fr.c) - arith::lift(L, fr.b));
        return d.flip ? std::pair{-n, -den} : std::pair{n, den};
    });
}

// Where a line of the section meets the chord: an end point of a crossing triangle's segment (a
// vertex in H, or where the edge p q crosses H, `at` made D > 0).
struct sweep_end {
    bool vertex = true;
    point3 p{}, q{};
    segment_param at{};
};
// A line of the section: kind 0, the segment where the triangle a0 a1 a2 crosses H (between e0
// and e1); kind 1, an edge a0 a1 lying in H. tau: the parity's change across it (0 or 1); band:
// the covering triangle whose edge it is, or -1.
struct sweep_line {
    int kind = 0;
    point3 a0{}, a1{}, a2{};
    sweep_end e0{}, e1{};
    int tau = 0;
    int band = -1;
    bool near = true; // from a triangle meeting t
};
// A line crossed by the chord at t = N / D (D > 0 with flip); pos: its group along the chord.
struct chord_cut {
    std::size_t line = 0;
    bool flip = false;
    int pos = 0;
};
// A chord of the sweep from the apex a: its direction dir(L); a cut at t = n / d along a + t dir,
// where num(L, x) balances a cut's numerator x with dir's degree; before(L, n, d), whose sign
// times before_sign is positive when the cut lies before the chord's end on b c.
// s_chord: the chord to e(s), dir = e(s) - a (degree 2, with 1 lifted), the end at t = 1.
struct s_chord {
    sweep_frame fr;
    sweep_s s;
    int before_sign = 1;
    template <class L>
    [[nodiscard]] constexpr auto dir(L lift) const { return fr.dir(lift, s); }
    template <class L, class T>
    [[nodiscard]] constexpr auto num(L lift, const T& x) const { return lift(1.0) * x; }
    template <class L, class N, class D>
    [[nodiscard]] constexpr auto before(L, const N& n, const D& d) const { return d - n; }
};
// The direction of a sector's bound from the apex, of degree 4 and pointing into the triangle:
// e(s) - a times D for a direction s = N / D (D > 0; s = 0 and 1 as the planes through b and c
// across b c along coordinate axes), or (z - a) D for a crossing z on an edge (`negate` when that
// D is negative).
struct sector_bound {
    sweep_dir d{};
    bool negate = false;
};
template <class L>
[[nodiscard]] constexpr auto bound_vector(L lift, const sweep_frame& fr, const sector_bound& b) {
    if (b.d.on_edge) {
        const auto Z = offset_on_edge(lift, b.d.plane, b.d.edge, fr.a);
        using T = decltype(Z.x);
        return b.negate ? arith::v3<T>{-Z.x, -Z.y, -Z.z} : Z;
    }
    segment_param p = b.d.plane;
    p.flip = b.d.flip;
    const auto [n, dd] = p.fraction(lift, segment3{fr.b, fr.c});
    const auto A = arith::lift(lift, fr.a), B = arith::lift(lift, fr.b);
    const auto u = B - A, w = arith::lift(lift, fr.c) - B;
    using T = decltype(u.x * dd + w.x * n);
    return arith::v3<T>{u.x * dd + w.x * n, u.y * dd + w.y * n, u.z * dd + w.z * n};
}
// pair_chord: w0 V0 + w1 V1 for the bounds V0, V1 of a sector (degree 5, strictly inside it
// however thin it is); a cut's numerator as it is (t = n / d is then of degree -4), and its side
// of b c, d S_a + n ((c - b) x dir) along the axis (degree 9), against that of a, S_a.
struct pair_chord {
    sweep_frame fr;
    sector_bound lo, hi;
    double w0 = 1.0, w1 = 1.0;
    int before_sign = 1; // the sign of S_a = (c - b) x (a - b) along the axis
    template <class L>
    [[nodiscard]] constexpr auto dir(L lift) const {
        const auto v0 = bound_vector(lift, fr, lo), v1 = bound_vector(lift, fr, hi);
        const auto x0 = lift(w0), x1 = lift(w1);
        using T = decltype(v0.x * x0 + v1.x * x1);
        return arith::v3<T>{v0.x * x0 + v1.x * x1, v0.y * x0 + v1.y * x1, v0.z * x0 + v1.z * x1};
    }
    template <class L, class T>
    [[nodiscard]] constexpr const T& num(L, const T& x) const { return x; }
    template <class L, class N, class D>
    [[nodiscard]] constexpr auto before(L lift, const N& n, const D& d) const {
        const auto B = arith::lift(lift, fr.b);
        const auto w = arith::lift(lift, fr.c) - B;
        return d * cross_along(fr.axis, w, arith::lift(lift, fr.a) - B) + n * cross_along(fr.axis, w, dir(lift));
    }
};
// use(f) with f(L) = {N, D} of the cut's parameter along the chord ch.
template <class Chord, class Use>
[[nodiscard]] constexpr auto with_cut(const sweep_frame& fr, const Chord& ch, const sweep_line& l, bool flip, const Use& use) {
    if (l.kind == 1)
        return use([fr, ch, l, flip](auto L) {
            const auto P = arith::lift(L, l.a0), A = arith::lift(L, fr.a);
            const auto e = arith::lift(L, l.a1) - P;
            const auto n = ch.num(L, cross_along(fr.axis, e, P - A));
            const auto d = cross_along(fr.axis, e, ch.dir(L));
            return flip ? std::pair{-n, -d} : std::pair{n, d};
        });
    return use([fr, ch, l, flip](auto L) {
        const auto P = arith::lift(L, l.a0), A = arith::lift(L, fr.a);
        const auto nf = arith::cross(arith::lift(L, l.a1) - P, arith::lift(L, l.a2) - P);
        const auto n = ch.num(L, arith::dot(nf, P - A));
        const auto d = arith::dot(nf, ch.dir(L));
        return flip ? std::pair{-n, -d} : std::pair{n, d};
    });
}
// use(f) with f(L) the direction of the line in H (an edge, degree 1, or n_f x n_t, degree 4).
template <class Use>
[[nodiscard]] constexpr auto with_line_dir(const sweep_frame& fr, const sweep_line& l, const Use& use) {
    if (l.kind == 1) return use([l](auto L) { return arith::lift(L, l.a1) - arith::lift(L, l.a0); });
    return use([fr, l](auto L) {
        const auto P = arith::lift(L, l.a0), A = arith::lift(L, fr.a);
        return arith::cross(arith::cross(arith::lift(L, l.a1) - P, arith::lift(L, l.a2) - P),
                            arith::cross(arith::lift(L, fr.b) - A, arith::lift(L, fr.c) - A));
    });
}

enum class sweep_result { inside, outside, retry };

// A filter kernel that has failed a sign: its answer will be discarded (the exact kernel decides,
// or classify says uncertain), so the search for a clean chord can stop.
template <class K>
[[nodiscard]] constexpr bool gave_up(const K& k) {
    if constexpr (requires { k.failed(); }) return k.failed();
    else return false;
}

// s with its last nonzero part moved to the next double up or down
[[nodiscard]] constexpr sweep_s next_s(sweep_s s, bool up) {
    const int i = s.c[2] != 0.0 ? 2 : (s.c[1] != 0.0 ? 1 : 0);
    const auto b = std::bit_cast<std::uint64_t>(s.c[i]);
    s.c[i] = std::bit_cast<double>(up ? b + 1 : b - 1);
    return s;
}

// The sweep from fr.a (see the top comment). `free_apex`: fr.a lies on no triangle and inside,
// and `near` lists every triangle meeting t; else every triangle is followed.
template <class K>
[[nodiscard]] constexpr sweep_result sweep(K& k, const mesh3& m, const sweep_frame& fr, bool free_apex, const std::vector<std::size_t>& near) {
    const point3 A = fr.a, B = fr.b, C = fr.c;
    const int axis = fr.axis;
    const point3 ek = unit(axis);
    std::vector<sweep_line> lines;
    std::vector<sweep_dir> dirs, far_dirs;
    int bands = 0;
    auto plane_side = [&](point3 p) { return k.sgn([=](auto L) { return poly::orient3d(L, A, B, C, p); }); };
    // d's s when strictly inside (0, 1), with D made positive
    auto keep_dir = [&](sweep_dir d, std::vector<sweep_dir>& into) {
        d.flip = false;
        const sign den = with_dir(fr, d, [&](auto f) { return k.sgn([=](auto L) { return f(L).second; }); });
        if (den == sign::zero) return;
        d.flip = den == sign::negative;
        const bool inside = with_dir(fr, d, [&](auto f) {
            return k.sgn([=](auto L) { return f(L).first; }) == sign::positive && k.sgn([=](auto L) {
                       const auto [n, dd] = f(L);
                       return dd - n;
                   }) == sign::positive;
        });
        if (inside) into.push_back(d);
    };
    // where the edge p q (strictly across H) crosses it
    auto crossing_end = [&](point3 p, point3 q) {
        segment_param at = fr.plane();
        const segment3 e{p, q};
        at.flip = k.sgn([=](auto L) { return at.fraction(L, e).second; }) == sign::negative;
        return sweep_end{false, p, q, at};
    };
    // Is the end e (a vertex in H, or where an edge crosses H) in the closed triangle? Only such
    // points are vertices of the cells the sweep must meet; the others matter only where the
    // chord's line is followed from outside (a line's end on it would break the half-open count).
    // the side of y from the line x0 x1 in H, seen along the axis (degree 2)
    auto side_of = [&](point3 x0, point3 x1, point3 y) {
        return k.sgn([=](auto L) {
            const auto X = arith::lift(L, x0);
            return cross_along(axis, arith::lift(L, x1) - X, arith::lift(L, y) - X);
        });
    };
    const sign turn = side_of(A, B, C);
    auto in_triangle = [&](const sweep_end& e) {
        auto side = [&](point3 u0, point3 u1) {
            if (e.vertex) return side_of(u0, u1, e.p);
            const segment_param at = e.at;
            const segment3 pq{e.p, e.q};
            return k.sgn([=](auto L) { // (x - u0) D = (x - a) D - (u0 - a) D
                const auto F = offset_on_edge(L, at, pq, A);
                const auto d = at.fraction(L, pq).second;
                const auto U = arith::lift(L, u0) - arith::lift(L, A);
                using T = decltype(F.x - U.x * d);
                return cross_along(axis, arith::lift(L, u1) - arith::lift(L, u0), arith::v3<T>{F.x - U.x * d, F.y - U.y * d, F.z - U.z * d});
            });
        };
        const point3 corner[3] = {A, B, C};
        for (int j = 0; j < 3; ++j)
            if (const sign x = side(corner[j], corner[(j + 1) % 3]); x != sign::zero && x != turn) return false;
        return true;
    };
    auto add_face = [&](std::size_t i, bool is_near) {
        const triangle3 f = m.triangle(i);
        const point3 v[3] = {f.a, f.b, f.c};
        const sign o[3] = {plane_side(v[0]), plane_side(v[1]), plane_side(v[2])};
        int zeros = 0, pos = 0, neg = 0;
        for (const sign x : o) zeros += x == sign::zero, pos += x == sign::positive, neg += x == sign::negative;
        if (zeros == 0 && (pos == 0 || neg == 0)) return; // off H
        bool collinear = true;
        for (int ax = 0; ax < 3 && collinear; ++ax)
            collinear = arith::is_zero(k, [=](auto L) {
                            const auto P = arith::lift(L, v[0]);
                            const auto n = arith::cross(arith::lift(L, v[1]) - P, arith::lift(L, v[2]) - P);
                            return ax == 0 ? n.x : (ax == 1 ? n.y : n.z);
                        });
        if (collinear) return; // no interior: neither crossed nor covering
        for (int j = 0; j < 3; ++j) {
            const point3 p = v[j], q = v[(j + 1) % 3];
            // a point in the triangle goes to dirs; one outside only to far_dirs, and only when the
            // chord's line is followed from outside
            auto to = [&](const sweep_end& e) -> std::vector<sweep_dir>* {
                if (is_near && in_triangle(e)) return &dirs;
                return free_apex ? nullptr : &far_dirs;
            };
            if (o[j] == sign::zero && !(p.x == A.x && p.y == A.y && p.z == A.z)) // a vertex in H: the plane through a, p and e_k
                if (std::vector<sweep_dir>* d = to(sweep_end{true, p})) keep_dir(sweep_dir{segment_param{A, A, p, origin, ek}}, *d);
            if ((o[j] == sign::positive && o[(j + 1) % 3] == sign::negative) || (o[j] == sign::negative && o[(j + 1) % 3] == sign::positive))
                if (std::vector<sweep_dir>* d = to(crossing_end(p, q))) // an edge across H: the plane through a, p, q
                    keep_dir(sweep_dir{segment_param{A, A, p, A, q}}, *d);
        }
        // where an edge in H meets b c, when it does (a cell's vertex)
        auto meets_bc = [&](point3 p, point3 q) {
            const sign sp = side_of(B, C, p), sq = side_of(B, C, q), sb = side_of(p, q, B), sc = side_of(p, q, C);
            return sp != sq && sb != sc && !(sp == sign::zero && sq == sign::zero);
        };
        auto in_plane_edge = [&](point3 p, point3 q, int tau, int band) {
            lines.push_back(sweep_line{1, p, q, q, sweep_end{true, p}, sweep_end{true, q}, tau, band, is_near});
            if (is_near && meets_bc(p, q)) keep_dir(sweep_dir{segment_param{p, p, q, origin, ek}}, dirs);
        };
        if (zeros == 3) { // covering
            const int band = bands++;
            for (int j = 0; j < 3; ++j) in_plane_edge(v[j], v[(j + 1) % 3], 0, band);
            return;
        }
        if (zeros == 2) { // an edge in H; the surface just above H crosses it when the third vertex is above
            const int j = o[0] != sign::zero ? 0 : (o[1] != sign::zero ? 1 : 2);
            if (o[j] == sign::positive) in_plane_edge(v[(j + 1) % 3], v[(j + 2) % 3], 1, -1);
            return;
        }
        sweep_end ends[2];
        if (zeros == 1) {
            const int j = o[0] == sign::zero ? 0 : (o[1] == sign::zero ? 1 : 2);
            if (o[(j + 1) % 3] == o[(j + 2) % 3]) return; // touching H at a vertex
            ends[0] = sweep_end{true, v[j]};
            ends[1] = crossing_end(v[(j + 1) % 3], v[(j + 2) % 3]);
        } else {
            int n = 0;
            for (int j = 0; j < 3; ++j)
                if (o[j] != o[(j + 1) % 3]) ends[n++] = crossing_end(v[j], v[(j + 1) % 3]);
        }
        lines.push_back(sweep_line{0, v[0], v[1], v[2], ends[0], ends[1], 1, -1, is_near});
        if (is_near && intersects(k, segment3{B, C}, f)) // where b c crosses it
            keep_dir(sweep_dir{segment_param{v[0], v[0], v[1], v[0], v[2]}}, dirs);
    };
    if (free_apex) {
        for (const std::size_t i : near) add_face(i, true);
    } else {
        std::vector<unsigned char> is_near(m.triangles.size(), 0); // (std::vector<bool> is not usable in constant evaluation here)
        for (const std::size_t i : near) is_near[i] = 1;
        for (std::size_t i = 0; i < m.triangles.size(); ++i) add_face(i, is_near[i] != 0);
    }
    if (gave_up(k)) return sweep_result::outside; // (a filter that failed here would find every triangle in H)
    // crossings of a covering triangle's edge by another line, strictly inside both (lines of
    // triangles meeting t: no other line has a point in t)
    const std::size_t n_lines = lines.size();
    for (std::size_t i = 0; i < n_lines && bands > 0; ++i) {
        if (lines[i].band < 0 || !lines[i].near) continue;
        const point3 p = lines[i].a0, q = lines[i].a1;
        const segment3 e{p, q};
        for (std::size_t j = 0; j < n_lines; ++j) {
            const sweep_line& l = lines[j];
            if (j == i || l.band == lines[i].band || !l.near) continue;
            if (l.kind == 0) {
                const point3 g0 = l.a0, g1 = l.a1, g2 = l.a2;
                const sign sp = k.sgn([=](auto L) { return poly::orient3d(L, g0, g1, g2, p); });
                const sign sq = k.sgn([=](auto L) { return poly::orient3d(L, g0, g1, g2, q); });
                if (sp == sign::zero || sq == sign::zero || sp == sq) continue;
                const sign s0 = k.sgn([=](auto L) { return poly::orient3d(L, p, q, g0, g1); });
                const sign s1 = k.sgn([=](auto L) { return poly::orient3d(L, p, q, g1, g2); });
                const sign s2 = k.sgn([=](auto L) { return poly::orient3d(L, p, q, g2, g0); });
                if (s0 == sign::zero || s0 != s1 || s1 != s2) continue;
                keep_dir(sweep_dir{segment_param{g0, g0, g1, g0, g2}, true, e}, dirs);
            } else {
                const point3 r = l.a0, w = l.a1;
                const sign a1 = side_of(p, q, r), a2 = side_of(p, q, w), b1 = side_of(r, w, p), b2 = side_of(r, w, q);
                if (a1 == sign::zero || a2 == sign::zero || a1 == a2 || b1 == sign::zero || b2 == sign::zero || b1 == b2) continue;
                keep_dir(sweep_dir{segment_param{r, r, w, origin, ek}, true, e}, dirs);
            }
        }
    }
    auto order = [&](const sweep_dir& x, const sweep_dir& y) {
        return with_dir(fr, x, [&](auto fx) {
            return with_dir(fr, y, [&](auto fy) {
                return k.sgn([=](auto L) {
                    const auto [nx, dx] = fx(L);
                    const auto [ny, dy] = fy(L);
                    return nx * dy - ny * dx;
                });
            });
        });
    };
    // the sign of s - d
    auto above = [&](const sweep_s& s, const sweep_dir& d) {
        return with_dir(fr, d, [&](auto f) {
            return k.sgn([=](auto L) {
                const auto [n, dd] = f(L);
                return s.lift(L) * dd - L(1.0) * n;
            });
        });
    };
    auto estimate = [&](const sweep_dir& d) {
        return with_dir(fr, d, [&](auto f) {
            const auto [n, dd] = f(arith::lift_double{});
            return n / dd;
        });
    };
    pieces::merge_sort(dirs, [&](const sweep_dir& x, const sweep_dir& y) { return order(x, y) == sign::negative; });

    // One chord: inside, outside, or retry (it passes where two lines cross).
    std::vector<chord_cut> cuts;
    std::vector<std::array<int, 3>> band_at; // per covering triangle: its crossings' groups, and their count
    auto chord = [&](const auto& ch) {
        cuts.clear();
        band_at.assign(static_cast<std::size_t>(bands), std::array<int, 3>{0, 0, 0});
        int parity = free_apex ? 1 : 0;
        auto end_side = [&](const sweep_end& e) {
            if (e.vertex) {
                const point3 p = e.p;
                return k.sgn([=](auto L) { return cross_along(axis, ch.dir(L), arith::lift(L, p) - arith::lift(L, A)); });
            }
            const segment_param at = e.at;
            const segment3 pq{e.p, e.q};
            return k.sgn([=](auto L) { return cross_along(axis, ch.dir(L), offset_on_edge(L, at, pq, A)); });
        };
        auto band_mark = [&](int band, int pos) {
            auto& b = band_at[static_cast<std::size_t>(band)];
            if (b[2] < 2) b[static_cast<std::size_t>(b[2])] = pos;
            ++b[2];
        };
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const sweep_line& l = lines[i];
            if ((end_side(l.e0) == sign::positive) == (end_side(l.e1) == sign::positive)) continue; // half-open: not crossed
            const sign den = with_cut(fr, ch, l, false, [&](auto f) { return k.sgn([=](auto L) { return f(L).second; }); });
            if (den == sign::zero) continue;
            const bool flip = den == sign::negative;
            const sign num = with_cut(fr, ch, l, flip, [&](auto f) { return k.sgn([=](auto L) { return f(L).first; }); });
            if (num != sign::positive) { // at or before the apex
                if (!free_apex) parity ^= l.tau;
                if (l.band >= 0) band_mark(l.band, -1);
                continue;
            }
            const sign rest = with_cut(fr, ch, l, flip, [&](auto f) {
                return k.sgn([=](auto L) {
                    const auto [n, d] = f(L);
                    return ch.before(L, n, d);
                });
            });
            if (rest == sign::zero || (rest == sign::positive) != (ch.before_sign > 0)) { // at or beyond the chord's end on b c
                if (l.band >= 0) band_mark(l.band, -2);
                continue;
            }
            cuts.push_back(chord_cut{i, flip, 0});
        }
        auto cut_order = [&](const chord_cut& x, const chord_cut& y) {
            return with_cut(fr, ch, lines[x.line], x.flip, [&](auto fx) {
                return with_cut(fr, ch, lines[y.line], y.flip, [&](auto fy) {
                    return k.sgn([=](auto L) {
                        const auto [nx, dx] = fx(L);
                        const auto [ny, dy] = fy(L);
                        return nx * dy - ny * dx;
                    });
                });
            });
        };
        pieces::merge_sort(cuts, [&](const chord_cut& x, const chord_cut& y) { return cut_order(x, y) == sign::negative; });
        int groups = 0;
        for (std::size_t i = 0; i < cuts.size(); ++i) {
            if (i > 0 && cut_order(cuts[i - 1], cuts[i]) != sign::zero) ++groups;
            cuts[i].pos = groups;
        }
        if (!cuts.empty()) ++groups;
        // two lines through one point of the chord, not along one line: move the chord
        for (std::size_t i = 1; i < cuts.size(); ++i) {
            std::size_t first = i;
            while (first > 0 && cuts[first - 1].pos == cuts[i].pos) --first;
            if (first == i) continue;
            const sign par = with_line_dir(fr, lines[cuts[first].line], [&](auto fx) {
                return with_line_dir(fr, lines[cuts[i].line], [&](auto fy) {
                    return k.sgn([=](auto L) { return cross_along(axis, fx(L), fy(L)); });
                });
            });
            if (par != sign::zero) return sweep_result::retry;
        }
        for (const chord_cut& c : cuts)
            if (lines[c.line].band >= 0) band_mark(lines[c.line].band, c.pos);
        // piece i lies between groups i - 1 and i (the apex before group 0, e(s) after the last)
        std::size_t next = 0;
        for (int piece = 0; piece <= groups; ++piece) {
            bool member = parity == 1;
            for (int b = 0; b < bands && !member; ++b) {
                const auto& at = band_at[static_cast<std::size_t>(b)];
                if (at[2] != 2) continue;
                auto place = [&](int x) { return x == -1 ? -1 : (x == -2 ? groups : x); };
                const int lo = place(at[0]) < place(at[1]) ? place(at[0]) : place(at[1]);
                const int hi = place(at[0]) < place(at[1]) ? place(at[1]) : place(at[0]);
                member = lo <= piece - 1 && hi >= piece;
            }
            if (!member) return sweep_result::outside;
            while (next < cuts.size() && cuts[next].pos == piece) parity ^= lines[cuts[next++].line].tau;
        }
        return sweep_result::inside;
    };
    // no far direction exactly at s (the chord's line, followed before the apex, meets no line's end)
    auto generic = [&](const sweep_s& s) {
        for (const sweep_dir& d : far_dirs)
            if (above(s, d) == sign::zero) return false;
        return true;
    };
    // the same for a pair chord: its direction parallel to none
    auto generic_pair = [&](const pair_chord& c) {
        for (const sweep_dir& d : far_dirs)
            if (arith::is_zero(k, [=](auto L) { return cross_along(axis, c.dir(L), bound_vector(L, fr, sector_bound{d, false})); })) return false;
        return true;
    };
    // a sector's bound: a direction (an edge's crossing z with its D's sign), or for s = 0 (b) or
    // s = 1 (c) the plane through that point and two coordinate axes, det(e_j, e_k, x - b) =
    // (x - b)_i for an axis i along which b c moves
    const int along = B.x != C.x ? 0 : (B.y != C.y ? 1 : 2);
    const bool descends = along == 0 ? C.x < B.x : (along == 1 ? C.y < B.y : C.z < B.z);
    auto bound_of = [&](const sweep_dir* d, bool end) {
        if (d == nullptr)
            return sector_bound{sweep_dir{segment_param{end ? C : B, origin, unit((along + 1) % 3), origin, unit((along + 2) % 3)}, false, {}, descends}, false};
        bool negate = false;
        if (d->on_edge) {
            const segment_param at = d->plane;
            const segment3 e = d->edge;
            negate = k.sgn([=](auto L) { return at.fraction(L, e).second; }) == sign::negative;
        }
        return sector_bound{*d, negate};
    };
    // the side of b c that a lies on, seen along the axis
    const int side_a = k.sgn([=](auto L) {
                           const auto Bl = arith::lift(L, B);
                           return cross_along(axis, arith::lift(L, C) - Bl, arith::lift(L, A) - Bl);
                       }) == sign::positive
                           ? 1
                           : -1;
    const sweep_dir* lo = nullptr; // s = 0
    for (std::size_t i = 0; i <= dirs.size(); ++i) {
        const sweep_dir* hi = i < dirs.size() ? &dirs[i] : nullptr; // nullptr: s = 1
        if (lo != nullptr && hi != nullptr && order(*lo, *hi) == sign::zero) continue;
        // lo < s < hi (0 and 1 where there is no direction)
        auto above_lo = [&](const sweep_s& x) {
            return lo == nullptr ? k.sgn([=](auto L) { return x.lift(L); }) == sign::positive : above(x, *lo) == sign::positive;
        };
        auto below_hi = [&](const sweep_s& x) {
            return hi == nullptr ? k.sgn([=](auto L) { return L(1.0) - x.lift(L); }) == sign::positive : above(x, *hi) == sign::negative;
        };
        sweep_s s{{0.5 * ((lo != nullptr ? estimate(*lo) : 0.0) + (hi != nullptr ? estimate(*hi) : 1.0)), 0.0, 0.0}};
        if (!(s.c[0] > 0.0 && s.c[0] < 1.0) || !above_lo(s) || !below_hi(s)) {
            // part by part, the least value of bit patterns in [0, 1] putting s above lo (bisection),
            // until s is below hi; else the largest not above lo, and on to the next part
            bool found = false;
            s = sweep_s{};
            for (int part = 0; part < 3 && !found; ++part) {
                std::uint64_t a = 0, b = std::bit_cast<std::uint64_t>(1.0);
                auto at = [&](std::uint64_t bits) {
                    sweep_s x = s;
                    x.c[part] = std::bit_cast<double>(bits);
                    return x;
                };
                while (b - a > 1) {
                    const std::uint64_t mid = a + (b - a) / 2;
                    if (above_lo(at(mid))) b = mid;
                    else a = mid;
                }
                found = below_hi(at(b));
                s = found ? at(b) : at(a);
            }
            if (!found) s = sweep_s{{-1.0, 0.0, 0.0}}; // no s of three doubles in this sector
        }
        bool done = false;
        sweep_s up = s, down = s;
        for (int attempt = 0; attempt < 33 && !done && s.c[0] >= 0.0; ++attempt) {
            const sweep_s c = attempt == 0 ? s : (attempt % 2 == 1 ? (up = next_s(up, true)) : (down = next_s(down, false)));
            if ((attempt > 0 && (!above_lo(c) || !below_hi(c))) || !generic(c)) continue;
            const sweep_result r = chord(s_chord{fr, c});
            if (r == sweep_result::outside || gave_up(k)) return sweep_result::outside;
            done = r == sweep_result::inside;
        }
        if (!done) { // chords w0 V_lo + w1 V_hi between the sector's bounds: each point where two lines
                     // cross, and each far direction, rules out one ratio w1 / w0
            const sector_bound blo = bound_of(lo, false), bhi = bound_of(hi, true);
            // (plain double reaches here where its signs disagree with the exact ones, near a zero: a
            // guess, two ratios, rather than lines^2 chords of lines^2 cuts each)
            const std::size_t tries = __is_same(K, arith::approx_kernel) ? 2 : lines.size() * lines.size() + far_dirs.size() + 2;
            for (std::size_t w = 1; w <= tries && !done; ++w) {
                const pair_chord c{fr, blo, bhi, 1.0, double(w), side_a};
                if (!generic_pair(c)) continue;
                const sweep_result r = chord(c);
                if (r == sweep_result::outside || gave_up(k)) return sweep_result::outside;
                done = r == sweep_result::inside;
            }
            if (!done) return sweep_result::retry; // (an inexact kernel's guesses)
        }
        lo = hi;
    }
    return sweep_result::inside;
}

} // namespace meshq

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const mesh3& m, const triangle3& t) {
    if (!meshq::well_formed(m) || !finite(t)) return false;
    const aabb3 mb = meshq::bounds(m);
    if (!meshq::in_box(mb, t.a) || !meshq::in_box(mb, t.b) || !meshq::in_box(mb, t.c)) return false; // the set lies in the vertices' box
    int axis = -1;
    for (int ax = 0; ax < 3 && axis < 0; ++ax)
        if (!arith::is_zero(k, [=](auto L) {
                const auto A = arith::lift(L, t.a);
                const auto n = arith::cross(arith::lift(L, t.b) - A, arith::lift(L, t.c) - A);
                return ax == 0 ? n.x : (ax == 1 ? n.y : n.z);
            }))
            axis = ax;
    if (axis < 0) // collinear: the union of its edges
        return contains(k, m, segment3{t.a, t.b}) && contains(k, m, segment3{t.b, t.c}) && contains(k, m, segment3{t.c, t.a});
    if (!contains(k, m, t.a) || !contains(k, m, t.b) || !contains(k, m, t.c)) return false;
    const point3 v[3] = {t.a, t.b, t.c};
    const aabb3 tb = meshq::bounds(v, 3);
    std::vector<std::size_t> near;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 f = m.triangle(i);
        const point3 w[3] = {f.a, f.b, f.c};
        if (meshq::boxes_meet(meshq::bounds(w, 3), tb) && intersects(k, f, t)) near.push_back(i);
    }
    if (near.empty()) return true; // wholly off the surface, and a vertex is inside
    bool on[3] = {false, false, false};
    for (int j = 0; j < 3; ++j)
        for (std::size_t n = 0; n < near.size() && !on[j]; ++n) on[j] = intersects(k, v[j], m.triangle(near[n]));
    for (int pass = 0; pass < 2; ++pass)
        for (int j = 0; j < 3; ++j) {
            if (pass == 0 && on[j]) continue;
            const meshq::sweep_frame fr{v[j], v[(j + 1) % 3], v[(j + 2) % 3], axis};
            const meshq::sweep_result r = meshq::sweep(k, m, fr, pass == 0, near);
            if (r != meshq::sweep_result::retry) return r == meshq::sweep_result::inside;
            if (meshq::gave_up(k)) return false;
        }
    return false; // see the top comment
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const mesh3&, const triangle3&);
} // namespace incidence::pair
