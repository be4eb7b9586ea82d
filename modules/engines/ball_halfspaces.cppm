// sphere3 against a set of half-spaces n_i . x <= d_i: the test that convex_polyhedron_sphere,
// frustum_sphere and kdop_sphere share (a k-DOP's slabs are such rows, exactly), and the ball in
// such a set (contains).
// Semantics: the closed ball |x - c| <= |r| (an unchecked negative radius acts as |r|, as in
// point_sphere) and the closed half-space set, possibly empty or unbounded (a zero normal is all of
// space when its offset is >= 0 and nothing otherwise). Touching counts.
// Method (exact tiers): the ball meets P iff P is not empty and dist(c, P)^2 <= r^2. The point x*
// of P nearest c is the projection of c onto the affine subspace of some set S of at most three
// rows with independent normals (Karush-Kuhn-Tucker: c - x* = sum over S of l_i n_i, l_i >= 0;
// Caratheodory leaves independent rows): with G = N_S N_S^T, e = N_S c - d_S, l = G^-1 e, and x*
// in P. No such S: P is empty. With e_i = n_i . c - d_i (degree 2, each offset times a lifted 1 so
// every sign is homogeneous):
//   S = {}:      every e_i <= 0 (c in P): yes.
//   S = {i}:     e_i >= 0; e_h |n_i|^2 - (n_h . n_i) e_i <= 0 for the other rows h; then
//                r^2 |n_i|^2 - e_i^2 >= 0 decides (degree 4).
//   S = {i, j}:  det = |n_i x n_j|^2 > 0; l' = (g e_i - b e_j, a e_j - b e_i) >= 0 (a = |n_i|^2,
//                b = n_i . n_j, g = |n_j|^2); e_h det - (n_h . n_i) l'_i - (n_h . n_j) l'_j <= 0;
//                then r^2 det - (l'_i e_i + l'_j e_j) >= 0 decides (degree 6).
//   S = {i,j,l}: D = det(n_i, n_j, n_l) != 0, x* = V / D (V as in aabb_convex_polyhedron.cppm);
//                (n_j x n_l) . (c D - V) >= 0 and its turns (l >= 0, degree 6); sign(d_h D - n_h . V)
//                zero or sign(D) (degree 5); then r^2 D^2 - |c D - V|^2 >= 0 decides (degree 8).
// Every S that the projection may use contains a row with e_i > 0 (its distance l . e is
// positive), so only those are tried, those of rows c lies beyond alone first; first, with more than
// eight rows, the set of plain double's projection (the dual active-set method of Goldfarb and
// Idnani), then the set that plain double's search names, then, if the kernel's signs refute
// them, every set in turn. First, a row with the
// whole ball beyond it (e_i > 0 and e_i^2 > r^2 |n_i|^2) says no.
// contains: for every row, -e_i >= 0 and e_i^2 >= r^2 |n_i|^2 (degree 4): the ball is in each
// half-space, so in P (and P is then not empty).
// Source: Ericson, Real-Time Collision Detection (2005), section 5.1 (closest points, the
// closest-feature case analysis by Voronoi regions); Boyd and Vandenberghe, Convex Optimization
// (2004), section 5.5.3 (KKT conditions for the projection onto a polyhedron).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/intersects/frustum_sphere.cpp).
module;
#include <array>
#include <type_traits>
#include <utility>
export module incidence.detail:engines.ball_halfspaces;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::detail {

namespace ball_rows {

inline constexpr unsigned most = 32; // the most rows: a convex polyhedron's capacity

// The active set the projection of c onto the rows uses: n rows, at[0..n).
struct active {
    unsigned n = 0;
    std::array<unsigned, 3> at{};
};

// What the search found: the projection's active set, or no set (P is empty).
struct found {
    bool any = false;
    active set;
};

template <class L>
[[nodiscard]] constexpr auto excess(L l, const plane3& h, point3 c) { // e = n . c - d, times a lifted 1
    return arith::dot(arith::lift(l, h.normal), arith::lift(l, c)) - l(h.offset) * l(1.0);
}

// The rows at hand: the finite planes, zero normals left out (each all of space or, with a negative
// offset, nothing: `empty`).
struct rows {
    const plane3* p;
    std::array<unsigned, most> at{};
    unsigned n = 0;
    bool empty = false;
    constexpr rows(const plane3* planes, int m) : p(planes) {
        for (unsigned i = 0; i < static_cast<unsigned>(m); ++i) {
            const vec3 v = planes[i].normal;
            if (v.x == 0.0 && v.y == 0.0 && v.z == 0.0) empty = empty || planes[i].offset < 0.0;
            else at[n++] = i;
        }
    }
    [[nodiscard]] constexpr const plane3& operator[](unsigned x) const { return p[at[x]]; }
};

// Is S = {i} (row indexes into r) the projection's active set?
template <class K>
[[nodiscard]] constexpr found one_row(K& k, const rows& r, point3 c, unsigned i) {
    const plane3 a = r[i];
    for (unsigned h = 0; h < r.n; ++h) {
        if (h == i) continue;
        const plane3 b = r[h];
        if (k.sgn([=](auto L) {
                const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal);
                return excess(L, b, c) * arith::dot(na, na) - arith::dot(nb, na) * excess(L, a, c);
            }) == sign::positive)
            return {};
    }
    return {true, active{1, {i, 0, 0}}};
}

template <class K>
[[nodiscard]] constexpr found two_rows(K& k, const rows& r, point3 c, unsigned i, unsigned j) {
    const plane3 a = r[i], b = r[j];
    const auto gram = [=](auto L) {
        const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal);
        return std::array{arith::dot(na, na), arith::dot(na, nb), arith::dot(nb, nb)};
    };
    const auto det = [=](auto L) {
        const auto w = arith::cross(arith::lift(L, a.normal), arith::lift(L, b.normal));
        return arith::dot(w, w);
    };
    if (arith::is_zero<arith::hint::often_zero>(k, det)) return {}; // parallel normals
    // l' = adj(G) e
    const auto mult = [=](auto L) {
        const auto g = gram(L);
        const auto ea = excess(L, a, c), eb = excess(L, b, c);
        return std::array{g[2] * ea - g[1] * eb, g[0] * eb - g[1] * ea};
    };
    if (k.sgn([=](auto L) { return mult(L)[0]; }) == sign::negative) return {};
    if (k.sgn([=](auto L) { return mult(L)[1]; }) == sign::negative) return {};
    for (unsigned h = 0; h < r.n; ++h) {
        if (h == i || h == j) continue;
        const plane3 o = r[h];
        if (k.sgn([=](auto L) {
                const auto l = mult(L);
                const auto no = arith::lift(L, o.normal);
                return excess(L, o, c) * det(L) - arith::dot(no, arith::lift(L, a.normal)) * l[0] -
                       arith::dot(no, arith::lift(L, b.normal)) * l[1];
            }) == sign::positive)
            return {};
    }
    return {true, active{2, {i, j, 0}}};
}

