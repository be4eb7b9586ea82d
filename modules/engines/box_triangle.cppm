// aabb3 against triangle3 (closed box, closed triangle; a collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): separating axes. Two disjoint convex polytopes, one of them a solid box,
// are strictly separated along one of 13 axes: the box's three face normals, the triangle's
// normal, and the nine cross products of a box axis with a triangle edge. Each axis test picks
// the box corner that is extreme along the axis (by the exact signs of the axis' components)
// and compares it with the triangle's projection as exact signs: box axes are comparisons of
// coordinates, edge axes are signs of degree 2 (e_i x f . (v - corner)), the normal axis a sign
// of degree 3 (orient3d-like). A box that is flat along some axis (a rectangle, a segment or a
// point) is not a solid, and the 13 axes no longer suffice for it; such a box is its rectangle's
// two triangles, decided by the exact triangle_triangle test. At run time the filter pass first
// tries the same 13 axes rounded, each widened by a proven error bound (rounded_axes_decide); the
// signs decide what that leaves, on the axes it left unclear only (the exact pass at run time asks
// the stage which those are), after a vertex in the closed box has said yes (comparisons).
// Source: Akenine-Moeller, "Fast 3D triangle-box overlap testing", JGT 6(1), 2001 (the 13 axes);
// Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5 (the separating axis theorem).
// Approximate tier: Akenine-Moeller's test in plain double (box centre and half sizes, the nine
// edge axes with projected radii, the box-axis overlap, then the plane-box test). Error bound:
// for inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is
// within 2^-40 of its permanent (the sets touch or nearly touch); tests/query/aabb_triangle.cpp
// checks it.
export module incidence.detail:engines.box_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.triangle;
import :intersects.triangle_pairs;

