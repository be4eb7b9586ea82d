// point3 against tetrahedron3 (a closed solid tetrahedron; coplanar vertices give their hull),
// contains(tetrahedron, point | segment | triangle | tetrahedron), and the engine every
// tetrahedron pair shares.
// Semantics: a point on a face, an edge or a vertex counts.
// Method (exact tiers): p beyond the tetrahedron's bounding box rejects (comparisons, exact;
// Ericson, Real-Time Collision Detection (2005), section 4.2.1). Then, with
// o = orient3d(a, b, c, d) != 0, p lies in the closed solid iff each of the four orient3d values
// with p in place of one vertex (p's barycentric coordinates times o) has the sign of o or is
// zero; degree 3 each. With o = 0 the hull of the four coplanar points is
// the union of the four faces (Caratheodory's theorem in the plane), so p is tested against each
// face with point_triangle. For a lone point o itself is not needed: the four values sum to o,
// so their signs alone decide (tetra::point_in_closed).
// The other pairs (tetrahedron_meets below): a convex set X meets the closed solid T iff X meets
// one of T's faces or X lies inside T, which one point of X then decides; the boundary triangles
// plus the inside test, the method for a closed mesh. When X has vertices, first the signs of its
// vertices against T's face planes: a vertex inside T says yes, all vertices strictly outside one
// face plane says no (that face's normal separates).
// For a segment, a triangle or a tetrahedron, a filter pass at run time first evaluates the same
// face planes rounded, each value widened by a proven error bound (tetra::rounded_locate; for a
// triangle, its own plane and the tetrahedron's edges through it come before them:
// rounded_triangle_side), then looks for an edge clearly through a face (rounded_crossing) and a
// clearly separating edge axis (rounded_edge_axes_apart); the signs decide what that leaves. A
// line or a ray has its own stage (rounded_line_meets: its side of each edge). (For a lone point,
// as in point_tetrahedron and contains, the stage measured slower than the signs alone.)
// Source: Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates" (1997) for orient3d; Ericson, Real-Time Collision Detection (2005), section 5.4.2
// (point in tetrahedron by the four face orientations); CGAL's Tetrahedron_3 do_intersect
// structures its pairs the same way (a point inside, else a face meets).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/point_tetrahedron.cpp).
//
// obb3 against tetrahedron3 (closed box, read as the parallelepiped its axes span; closed solid
// tetrahedron, coplanar vertices give their hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): the box centre inside the solid (four orient3d signs) says yes; otherwise
// the box meets the tetrahedron iff it meets one of its four faces (the 13-axis obb_triangle
// test), since it cannot then lie inside.
// contains(box, tetrahedron): the four vertices in the box. contains(tetrahedron, box): with
// o = orient3d != 0, for each face plane N . (x - q) (N the face's normal, degree 2) the box's
// least value tau N . (c - q) - sum_j h_j |N . a_j| >= 0, tau the side of the opposite vertex
// (degree 4, the support function of the box, so no corner is ever formed). A coplanar tetrahedron
// is its planar hull: the box must lie in the plane (N . (c - q) = 0, h_j N . a_j = 0) and within
// each line through two vertices that has the other two on one side, m = N x (v - u) (degree 5);
// collinear vertices give a segment, one point a point.
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Gottschalk, Lin and
// Manocha, "OBBTree", SIGGRAPH 1996, section 5, for the face tests.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/obb_tetrahedron.cpp).
//
// tetrahedron3 against tetrahedron3 (closed solids; coplanar vertices give their hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): bounding boxes apart reject (comparisons, exact; Ericson, Real-Time
// Collision Detection (2005), section 4.2.1). Then: each one's vertices against the other's face
// planes (orient3d signs, degree 3): a vertex inside the other solid says yes, all four strictly
// beyond one face plane say no. Otherwise neither lies inside the other, so they meet iff a face of
// one meets a face of the other (the 16 triangle_triangle tests). In a filter pass at run time the
// rounded stage of point_tetrahedron.cppm comes first (face planes, an edge clearly through a face,
// the edge axes; each value widened by a proven error bound).
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Ganovelli, Ponchio
// and Rocchini, "Fast tetrahedron-tetrahedron overlap algorithm", JGT 7(2), 2002 use the same
// face-plane rejections first.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/tetrahedron_tetrahedron.cpp).
export module incidence.detail:engines.tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.separating_axes;
import :engines.triangle;