template <class K>
[[nodiscard]] constexpr found three_rows(K& k, const rows& r, point3 c, unsigned i, unsigned j, unsigned l) {
    const plane3 a = r[i], b = r[j], e = r[l];
    // two parallel normals first (a camera frustum's near and far planes): their cross product is
    // exactly zero in double, where the determinant's rounding may leave it open
    for (const auto& [u, v] : {std::pair{a.normal, b.normal}, std::pair{b.normal, e.normal}, std::pair{a.normal, e.normal}})
        if (arith::is_zero<arith::hint::often_zero>(k, [=](auto L) {
                const auto w = arith::cross(arith::lift(L, u), arith::lift(L, v));
                return arith::dot(w, w);
            }))
            return {};
    const auto det = [=](auto L) { return arith::det3(arith::lift(L, a.normal), arith::lift(L, b.normal), arith::lift(L, e.normal)); };
    const sign sd = arith::sgn<arith::hint::often_zero>(k, det);
    if (sd == sign::zero) return {};
    // V = d_a (n_b x n_e) + d_b (n_e x n_a) + d_e (n_a x n_b), each offset times a lifted 1
    const auto vertex = [=](auto L) {
        const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal), ne = arith::lift(L, e.normal);
        const auto one = L(1.0);
        return arith::scaled(arith::cross(nb, ne), L(a.offset) * one) + arith::scaled(arith::cross(ne, na), L(b.offset) * one) +
               arith::scaled(arith::cross(na, nb), L(e.offset) * one);
    };
    const auto gap = [=](auto L) { return arith::scaled(arith::lift(L, c), det(L)) - vertex(L); }; // (c - x*) D
    const vec3 turns[3][2] = {{b.normal, e.normal}, {e.normal, a.normal}, {a.normal, b.normal}};
    for (const auto& t : turns) {
        const vec3 u = t[0], v = t[1];
        if (k.sgn([=](auto L) { return arith::dot(arith::cross(arith::lift(L, u), arith::lift(L, v)), gap(L)); }) == sign::negative)
            return {};
    }
    for (unsigned h = 0; h < r.n; ++h) {
        if (h == i || h == j || h == l) continue;
        const plane3 o = r[h];
        const sign s = k.sgn([=](auto L) { return L(o.offset) * L(1.0) * det(L) - arith::dot(arith::lift(L, o.normal), vertex(L)); });
        if (s != sign::zero && s != sd) return {};
    }
    return {true, active{3, {i, j, l}}};
}