export namespace incidence::detail {

namespace box_triangle {
[[nodiscard]] constexpr double at(const point3& p, int i) { return i == 0 ? p.x : (i == 1 ? p.y : p.z); }
[[nodiscard]] constexpr point3 with(point3 p, int i, double v) {
    if (i == 0) p.x = v;
    else if (i == 1) p.y = v;
    else p.z = v;
    return p;
}
} // namespace box_triangle

// Which points of the box a triangle must reach: any point of the closed box, or one of its
// interior (touching the boundary alone does not count: contains(mesh3, aabb3) asks this of the
// mesh's triangles). For the interior the same 13 axes decide, with touching projections counted
// as separated: the triangle misses the open box iff the origin is outside the interior of the
// Minkowski difference, whose facet normals are these axes (a full box is needed; a flat one has
// no interior).
enum class box_reach : unsigned char { closed, interior };

namespace box_triangle {
// Does an axis sign s put the triangle beyond the box on the side `side` of that axis?
template <box_reach Reach>
[[nodiscard]] constexpr bool beyond(sign s, sign side) {
    if constexpr (Reach == box_reach::closed) return s == side;
    else return s == side || s == sign::zero;
}

// The separating axes of the box and the hull of NV points (a triangle: 13, a tetrahedron: 25)
// with the projections rounded, each widened by a rigorous bound on its rounding error, before any
// sign: no when some axis certainly separates, yes when none can (every projection overlaps by more
// than its bound), uncertain when that is not clear. The axes: the box's three face normals (coordinate
// comparisons, exact), the normals of the given faces, and each given edge crossed with each box
// axis; for a solid box and a triangle or a tetrahedron (every edge and face listed) no axis
// separating means the sets meet, and a zero normal is never called clear. It decides the same
// axis tests as the signs, so where it decides it agrees with them.
// Frame: every point relative to the box's min corner m, so the box is [0, w] with w = max - m,
// and an axis a projects it onto [sum min(a_k, 0) w_k, sum max(a_k, 0) w_k] (no rounded centre).
// Error bounds (u = 2^-53): an edge axis value f_j x_l - f_l x_j (f = q - p, x = v - m, every
// difference rounded once) is off by at most about 4u (|f_j x_l| + |f_l x_j|) <= 8u F X, the box's
// end by 4u (|f_j| w_l + |f_l| w_j) <= 8u F W, their difference by u more (F, X, W: sums of every
// |f|, |x| and w, at least the largest of each): 2^-48 F (X + W) covers every edge axis. A face
// normal n = (b - a) x (c - a) is off by 4u N_k per component (N_k its permanent); n . x and the
// box's end with the rounded n by about 12u sum N_k (X_k + w_k) (X_k: the sum of |x_k| over the
// points): 2^-48 times that. Every difference is finite with magnitude at most 2^300, so nothing
// overflows; an underflowed product or difference is off by at most 2^-1074, and carried through
// degree 3 below 2^300 that stays under 2^-700, which is added to every bound. A NaN cannot
// decide. Source: Akenine-Moeller, "Fast 3D triangle-box overlap testing", JGT 6(1), 2001 (the
// axes); Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed. (2002), section 3.1
// (the bounds). Run time only (the callers check). With `unclear` given and -1 returned, the axes
// whose projections are not clearly overlapping get their bit in *unclear (edge e with box axis i:
// bit 3 e + i; face g: bit 3 NE + g; every bit when the stage stopped early): the others cannot
// separate, so the signs need not test them.
template <int NV, int NE, int NF>
[[nodiscard]] constexpr certainty rounded_hull_axes_decide(const aabb3& b, const point3 (&v)[NV], const int (&edges)[NE][2],
                                                           const int (&faces)[NF][3], unsigned* unclear = nullptr) {
    static_assert(3 * NE + NF <= 32);
    if (unclear) *unclear = ~0u;
    for (int i = 0; i < 3; ++i) { // the box's face normals: comparisons, exact
        const double lo = at(b.min, i), hi = at(b.max, i);
        bool above = true, below = true;
        for (int p = 0; p < NV; ++p) above = above && at(v[p], i) > hi, below = below && at(v[p], i) < lo;
        if (above || below) return certainty::no;
    }
    const double m[3] = {b.min.x, b.min.y, b.min.z};
    const double w[3] = {b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z};
    if (!(w[0] > 0.0 && w[1] > 0.0 && w[2] > 0.0)) return certainty::uncertain; // flat or inverted: these axes do not suffice
    double x[NV][3], f[NE][3];                                                  // point minus the box's min corner; edge e: v[q] - v[p]
    double Xk[3] = {0.0, 0.0, 0.0}, F = 0.0; // sums of |x| per axis and of |f|: NaN or infinite with any of them
    for (int p = 0; p < NV; ++p)
        for (int i = 0; i < 3; ++i) x[p][i] = at(v[p], i) - m[i], Xk[i] += arith::abs(x[p][i]);
    for (int e = 0; e < NE; ++e)
        for (int i = 0; i < 3; ++i) f[e][i] = at(v[edges[e][1]], i) - at(v[edges[e][0]], i), F += arith::abs(f[e][i]);
    const double X = Xk[0] + Xk[1] + Xk[2], W = w[0] + w[1] + w[2];
    if (!(X <= 0x1p300 && F <= 0x1p300 && W <= 0x1p300)) return certainty::uncertain; // also NaN
    constexpr double tiny = 0x1p-700;
    unsigned mask = 0;
    const double err = 0x1p-48 * F * (X + W) + tiny;
    for (int e = 0; e < NE; ++e)
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3, l = (i + 2) % 3;
            const double fj = f[e][j], fl = f[e][l];
            // axis components: l is f_j, j is -f_l; none when both are zero (a rounded difference
            // is zero only when exact), as in the signs
            if (fj == 0.0 && fl == 0.0) continue;
            const double hi = (fj > 0.0 ? fj : 0.0) * w[l] - (fl < 0.0 ? fl : 0.0) * w[j];
            const double lo = (fj < 0.0 ? fj : 0.0) * w[l] - (fl > 0.0 ? fl : 0.0) * w[j];
            double mn = __builtin_huge_val(), mx = -__builtin_huge_val();
            for (int p = 0; p < NV; ++p) {
                if (p == edges[e][1]) continue; // projects where the edge's first point does
                const double P = fj * x[p][l] - fl * x[p][j];
                mn = P < mn ? P : mn, mx = P > mx ? P : mx;
            }
            if (mn - hi > err || mx - lo < -err) return certainty::no;
            if (!(mn - hi < -err && mx - lo > err)) mask |= 1u << (3 * e + i);
        }
    for (int g = 0; g < NF; ++g) {
        const int a = faces[g][0], fb = faces[g][1], fc = faces[g][2];
        double n[3], perm = 0.0, hi = 0.0, lo = 0.0;
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3, l = (i + 2) % 3;
            const double s = (at(v[fb], j) - at(v[a], j)) * (at(v[fc], l) - at(v[a], l));
            const double r = (at(v[fb], l) - at(v[a], l)) * (at(v[fc], j) - at(v[a], j));
            n[i] = s - r;
            perm += (arith::abs(s) + arith::abs(r)) * (Xk[i] + w[i]);
        }
        for (int i = 0; i < 3; ++i) {
            hi += n[i] > 0.0 ? n[i] * w[i] : 0.0;
            lo += n[i] < 0.0 ? n[i] * w[i] : 0.0;
        }
        double mn = __builtin_huge_val(), mx = -__builtin_huge_val();
        for (int p = 0; p < NV; ++p) {
            if (p == fb || p == fc) continue; // project where the face's first point does
            const double q = n[0] * x[p][0] + n[1] * x[p][1] + n[2] * x[p][2];
            mn = q < mn ? q : mn, mx = q > mx ? q : mx;
        }
        const double en = 0x1p-48 * perm + tiny;
        if (mn - hi > en || mx - lo < -en) return certainty::no;
        if (!(mn - hi < -en && mx - lo > en)) mask |= 1u << (3 * NE + g);
    }
    if (mask == 0) return certainty::yes;
    if (unclear) *unclear = mask;
    return certainty::uncertain;
}
// The triangle's 13 axes (every tier's box-triangle test, and the box-tetrahedron test's faces).
[[nodiscard]] constexpr certainty rounded_axes_decide(const aabb3& b, const point3 (&v)[3], unsigned* unclear = nullptr) {
    constexpr int edges[3][2] = {{0, 1}, {1, 2}, {2, 0}}, faces[1][3] = {{0, 1, 2}};
    return rounded_hull_axes_decide(b, v, edges, faces, unclear);
}