export namespace incidence::detail {

namespace tetra {

[[nodiscard]] constexpr point3 vertex(const tetrahedron3& t, int i) { return i == 0 ? t.a : (i == 1 ? t.b : (i == 2 ? t.c : t.d)); }

// orient3d(a, b, c, d): positive, negative, or zero for coplanar vertices.
template <class K>
[[nodiscard]] constexpr sign orientation(K& k, const tetrahedron3& t) {
    const point3 a = t.a, b = t.b, c = t.c, d = t.d;
    return k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, d); });
}
// orient3d with p in place of vertex i: the sign of o when p is on vertex i's side of face i.
template <class K>
[[nodiscard]] constexpr sign side(K& k, const tetrahedron3& t, int i, point3 p) {
    point3 v[4] = {t.a, t.b, t.c, t.d};
    v[i] = p;
    const point3 a = v[0], b = v[1], c = v[2], d = v[3];
    return k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, d); });
}
// p in the closed solid t of orientation o != 0.
template <class K>
[[nodiscard]] constexpr bool in_solid(K& k, const tetrahedron3& t, sign o, point3 p) {
    for (int i = 0; i < 4; ++i) {
        const sign s = side(k, t, i, p);
        if (s != o && s != sign::zero) return false;
    }
    return true;
}
enum class located { inside, outside, unknown };
// The points pts[0..n) against the solid t (orientation o != 0): inside when one of them lies in
// t; outside when `hull` (the points span the other shape) and all of them lie strictly beyond one
// face plane; else unknown.
template <class K>
[[nodiscard]] constexpr located locate(K& k, const tetrahedron3& t, sign o, const point3* pts, int n, bool hull) {
    const sign beyond = o == sign::positive ? sign::negative : sign::positive;
    bool all_beyond[4] = {true, true, true, true};
    for (int j = 0; j < n; ++j) {
        bool in = true;
        for (int i = 0; i < 4; ++i) {
            const sign s = side(k, t, i, pts[j]);
            if (s != beyond) all_beyond[i] = false;
            if (s != o && s != sign::zero) in = false;
        }
        if (in) return located::inside;
    }
    if (hull)
        for (bool b : all_beyond)
            if (b) return located::outside;
    return located::unknown;
}