// The set S as the kernel sees it, or no set.
template <class K>
[[nodiscard]] constexpr found try_set(K& k, const rows& r, point3 c, const active& s) {
    switch (s.n) {
    case 1: return one_row(k, r, c, s.at[0]);
    case 2: return two_rows(k, r, c, s.at[0], s.at[1]);
    default: return three_rows(k, r, c, s.at[0], s.at[1], s.at[2]);
    }
}

// Every set in turn (those with a row c lies beyond); `beyond[x]`: e_x > 0. First the sets of
// rows c lies beyond alone (the nearest face, edge or vertex of a ball outside usually), then
// those with some other row.
template <class K>
[[nodiscard]] constexpr found search(K& k, const rows& r, point3 c, const std::array<bool, most>& beyond) {
    for (unsigned i = 0; i < r.n; ++i)
        if (beyond[i])
            if (const found f = one_row(k, r, c, i); f.any) return f;
    for (const bool all_beyond : {true, false}) {
        const auto wanted = [&](unsigned i, unsigned j) { return all_beyond ? beyond[i] && beyond[j] : beyond[i] != beyond[j]; };
        for (unsigned i = 0; i < r.n; ++i)
            for (unsigned j = i + 1; j < r.n; ++j)
                if (wanted(i, j))
                    if (const found f = two_rows(k, r, c, i, j); f.any) return f;
    }
    for (const bool all_beyond : {true, false}) {
        const auto wanted = [&](unsigned i, unsigned j, unsigned l) {
            const bool any = beyond[i] || beyond[j] || beyond[l], all = beyond[i] && beyond[j] && beyond[l];
            return all_beyond ? all : any && !all;
        };
        for (unsigned i = 0; i < r.n; ++i)
            for (unsigned j = i + 1; j < r.n; ++j)
                for (unsigned l = j + 1; l < r.n; ++l)
                    if (wanted(i, j, l))
                        if (const found f = three_rows(k, r, c, i, j, l); f.any) return f;
    }
    return {};
}