// ExactPassStage: whether the exact pass at run time asks the rounded stage for the unclear axes
// (box-tetrahedron's faces do not: slower there; bench/NOTES.md, "Measured choices").
template <box_reach Reach, bool ExactPassStage = true, class K>
[[nodiscard]] constexpr bool box_meets(K& k, const aabb3& b, const triangle3& t) {
    for (int i = 0; i < 3; ++i)
        if (!(at(b.min, i) <= at(b.max, i))) return false; // inverted or NaN box
    // The box is read only through comparisons when the triangle is a point (no normal, no
    // edge axes): an infinite bound must still give no.
    if (!finite(b.min) || !finite(b.max)) return false;
    const point3 v[3] = {t.a, t.b, t.c};
    // In a filter pass (arith::rounded_stage_applies) the rounded axes first (the box's axes
    // included); the signs where they are not clear, and only on the axes it left unclear (the
    // others cannot separate). The exact pass at run time asks the stage for those axes too.
    unsigned unclear = ~0u; // bit 3 e + i: edge e with box axis i; bit 9: the normal
    if constexpr (Reach == box_reach::closed) {
        if (arith::rounded_stage_applies<K>() || (ExactPassStage && arith::exact_pass_at_run_time<K>()))
            if (const certainty r = rounded_axes_decide(b, v, &unclear); r != certainty::uncertain) return r == certainty::yes;
        // a vertex in the closed box: they meet (comparisons, exact; a triangle with a NaN or an
        // infinity is no shape, which the signs below turn into no)
        if (finite(t))
            for (const point3& p : v) {
                bool in = true;
                for (int i = 0; i < 3 && in; ++i)
                    in = arith::compare(k, at(p, i), at(b.min, i)) != sign::negative &&
                         arith::compare(k, at(p, i), at(b.max, i)) != sign::positive;
                if (in) return true;
            }
    }
    constexpr sign up = sign::positive, down = sign::negative;
    // The box's face normals: comparisons of coordinates.
    for (int i = 0; i < 3; ++i) {
        const double lo = at(b.min, i), hi = at(b.max, i);
        if (beyond<Reach>(arith::compare(k, at(v[0], i), hi), up) && beyond<Reach>(arith::compare(k, at(v[1], i), hi), up) &&
            beyond<Reach>(arith::compare(k, at(v[2], i), hi), up))
            return false;
        if (beyond<Reach>(arith::compare(k, at(v[0], i), lo), down) && beyond<Reach>(arith::compare(k, at(v[1], i), lo), down) &&
            beyond<Reach>(arith::compare(k, at(v[2], i), lo), down))
            return false;
    }
    for (int i = 0; i < 3; ++i)
        if (at(b.min, i) == at(b.max, i)) { // flat box: its rectangle's two triangles (no interior)
            if constexpr (Reach == box_reach::interior) return false;
            const int j = (i + 1) % 3, l = (i + 2) % 3;
            auto corner = [&](bool hj, bool hl) {
                point3 p = b.min;
                p = with(p, j, hj ? at(b.max, j) : at(b.min, j));
                return with(p, l, hl ? at(b.max, l) : at(b.min, l));
            };
            const point3 c00 = corner(false, false), c10 = corner(true, false), c11 = corner(true, true), c01 = corner(false, true);
            return intersects(k, triangle3{c00, c10, c11}, t) || intersects(k, triangle3{c00, c11, c01}, t);
        }
    // The triangle's normal n = (b - a) x (c - a): every vertex projects to n . a.
    if (unclear >> 9 & 1u) {
        const point3 a = t.a, bb = t.b, c = t.c;
        // A triangle in a coordinate plane (its vertices share that coordinate) has its normal's
        // other two components exactly zero: comparisons say so, where the filter could not.
        // (Only for a finite triangle: a NaN or infinity is left to the signs, which see it and make
        // the exact tier say no.)
        const bool fin = finite(t.a) && finite(t.b) && finite(t.c);
        auto shared = [fin](double p, double q, double r) { return fin && p == q && p == r; };
        const bool in_plane[3] = {shared(a.x, bb.x, c.x), shared(a.y, bb.y, c.y), shared(a.z, bb.z, c.z)};
        auto known_zero = [&](int i) { return in_plane[(i + 1) % 3] || in_plane[(i + 2) % 3]; };
        sign s[3];
        s[0] = known_zero(0)
                   ? sign::zero
                   : k.sgn([=](auto L) { return (L(bb.y) - L(a.y)) * (L(c.z) - L(a.z)) - (L(bb.z) - L(a.z)) * (L(c.y) - L(a.y)); });
        s[1] = known_zero(1)
                   ? sign::zero
                   : k.sgn([=](auto L) { return (L(bb.z) - L(a.z)) * (L(c.x) - L(a.x)) - (L(bb.x) - L(a.x)) * (L(c.z) - L(a.z)); });
        s[2] = known_zero(2)
                   ? sign::zero
                   : k.sgn([=](auto L) { return (L(bb.x) - L(a.x)) * (L(c.y) - L(a.y)) - (L(bb.y) - L(a.y)) * (L(c.x) - L(a.x)); });
        if (s[0] != sign::zero || s[1] != sign::zero || s[2] != sign::zero) {
            // the corner farthest along n (hi) and along -n (lo)
            point3 hi = b.min, lo = b.max;
            for (int i = 0; i < 3; ++i)
                if (s[i] == sign::positive) hi = with(hi, i, at(b.max, i)), lo = with(lo, i, at(b.min, i));
            auto side = [&](point3 q) {
                return k.sgn([=](auto L) {
                    const auto u = arith::lift(L, bb) - arith::lift(L, a), w = arith::lift(L, c) - arith::lift(L, a);
                    return arith::dot(arith::cross(u, w), arith::lift(L, a) - arith::lift(L, q));
                });
            };
            if (beyond<Reach>(side(hi), up) || beyond<Reach>(side(lo), down)) return false;
        }
    }
    // The nine axes e_i x f, f = q - p an edge, o the third vertex: with (i, j, l) cyclic,
    // e_i x f = f_j e_l - f_l e_j, so (e_i x f) . w = f_j w_l - f_l w_j.
    for (int e = 0; e < 3; ++e) {
        const point3 p = v[e], q = v[(e + 1) % 3], o = v[(e + 2) % 3];
        for (int i = 0; i < 3; ++i) {
            if (!(unclear >> (3 * e + i) & 1u)) continue; // clearly overlapping on this axis
            const int j = (i + 1) % 3, l = (i + 2) % 3;
            const sign fj = arith::compare(k, at(q, j), at(p, j)), fl = arith::compare(k, at(q, l), at(p, l));
            if (fj == sign::zero && fl == sign::zero) continue; // the edge is parallel to e_i: no axis
            // axis component l is f_j, component j is -f_l
            point3 hi = b.min, lo = b.max;
            if (fj == sign::positive) hi = with(hi, l, at(b.max, l)), lo = with(lo, l, at(b.min, l));
            if (fl == sign::negative) hi = with(hi, j, at(b.max, j)), lo = with(lo, j, at(b.min, j));
            const double pj = at(p, j), pl = at(p, l), qj = at(q, j), ql = at(q, l);
            auto proj = [&](point3 x, point3 c) {
                const double xj = at(x, j), xl = at(x, l), cj = at(c, j), cl = at(c, l);
                return k.sgn([=](auto L) { return (L(qj) - L(pj)) * (L(xl) - L(cl)) - (L(ql) - L(pl)) * (L(xj) - L(cj)); });
            };
            if (beyond<Reach>(proj(p, hi), up) && beyond<Reach>(proj(o, hi), up)) return false;
            if (beyond<Reach>(proj(p, lo), down) && beyond<Reach>(proj(o, lo), down)) return false;
        }
    }
    return true;
}
} // namespace box_triangle
// Does the triangle reach the box's interior (min < max on every axis; a flat or inverted box has
// none)? A collinear triangle is its hull, so a segment p q asks it as the triangle p q q.
template <class K>
[[nodiscard]] constexpr bool meets_interior(K& k, const aabb3& b, const triangle3& t) {
    return box_triangle::box_meets<box_reach::interior>(k, b, t);
}