// The rounded stage of the tetrahedron pairs (a filter pass at run time, arith::rounded_stage_applies):
// t's four face planes evaluated in double, each value widened by a proven bound on its rounding
// error, before any sign. For each point of pts[0..n) (n <= 8): +1 when it lies clearly inside t
// (strictly inside every face plane by more than the bound), -1 when clearly beyond some face
// plane, 0 when neither is clear. `apart` says that every point lies clearly beyond one face plane
// (t and the points' hull are then disjoint). Every entry 0 and `apart` false when a face's
// opposite vertex is not clearly off its plane (a flat or nearly flat t), or a value is far off or
// not finite. Where it decides, it agrees with the orient3d signs of in_solid and locate. The
// values themselves stay in the result for rounded_crossing (an edge of the other shape clearly
// through a face of t).
// Frame: x = p - t.a, rounded once. Face i (opposite vertex i) has base b and normal
// n = (c - b) x (d - b), each difference rounded once; its values n . x - n . x_b. Error bounds
// (u = 2^-53): n_k is off by at most about 4u N_k (N_k = |s| + |r|, the permanent of its two
// products), n . x by 8u sum N_k X_k (X_k: the largest |x_k| over t's vertices and the points), and
// the difference of two such by 18u sum N_k X_k (its own rounding included): 2^-48 sum N_k X_k
// (32u) covers it. Every |x_k| at most 2^300, so nothing overflows; an underflowed product is off
// by at most 2^-1074, which stays under 2^-700 through the degree-3 values. Source: Ericson,
// Real-Time Collision Detection (2005), section 5.4.2 (the four face orientations); Higham,
// Accuracy and Stability of Numerical Algorithms, 2nd ed. (2002), section 3.1 (the bounds).
struct rounded_located {
    int status[8];
    bool apart;
    // For rounded_crossing: w[i][j], point j's value against face i, signed so that t's inside is
    // positive, off by at most err[i]; `crossings` when every value and bound is at most 2^500.
    double w[4][8];
    double err[4];
    bool crossings;
};
[[nodiscard]] constexpr rounded_located rounded_locate(const tetrahedron3& t, const point3* pts, int n) {
    rounded_located r{};
    const point3* const v[4] = {&t.a, &t.b, &t.c, &t.d}; // in place: a copy's stores stall wide loads
    double xv[4][3], xp[8][3], X[3] = {0.0, 0.0, 0.0};
    bool in_range = true; // every |x_k| <= 2^300 (false for NaN)
    auto rel = [&](point3 p, double* x) {
        x[0] = p.x - t.a.x, x[1] = p.y - t.a.y, x[2] = p.z - t.a.z;
        for (int k = 0; k < 3; ++k) {
            const double a = arith::abs(x[k]);
            in_range = in_range && a <= 0x1p300;
            X[k] = max2(X[k], a);
        }
    };
    for (int i = 0; i < 4; ++i) rel(*v[i], xv[i]);
    for (int j = 0; j < n; ++j) rel(pts[j], xp[j]);
    if (!in_range) return r;
    bool inside[8] = {true, true, true, true, true, true, true, true};
    double largest = 0.0;
    for (int i = 0; i < 4; ++i) {
        const int ib = (i + 1) & 3, ic = (i + 2) & 3, id = (i + 3) & 3;
        const double e[2][3] = {{v[ic]->x - v[ib]->x, v[ic]->y - v[ib]->y, v[ic]->z - v[ib]->z},
                                {v[id]->x - v[ib]->x, v[id]->y - v[ib]->y, v[id]->z - v[ib]->z}};
        double nrm[3], perm = 0.0;
        for (int k = 0; k < 3; ++k) {
            const int j = (k + 1) % 3, l = (k + 2) % 3;
            const double sp = e[0][j] * e[1][l], rp = e[0][l] * e[1][j];
            nrm[k] = sp - rp;
            perm += (arith::abs(sp) + arith::abs(rp)) * X[k];
        }
        const double err = 0x1p-48 * perm + 0x1p-700;
        const double base = nrm[0] * xv[ib][0] + nrm[1] * xv[ib][1] + nrm[2] * xv[ib][2];
        auto value = [&](const double* x) { return (nrm[0] * x[0] + nrm[1] * x[1] + nrm[2] * x[2]) - base; };
        const double opposite = value(xv[i]);
        if (!(opposite > err || opposite < -err)) return rounded_located{}; // flat, or not clear
        const double side = opposite > 0.0 ? 1.0 : -1.0;
        bool all_beyond = true; // without branches: on random input each would be a coin toss
        for (int j = 0; j < n; ++j) {
            const double w = side * value(xp[j]);
            r.w[i][j] = w;
            largest = max2(largest, arith::abs(w));
            const bool beyond = w < -err;
            r.status[j] |= -int(beyond);
            all_beyond = all_beyond & beyond;
            inside[j] = inside[j] & (w > err);
        }
        r.err[i] = err;
        largest = max2(largest, err);
        r.apart = r.apart | all_beyond;
    }
    for (int j = 0; j < n; ++j) r.status[j] = inside[j] ? 1 : r.status[j];
    r.crossings = largest <= 0x1p500;
    return r;
}

// What rounded_locate's table decides alone for the points' hull (n points): no, apart (every point
// clearly beyond one face plane), yes, they meet (a point clearly inside t), or uncertain.
[[nodiscard]] constexpr certainty rounded_verdict(const rounded_located& r, int n) {
    if (r.apart) return certainty::no;
    for (int j = 0; j < n; ++j)
        if (r.status[j] == 1) return certainty::yes;
    return certainty::uncertain;
}

// Does the segment from point p to point q of rounded_locate's table clearly cross t's boundary
// inside a face? For face i with the two values clearly of opposite signs (a < 0 < b, or the
// reverse), the crossing point X lies on face i's plane strictly between p and q, and its value
// against face j is (a d - b c) / (a - b) (c, d: the values of p and q against face j); X lies in
// the closed face, so the segment meets t, when that is clearly positive for the three other
// faces. Error bound on M = a d - b c from values off by at most E_i (a, b) and E_j (c, d):
// (|a| + |b|) E_j + (|c| + |d| + 2 E_j) E_i for the values, 2^-50 (|a d| + |b c|) for the two
// products and the difference (about 2u), the whole widened by 1/8 for the rounding of the bound
// itself, plus 2^-1060 for underflow (values at most 2^500, so no product overflows).
[[nodiscard]] constexpr bool rounded_crossing(const rounded_located& r, int p, int q) {
    if (!r.crossings) return false;
    for (int i = 0; i < 4; ++i) {
        const double a = r.w[i][p], b = r.w[i][q], ei = r.err[i];
        if (!((a < -ei && b > ei) || (a > ei && b < -ei))) continue;
        const double sa = a < 0.0 ? -1.0 : 1.0; // the sign of a - b
        bool in_face = true;
        for (int j = 0; j < 4 && in_face; ++j) {
            if (j == i) continue;
            const double c = r.w[j][p], d = r.w[j][q], ej = r.err[j];
            const double ad = a * d, bc = b * c;
            const double bound = ((arith::abs(a) + arith::abs(b)) * ej + (arith::abs(c) + arith::abs(d) + 2.0 * ej) * ei +
                                  0x1p-50 * (arith::abs(ad) + arith::abs(bc))) *
                                     1.125 +
                                 0x1p-1060;
            in_face = sa * (ad - bc) > bound;
        }
        if (in_face) return true;
    }
    return false;
}