// The squared distance from c to its projection under set s, as a quotient P / S (S > 0) of
// polynomials in the inputs: f(g) for g(L) -> ratio{P, S}, one type of g per size of s.
//   {i}:       P = e_i^2, S = |n_i|^2;
//   {i, j}:    P = l'_i e_i + l'_j e_j, S = det (l' = adj(G) e, as in two_rows);
//   {i, j, l}: P = |c D - V|^2, S = D^2 (as in three_rows).
template <class F>
constexpr decltype(auto) with_distance(const rows& r, point3 c, const active& s, F&& f) {
    if (s.n == 1) {
        const plane3 a = r[s.at[0]];
        return f([=](auto L) {
            const auto na = arith::lift(L, a.normal);
            const auto e = excess(L, a, c);
            return arith::ratio{e * e, arith::dot(na, na)};
        });
    }
    if (s.n == 2) {
        const plane3 a = r[s.at[0]], b = r[s.at[1]];
        return f([=](auto L) {
            const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal);
            const auto ea = excess(L, a, c), eb = excess(L, b, c);
            const auto g0 = arith::dot(na, na), g1 = arith::dot(na, nb), g2 = arith::dot(nb, nb);
            const auto w = arith::cross(na, nb);
            return arith::ratio{(g2 * ea - g1 * eb) * ea + (g0 * eb - g1 * ea) * eb, arith::dot(w, w)};
        });
    }
    const plane3 a = r[s.at[0]], b = r[s.at[1]], e = r[s.at[2]];
    return f([=](auto L) {
        const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal), ne = arith::lift(L, e.normal);
        const auto one = L(1.0);
        const auto d = arith::det3(na, nb, ne);
        const auto v = arith::scaled(arith::cross(nb, ne), L(a.offset) * one) + arith::scaled(arith::cross(ne, na), L(b.offset) * one) +
                       arith::scaled(arith::cross(na, nb), L(e.offset) * one);
        const auto g = arith::scaled(arith::lift(L, c), d) - v;
        return arith::ratio{arith::dot(g, g), d * d};
    });
}

// Is the squared distance under set s at most rad^2: rad^2 S - P >= 0 (degree 4, 6 or 8)?
template <class K>
[[nodiscard]] constexpr bool within(K& k, const rows& r, point3 c, double rad, const active& s) {
    return with_distance(r, c, s, [&](auto q) {
        return k.sgn([=](auto L) {
            const auto x = q(L);
            return L(rad) * L(rad) * x.den - x.num;
        }) != sign::negative;
    });
}

// The rows' side of c: beyond[x] iff e_x > 0; with rad, whether c is beyond some row with the
// whole ball beyond it too (`apart`, which ends the walk).
struct sides {
    std::array<bool, most> beyond{};
    bool outside = false, apart = false;
};
template <class K>
[[nodiscard]] constexpr sides sides_of(K& k, const rows& r, point3 c, const double* rad = nullptr) {
    sides s;
    for (unsigned x = 0; x < r.n && !s.apart; ++x) {
        const plane3 h = r[x];
        if (k.sgn([=](auto L) { return excess(L, h, c); }) != sign::positive) continue;
        s.beyond[x] = s.outside = true;
        if (rad == nullptr) continue;
        const double q = *rad;
        s.apart = k.sgn([=](auto L) {
            const auto e = excess(L, h, c);
            const auto n = arith::lift(L, h.normal);
            return e * e - L(q) * L(q) * arith::dot(n, n);
        }) == sign::positive;
    }
    return s;
}