// Akenine-Moeller's triangle-box overlap test in plain double (approximate tier).
[[nodiscard]] constexpr bool aabb_triangle_sat(const aabb3& b, const triangle3& t) {
    if (!(b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z)) return false;
    const point3 c{0.5 * b.min.x + 0.5 * b.max.x, 0.5 * b.min.y + 0.5 * b.max.y, 0.5 * b.min.z + 0.5 * b.max.z};
    const double h[3] = {0.5 * b.max.x - 0.5 * b.min.x, 0.5 * b.max.y - 0.5 * b.min.y, 0.5 * b.max.z - 0.5 * b.min.z};
    const vec3 v[3] = {t.a - c, t.b - c, t.c - c};
    const vec3 f[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    auto get = [](vec3 a, int i) { return i == 0 ? a.x : (i == 1 ? a.y : a.z); };
    for (int e = 0; e < 3; ++e)
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3, l = (i + 2) % 3;
            // axis e_i x f: components (j: -f_l, l: f_j)
            const double aj = -get(f[e], l), al = get(f[e], j);
            double mn = __builtin_huge_val(), mx = -__builtin_huge_val();
            for (const vec3& w : v) {
                const double s = aj * get(w, j) + al * get(w, l);
                mn = s < mn ? s : mn, mx = s > mx ? s : mx;
            }
            const double r = h[j] * (aj < 0 ? -aj : aj) + h[l] * (al < 0 ? -al : al);
            if (mn > r || mx < -r) return false;
        }
    for (int i = 0; i < 3; ++i) {
        const double x0 = get(v[0], i), x1 = get(v[1], i), x2 = get(v[2], i);
        const double mn = x0 < x1 ? (x0 < x2 ? x0 : x2) : (x1 < x2 ? x1 : x2), mx = x0 > x1 ? (x0 > x2 ? x0 : x2) : (x1 > x2 ? x1 : x2);
        if (mn > h[i] || mx < -h[i]) return false;
    }
    const vec3 n = cross(f[0], f[1]);
    const double d = dot(n, v[0]);
    const double r = h[0] * (n.x < 0 ? -n.x : n.x) + h[1] * (n.y < 0 ? -n.y : n.y) + h[2] * (n.z < 0 ? -n.z : n.z);
    return !(d > r || d < -r);
}

} // namespace incidence::detail