// Is there a clearly separating axis among the cross products of an edge of the hull of a[0..na)
// with an edge of the hull of b[0..nb) (na, nb <= 4: every pair of points is taken as an edge,
// which covers the edges of a point, a segment, a triangle or a tetrahedron)? The separating-axis
// test's edge axes, rounded, each widened by a proven bound. Frame: x = p - a[0], rounded once;
// an axis is e x f with e and f differences of inputs rounded once. The axis component k is off
// by about 4u M_k (M_k = |e_j f_l| + |e_l f_j|), a projection x . (e x f) by 8u sum M_k X_k
// (X_k: the largest |x_k|), the difference of two projections by 18u sum M_k X_k: 2^-48 sum M_k X_k
// plus 2^-700 covers it, as in rounded_locate (every |x_k| and every edge component at most 2^300).
// Only a separation is claimed: where no axis separates clearly, nothing is known. Source:
// Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5 (the edge-edge axes); Higham,
// Accuracy and Stability of Numerical Algorithms, 2nd ed. (2002), section 3.1 (the bounds).
[[nodiscard]] constexpr bool rounded_edge_axes_apart(const point3* a, int na, const point3* b, int nb) {
    double x[8][3], X[3] = {0.0, 0.0, 0.0};
    bool in_range = true;
    const int n = na + nb;
    for (int p = 0; p < n; ++p) {
        const point3 v = p < na ? a[p] : b[p - na];
        x[p][0] = v.x - a[0].x, x[p][1] = v.y - a[0].y, x[p][2] = v.z - a[0].z;
        for (int k = 0; k < 3; ++k) {
            const double m = arith::abs(x[p][k]);
            in_range = in_range && m <= 0x1p299; // so every edge component is at most 2^300
            X[k] = max2(X[k], m);
        }
    }
    if (!in_range) return false;
    for (int p0 = 0; p0 < na; ++p0)
        for (int p1 = p0 + 1; p1 < na; ++p1) {
            const double e[3] = {a[p1].x - a[p0].x, a[p1].y - a[p0].y, a[p1].z - a[p0].z};
            for (int q0 = 0; q0 < nb; ++q0)
                for (int q1 = q0 + 1; q1 < nb; ++q1) {
                    const double f[3] = {b[q1].x - b[q0].x, b[q1].y - b[q0].y, b[q1].z - b[q0].z};
                    double axis[3], perm = 0.0;
                    for (int k = 0; k < 3; ++k) {
                        const int j = (k + 1) % 3, l = (k + 2) % 3;
                        const double sp = e[j] * f[l], rp = e[l] * f[j];
                        axis[k] = sp - rp;
                        perm += (arith::abs(sp) + arith::abs(rp)) * X[k];
                    }
                    const double err = 0x1p-48 * perm + 0x1p-700;
                    double lo_a = __builtin_huge_val(), hi_a = -__builtin_huge_val();
                    double lo_b = __builtin_huge_val(), hi_b = -__builtin_huge_val();
                    for (int p = 0; p < na; ++p) {
                        const double proj = axis[0] * x[p][0] + axis[1] * x[p][1] + axis[2] * x[p][2];
                        lo_a = min2(lo_a, proj), hi_a = max2(hi_a, proj);
                    }
                    for (int p = na; p < n; ++p) {
                        const double proj = axis[0] * x[p][0] + axis[1] * x[p][1] + axis[2] * x[p][2];
                        lo_b = min2(lo_b, proj), hi_b = max2(hi_b, proj);
                    }
                    if (lo_b - hi_a > err || lo_a - hi_b > err) return true;
                }
        }
    return false;
}