// Plain double's projection of c onto the rows by the dual active-set method (Goldfarb and Idnani,
// "A numerically stable dual method for solving strictly convex quadratic programs", Mathematical
// Programming 27 (1983), on min |x - c|^2 / 2): the active set it ends with, or none where it finds
// no feasible point or does not settle within its step limit. A guess for try_set, which proves or
// refutes it: nothing here needs an error bound.
[[nodiscard]] constexpr found projected_set(const rows& r, point3 c) {
    using v3d = std::array<double, 3>;
    const auto normal = [&](unsigned i) { return v3d{r[i].normal.x, r[i].normal.y, r[i].normal.z}; };
    const auto dot3 = [](const v3d& a, const v3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    v3d x{c.x, c.y, c.z};
    unsigned set[3] = {0, 0, 0}, n = 0;
    double u[3] = {0, 0, 0};
    const auto excess_at = [&](unsigned i) { return dot3(normal(i), x) - r[i].offset; };
    for (unsigned step = 0; step < 4 * r.n + 8; ++step) {
        // the row most violated, by e_i / |n_i|, beyond rounding (2^-45 of its terms' magnitude)
        unsigned p = r.n;
        double worst = 0.0;
        for (unsigned i = 0; i < r.n; ++i) {
            if ((n > 0 && set[0] == i) || (n > 1 && set[1] == i) || (n > 2 && set[2] == i)) continue;
            const v3d m = normal(i);
            const double e = excess_at(i);
            const double size = (m[0] < 0 ? -m[0] : m[0]) * (x[0] < 0 ? -x[0] : x[0]) +
                                (m[1] < 0 ? -m[1] : m[1]) * (x[1] < 0 ? -x[1] : x[1]) +
                                (m[2] < 0 ? -m[2] : m[2]) * (x[2] < 0 ? -x[2] : x[2]) + (r[i].offset < 0 ? -r[i].offset : r[i].offset);
            if (!(e > 0x1p-45 * size)) continue;
            const double score = e * e / dot3(m, m);
            if (score > worst) worst = score, p = i;
        }
        if (p == r.n) {
            if (n == 0) return {};
            return {true, active{n, {set[0], set[1], set[2]}}};
        }
        // steps toward row p: x - t z with z = n_p less its part in the active rows' span, the
        // multipliers u - t q (G q = N n_p), until p is active or a multiplier reaches zero
        double up = 0.0;
        for (int partial = 0; partial < 4; ++partial) {
            const v3d np = normal(p);
            double g[3][3], b[3], q[3] = {0, 0, 0};
            for (unsigned a = 0; a < n; ++a) {
                b[a] = dot3(normal(set[a]), np);
                for (unsigned e = 0; e < n; ++e) g[a][e] = dot3(normal(set[a]), normal(set[e]));
            }
            if (n == 1) {
                if (!(g[0][0] > 0.0)) return {};
                q[0] = b[0] / g[0][0];
            } else if (n == 2) {
                const double det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
                if (det == 0.0) return {};
                q[0] = (g[1][1] * b[0] - g[0][1] * b[1]) / det, q[1] = (g[0][0] * b[1] - g[1][0] * b[0]) / det;
            } else if (n == 3) { // Cramer's rule on G's columns
                const arith::v3<double> g0{g[0][0], g[1][0], g[2][0]}, g1{g[0][1], g[1][1], g[2][1]}, g2{g[0][2], g[1][2], g[2][2]};
                const arith::v3<double> rhs{b[0], b[1], b[2]};
                const double det = arith::det3(g0, g1, g2);
                if (det == 0.0) return {};
                q[0] = arith::det3(rhs, g1, g2) / det, q[1] = arith::det3(g0, rhs, g2) / det, q[2] = arith::det3(g0, g1, rhs) / det;
            }
            v3d z = np;
            for (unsigned a = 0; a < n; ++a) {
                const v3d m = normal(set[a]);
                for (unsigned e = 0; e < 3; ++e) z[e] -= q[a] * m[e];
            }
            const double zz = dot3(z, z);
            const bool dependent = n == 3 || !(zz > 0x1p-60 * dot3(np, np));
            constexpr double inf = __builtin_huge_val();
            double t1 = inf;
            unsigned block = 3;
            for (unsigned a = 0; a < n; ++a)
                if (q[a] > 0.0 && u[a] / q[a] < t1) t1 = u[a] / q[a], block = a;
            const double t2 = dependent ? inf : excess_at(p) / zz;
            if (!(t1 < inf) && !(t2 < inf)) return {}; // no feasible point (or not settled)
            const double t = t2 < t1 ? t2 : t1;
            if (!dependent)
                for (unsigned e = 0; e < 3; ++e) x[e] -= t * z[e];
            for (unsigned a = 0; a < n; ++a) u[a] -= t * q[a];
            up += t;
            if (t2 <= t1) { // p is active
                set[n] = p, u[n] = up, ++n;
                break;
            }
            for (unsigned a = block; a + 1 < n; ++a) set[a] = set[a + 1], u[a] = u[a + 1]; // the blocking row leaves
            --n;
        }
    }
    return {};
}

// The projection's active set for c outside the rows (s: their sides, s.outside), proven by k's
// signs: with more than eight rows, outside the exact pass, first the set of plain double's
// projection (projected_set); then the set that plain double's search names; then every set in
// turn. No set: the rows are empty. (Measured: with six rows, a frustum's, the search costs less
// than the projection; with the projection first in the exact pass too, a ball near a 26-DOP took
// 12.1 us against 10.5 us before the projection, 8.5 us as here.)
template <class K>
[[nodiscard]] constexpr found nearest(K& k, const rows& r, point3 c, const sides& s) {
    if (r.n > 8 && !arith::exact_pass_at_run_time<K>() && !__builtin_is_constant_evaluated()) // (a guess at extreme
        if (const found g = projected_set(r, c); g.any)                                       // scales may overflow,
            if (const found f = try_set(k, r, c, g.set); f.any) return f;                     // which constant evaluation refuses)
    if constexpr (!std::is_same_v<K, arith::approx_kernel>) {
        arith::approx_kernel a;
        const sides guess_sides = sides_of(a, r, c);
        if (const found g = search(a, r, c, guess_sides.beyond); g.any)
            if (const found f = try_set(k, r, c, g.set); f.any) return f;
    }
    return search(k, r, c, s.beyond);
}

// Does the ball meet the set of the m half-spaces (finite: the caller checks)?
template <class K>
[[nodiscard]] constexpr bool meets(K& k, const plane3* planes, int m, const sphere3& ball) {
    const rows r(planes, m);
    if (r.empty) return false;
    const point3 c = ball.center;
    const double rad = ball.radius;
    const sides s = sides_of(k, r, c, &rad);
    if (s.apart) return false;
    if (!s.outside) return true; // c in every half-space
    const found f = nearest(k, r, c, s);
    return f.any && within(k, r, c, rad, f.set); // no set: the rows are empty
}

// Is the ball inside each of the m half-spaces (finite: the caller checks)?
template <class K>
[[nodiscard]] constexpr bool inside(K& k, const plane3* planes, int m, const sphere3& ball) {
    for (unsigned x = 0; x < static_cast<unsigned>(m); ++x) {
        const plane3 h = planes[x];
        const point3 c = ball.center;
        const double rad = ball.radius;
        if (k.sgn([=](auto L) { return excess(L, h, c); }) == sign::positive) return false;
        if (k.sgn([=](auto L) {
                const auto e = excess(L, h, c);
                const auto n = arith::lift(L, h.normal);
                return e * e - L(rad) * L(rad) * arith::dot(n, n);
            }) == sign::negative)
            return false;
    }
    return true;
}

} // namespace ball_rows

// The classic culling test, an alternative to frustum_sphere (method::frustum_sphere_planes): the
// ball is culled when it lies wholly beyond one of the six planes, n . c - d > |r| |n|, in plain
// double. It keeps balls near the frustum's edges and corners that miss it (no plane alone has them
// beyond), and decides within rounding near each plane.
// Source: Akenine-Moeller, Haines, Hoffman et al., Real-Time Rendering, 4th ed. (2018), chapter 22
// (frustum/sphere intersection).
[[nodiscard]] constexpr bool frustum_sphere_planes(const frustum3& f, const sphere3& s) {
    if (!is_finite(s.center) || !is_finite(s.radius)) return false;
    const double rad = s.radius < 0.0 ? -s.radius : s.radius;
    for (const plane3& h : f.planes) {
        if (!is_finite(h.normal) || !is_finite(h.offset)) return false;
        const double e = dot(h.normal, s.center - point3{0, 0, 0}) - h.offset;
        if (e > rad * arith::sqrt(dot(h.normal, h.normal))) return false;
    }
    return true;
}

} // namespace incidence::detail