// The line (or, when `ray`, the ray) through o with direction d against the closed tetrahedron t,
// rounded, each value widened by a proven bound: yes when it clearly meets t, no when it clearly
// misses, uncertain when that is not clear (and for a zero d, a flat t that the line lies in, values far
// off or not finite). Frame: x_i = v_i - o, rounded once. For an edge (v_i, v_j),
// s_ij = d . (x_i x x_j) is the side of the line on which the edge passes (Pluecker's relative
// orientation of two lines). The line crosses the plane of face (a, b, c) at a point of the face,
// transversally, iff s_ab, s_bc and s_ca share a sign (their sum is d . n, n the face normal), so
// all three clearly of sign S says the line meets t; every face with two clearly opposite values
// says it misses (a line that meets t meets a face, where the three are of one sign or zero). For
// the ray the crossing's parameter is D / (d . n), D = x_a . (x_b x x_c) (o against the face's
// plane): a face clearly of sign S is crossed ahead of o when D is clearly of sign S, behind when
// clearly of sign -S; the ray misses t when every face is clearly missed by the line or crossed
// behind o (a ray that meets t meets a face at a parameter of at least 0). Error bounds (u = 2^-53):
// a component k of x_i x x_j is off by about 4u M_k (M_k = |x_i,l x_j,m| + |x_i,m x_j,l|, the
// permanent of its two products), a value s_ij or D by about 8u sum |y_k| M_k (y = d or x_a): 2^-48
// sum |y_k| M_k covers it; every |x_i,k| and |d_k| at most 2^300, so nothing overflows, and
// underflowed products stay under 2^-700. Source: Pluecker coordinates for line-triangle
// crossing, Ericson, Real-Time Collision Detection (2005), section 5.3.4 (scalar triple products
// of a line against a triangle's edges); Higham, Accuracy and Stability of Numerical Algorithms,
// 2nd ed. (2002), section 3.1 (the bounds).
[[nodiscard]] constexpr certainty rounded_line_meets(const tetrahedron3& t, point3 o, vec3 d, bool ray) {
    const point3* const v[4] = {&t.a, &t.b, &t.c, &t.d}; // in place: a copy's stores stall wide loads
    const double y[3] = {d.x, d.y, d.z};
    double x[4][3];
    bool in_range = true; // every |x_i,k| and |d_k| at most 2^300 (false for NaN)
    for (int i = 0; i < 4; ++i) {
        x[i][0] = v[i]->x - o.x, x[i][1] = v[i]->y - o.y, x[i][2] = v[i]->z - o.z;
        for (int k = 0; k < 3; ++k) in_range = in_range && arith::abs(x[i][k]) <= 0x1p300;
    }
    for (int k = 0; k < 3; ++k) in_range = in_range && arith::abs(y[k]) <= 0x1p300;
    if (!in_range) return certainty::uncertain;
    // The six edges (0,1) (0,2) (0,3) (1,2) (1,3) (2,3): their cross products, permanents, s and bound.
    constexpr int ei[6] = {0, 0, 0, 1, 1, 2}, ej[6] = {1, 2, 3, 2, 3, 3};
    double c[6][3], m[6][3], s[6], es[6];
    for (int e = 0; e < 6; ++e) {
        const double* a = x[ei[e]];
        const double* b = x[ej[e]];
        double val = 0.0, perm = 0.0;
        for (int k = 0; k < 3; ++k) {
            const int l = (k + 1) % 3, n = (k + 2) % 3;
            const double sp = a[l] * b[n], rp = a[n] * b[l];
            c[e][k] = sp - rp;
            m[e][k] = arith::abs(sp) + arith::abs(rp);
            val += y[k] * c[e][k];
            perm += arith::abs(y[k]) * m[e][k];
        }
        s[e] = val;
        es[e] = 0x1p-48 * perm + 0x1p-700;
    }
    // Face opposite vertex f as the cycle (a, b, c): its edges (a, b), (b, c) and (a, c) (whose s
    // is -s_ca), and the vertex a and edge (b, c) for D.
    constexpr int fe[4][3] = {{3, 5, 4}, {1, 5, 2}, {0, 4, 2}, {0, 3, 1}};
    constexpr int fa[4] = {1, 0, 0, 0}, fbc[4] = {5, 5, 4, 3};
    bool misses = true;
    for (int f = 0; f < 4; ++f) {
        int pos = 0, neg = 0;
        for (int q = 0; q < 3; ++q) {
            const double w = q == 2 ? -s[fe[f][q]] : s[fe[f][q]], err = es[fe[f][q]];
            pos += w > err;
            neg += w < -err;
        }
        if (pos > 0 && neg > 0) continue; // the line misses this face
        if (pos < 3 && neg < 3) {
            misses = false; // not clear
            continue;
        }
        if (!ray) return certainty::yes;
        const double S = pos == 3 ? 1.0 : -1.0;
        const double* a = x[fa[f]];
        const int e = fbc[f];
        const double D = a[0] * c[e][0] + a[1] * c[e][1] + a[2] * c[e][2];
        const double eD = 0x1p-48 * (arith::abs(a[0]) * m[e][0] + arith::abs(a[1]) * m[e][1] + arith::abs(a[2]) * m[e][2]) + 0x1p-700;
        if (S * D > eD) return certainty::yes; // crossed ahead of o
        if (S * D < -eD) continue;             // crossed behind o
        misses = false;
    }
    return misses ? certainty::no : certainty::uncertain;
}

// The triangle f[0..3) against the tetrahedron t from f's side, rounded, each value widened by a
// proven bound: no when every vertex of t lies clearly on one side of f's plane (that normal
// separates), yes when an edge of t clearly crosses f's plane inside f (its end points clearly on
// opposite sides, and the edge's line clearly through f's interior: the three values
// (q - p) . ((a - p) x (b - p)) over f's edges (a, b) clearly of one sign, as in
// rounded_line_meets), uncertain when neither is clear (and for a collinear f, values far off or not
// finite). Plane values: n . (v - f[0]) with n = (f[1] - f[0]) x (f[2] - f[0]), every difference
// rounded once, off by at most about 8u sum N_k X_k (N_k: the permanent of n_k, X_k: the largest
// |v_k - f[0]_k|); an edge value is an orient3d of three rounded differences, off by at most
// about 9u sum |y_k| M_k (y = q - p, M_k the permanent of the cross product's component k,
// Shewchuk's bound for orient3d is 7u plus higher order); 2^-48 (32u) times the permanent, plus
// 2^-700, covers both (every difference at most 2^300 in magnitude). Source: Moeller, "A fast
// triangle-triangle intersection test", JGT 2(2), 1997 (the plane rejection); Ericson, Real-Time
// Collision Detection (2005), section 5.3.4 (a line through a triangle by scalar triple products).
[[nodiscard]] constexpr certainty rounded_triangle_side(const point3* f, const tetrahedron3& t) {
    const point3* const v[4] = {&t.a, &t.b, &t.c, &t.d}; // in place: a copy's stores stall wide loads
    double x[4][3], X[3] = {0.0, 0.0, 0.0};
    bool in_range = true; // every |difference| at most 2^299 (false for NaN)
    for (int i = 0; i < 4; ++i) {
        x[i][0] = v[i]->x - f[0].x, x[i][1] = v[i]->y - f[0].y, x[i][2] = v[i]->z - f[0].z;
        for (int k = 0; k < 3; ++k) {
            const double m = arith::abs(x[i][k]);
            in_range = in_range && m <= 0x1p299;
            X[k] = max2(X[k], m);
        }
    }
    const double e[2][3] = {{f[1].x - f[0].x, f[1].y - f[0].y, f[1].z - f[0].z}, {f[2].x - f[0].x, f[2].y - f[0].y, f[2].z - f[0].z}};
    for (int k = 0; k < 3; ++k) in_range = in_range && arith::abs(e[0][k]) <= 0x1p299 && arith::abs(e[1][k]) <= 0x1p299;
    if (!in_range) return certainty::uncertain;
    double nrm[3], perm = 0.0;
    for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3, l = (k + 2) % 3;
        const double sp = e[0][j] * e[1][l], rp = e[0][l] * e[1][j];
        nrm[k] = sp - rp;
        perm += (arith::abs(sp) + arith::abs(rp)) * X[k];
    }
    const double err = 0x1p-48 * perm + 0x1p-700;
    double w[4];
    int above = 0, below = 0;
    for (int i = 0; i < 4; ++i) {
        w[i] = nrm[0] * x[i][0] + nrm[1] * x[i][1] + nrm[2] * x[i][2];
        above += w[i] > err;
        below += w[i] < -err;
    }
    if (above == 4 || below == 4) return certainty::no;
    if (above == 0 || below == 0) return certainty::uncertain;
    for (int p = 0; p < 4; ++p)
        for (int q = p + 1; q < 4; ++q) {
            if (!((w[p] > err && w[q] < -err) || (w[p] < -err && w[q] > err))) continue;
            const double y[3] = {v[q]->x - v[p]->x, v[q]->y - v[p]->y, v[q]->z - v[p]->z};
            double a[3][3]; // f's vertices relative to v[p]
            for (int c = 0; c < 3; ++c) a[c][0] = f[c].x - v[p]->x, a[c][1] = f[c].y - v[p]->y, a[c][2] = f[c].z - v[p]->z;
            int pos = 0, neg = 0;
            for (int c = 0; c < 3; ++c) {
                const double* g = a[c];
                const double* h = a[(c + 1) % 3];
                double val = 0.0, pm = 0.0;
                for (int k = 0; k < 3; ++k) {
                    const int j = (k + 1) % 3, l = (k + 2) % 3;
                    const double sp = g[j] * h[l], rp = g[l] * h[j];
                    val += y[k] * (sp - rp);
                    pm += arith::abs(y[k]) * (arith::abs(sp) + arith::abs(rp));
                }
                const double ev = 0x1p-48 * pm + 0x1p-700;
                pos += val > ev;
                neg += val < -ev;
            }
            if (pos == 3 || neg == 3) return certainty::yes;
        }
    return certainty::uncertain;
}

// The closed convex set x (finite, checked by the caller) against the closed tetrahedron t
// (finite): pts[0..n) are points of x, its vertices when `hull`; meets(f) says whether x meets
// the triangle f.
template <class K, class Meets>
[[nodiscard]] constexpr bool tetrahedron_meets(K& k, const tetrahedron3& t, const Meets& meets, const point3* pts, int n, bool hull) {
    // The rounded stage first, for a hull (x's vertices; for a lone point of x such as a ray's
    // origin it measured slower than the signs alone).
    if (arith::rounded_stage_applies<K>() && hull && n <= 8) {
        // a triangle: its plane first, and t's edges through it, before t's four planes (one plane
        // is often apart alone; bench/NOTES.md, "Measured choices")
        if (n == 3)
            if (const certainty s = rounded_triangle_side(pts, t); s != certainty::uncertain) return s == certainty::yes;
        const rounded_located r = rounded_locate(t, pts, n);
        if (const certainty d = rounded_verdict(r, n); d != certainty::uncertain) return d == certainty::yes;
        // x is convex: the segment between two of its points lies in it
        if (n <= 4) {
            for (int p = 0; p < n; ++p)
                for (int q = p + 1; q < n; ++q)
                    if (rounded_crossing(r, p, q)) return true;
            const point3 v[4] = {t.a, t.b, t.c, t.d};
            if (rounded_edge_axes_apart(pts, n, v, 4)) return false;
        }
    }
    const sign o = orientation(k, t);
    if (o != sign::zero) {
        const located l = locate(k, t, o, pts, n, hull);
        if (l != located::unknown) return l == located::inside;
    }
    for (int i = 0; i < 4; ++i)
        if (meets(t.face(i))) return true;
    return false;
}

} // namespace tetra

namespace tetra {
// p in the closed tetrahedron t of orientation o (its faces when o is zero).
template <class K>
[[nodiscard]] constexpr bool in_closed(K& k, const tetrahedron3& t, sign o, point3 p) {
    if (o != sign::zero) return in_solid(k, t, o, p);
    for (int i = 0; i < 4; ++i)
        if (linear_triangle(k, as_linear(p), t.face(i))) return true;
    return false;
}
// One point p in the closed tetrahedron t, without t's own orientation o: the four volumes with p
// in place of one vertex (side(), p's barycentric coordinates times o) sum to o, the determinant
// being linear in each row. So two of them with opposite nonzero signs put p outside whatever o
// is; signs in {0, s} with some s != 0 give o = s and p inside; four zeros give o = 0 (a flat t,
// whose faces decide). The volumes as triple products of d_i = v_i - p around two shared cross
// products c = d_0 x d_1 and e = d_2 x d_3: vertex 3's is c . d_2, vertex 2's -(c . d_3),
// vertex 1's d_0 . e, vertex 0's -(d_1 . e). One orient3d fewer than o and side(), and the two
// cross products lifted into the filter once (bench/NOTES.md, "Measured choices").
// Source: Ericson, Real-Time Collision Detection (2005), section 3.4 (barycentric coordinates as
// signed volumes).
template <class K>
[[nodiscard]] constexpr bool point_in_closed(K& k, const tetrahedron3& t, point3 p) {
    auto diff = [=](point3 v) { return [=](auto L) { return arith::lift(L, v) - arith::lift(L, p); }; };
    auto crossed = [=](point3 u, point3 v) { return [=](auto L) { return arith::cross(diff(u)(L), diff(v)(L)); }; };
    const auto d0 = diff(t.a), d1 = diff(t.b), d2 = diff(t.c), d3 = diff(t.d);
    const auto f01 = crossed(t.a, t.b);
    const arith::lifted_once<K, decltype(f01)> c{f01};
    // v[i]: the sign of vertex i's volume; v[2] and v[0] are read negated
    sign v[4];
    v[3] = k.sgn([=, &c](auto L) { return arith::dot(c(L), d2(L)); });
    v[2] = -k.sgn([=, &c](auto L) { return arith::dot(c(L), d3(L)); });
    if (v[3] != sign::zero && v[2] == -v[3]) return false;
    const auto f23 = crossed(t.c, t.d);
    const arith::lifted_once<K, decltype(f23)> e{f23};
    v[1] = k.sgn([=, &e](auto L) { return arith::dot(d0(L), e(L)); });
    v[0] = -k.sgn([=, &e](auto L) { return arith::dot(d1(L), e(L)); });
    sign seen = sign::zero;
    for (const sign x : v) {
        if (x == sign::zero) continue;
        if (seen != sign::zero && x != seen) return false;
        seen = x;
    }
    if (seen != sign::zero) return true;
    for (int i = 0; i < 4; ++i) // o = 0: the hull of four coplanar points is the union of its faces
        if (linear_triangle(k, as_linear(p), t.face(i))) return true;
    return false;
}
// Every point of pts[0..n) in the closed tetrahedron t: by convexity, t contains their hull.
template <class K>
[[nodiscard]] constexpr bool contains_all(K& k, const tetrahedron3& t, const point3* pts, int n) {
    if (!finite(t)) return false;
    for (int j = 0; j < n; ++j)
        if (!finite(pts[j]) || boxes_apart(k, pts[j], t)) return false; // a point beyond t's box
    if (n == 1) return point_in_closed(k, t, pts[0]);
    const sign o = orientation(k, t);
    for (int j = 0; j < n; ++j)
        if (!in_closed(k, t, o, pts[j])) return false;
    return true;
}
} // namespace tetra

[[nodiscard]] constexpr bool finite(const obb3& b) {
    return finite(b.center) && finite(b.axes[0]) && finite(b.axes[1]) && finite(b.axes[2]) && finite(b.half_extents[0]) &&
           finite(b.half_extents[1]) && finite(b.half_extents[2]);
}

namespace tetra {
// Is the box on the closed side tau f >= 0 of the affine function f(x) = n . (x - q), n(L) a lifted
// vector? Its least value there is tau n . (c - q) - sum_j h_j |n . a_j| (both terms of one degree).
template <class K, class Normal>
[[nodiscard]] constexpr bool box_on_side(K& k, const obb3& b, const Normal& normal, point3 q, double tau) {
    const point3 c = b.center;
    const vec3 a0 = b.axes[0], a1 = b.axes[1], a2 = b.axes[2];
    const double h0 = b.half_extents[0], h1 = b.half_extents[1], h2 = b.half_extents[2];
    return k.sgn([=](auto L) {
        const auto n = normal(L);
        const auto reach = L(h0) * sat::magnitude(arith::dot(n, arith::lift(L, a0))) +
                           L(h1) * sat::magnitude(arith::dot(n, arith::lift(L, a1))) +
                           L(h2) * sat::magnitude(arith::dot(n, arith::lift(L, a2)));
        return L(tau) * arith::dot(n, arith::lift(L, c) - arith::lift(L, q)) - reach;
    }) != sign::negative;
}
// Does the box lie in the zero set of the affine function f? zero(x, true) says f(x) = 0 for a
// point, zero(x, false) that f's linear part vanishes on the vector x: the centre, and each axis
// of nonzero extent.
template <class Zero>
[[nodiscard]] constexpr bool box_on_zero(const obb3& b, const Zero& zero) {
    if (!zero(b.center, true)) return false;
    for (unsigned j = 0; j < 3; ++j)
        if (b.half_extents[j] != 0.0 && !zero(point3{b.axes[j].x, b.axes[j].y, b.axes[j].z}, false)) return false;
    return true;
}
} // namespace tetra

// One canonical order (lexicographic on the twelve numbers), so every tier is symmetric.
[[nodiscard]] constexpr bool before(const tetrahedron3& s, const tetrahedron3& t) {
    const double x[12] = {s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z, s.c.x, s.c.y, s.c.z, s.d.x, s.d.y, s.d.z};
    const double y[12] = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z, t.d.x, t.d.y, t.d.z};
    return lex_compare(x, y, 12) <= 0;
}

} // namespace incidence::detail
