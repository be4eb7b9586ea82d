// The separating-axis engine shared by the OBB pairs (box against box, segment, point, ray,
// line and triangle). Each shape is a zonotope (a centre plus bounded generators: a box has its
// three axes, a segment its direction, a point none), optionally with one unbounded direction
// (a ray, a line), or a triangle (three vertices). Two closed convex polytopes are disjoint iff
// some axis separates their projections; when the shapes together span space, the cross products
// of every two generating directions (box axes, segment, ray or line directions, triangle edges)
// are enough. Flat and lower-dimensional configurations (a box of zero extent, a box given with
// dependent axes, a point against a segment) add the in-plane normals n x g, the generators
// themselves, the offset normals (g x d) x g and the coordinate axes, so the test stays exact.
// Every comparison is the sign of one polynomial: twice the distance between the projected
// centres against the sum of twice the projected radii, |w . (2 c_b - 2 c_a)| - sum 2 h_i |w . g_i|,
// with absolute values (see arith::abs) and no division; a lifted 1.0 balances the degrees.
// Source: Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5 (the separating axis
// theorem and its 15 box-box axes); Ericson, Real-Time Collision Detection (2005), sections
// 4.4.1 and 5.2.1 (the axis sets for box-triangle and box-segment); the flat cases follow from
// the axes being the facet normals of the Minkowski difference (ibid., section 5.2.1).
//
// obb3 against obb3 (closed boxes; the axes are read exactly as given, so a box is the
// parallelepiped they span, and a box of zero extent is a rectangle, a segment or a point).
// Semantics: touching at a corner, along an edge or on a face counts.
// Method (exact tiers): the 15 separating axes (the face normals of each parallelepiped, a_j x a_k,
// which are its axes when they are orthonormal, and the nine cross products a_i x b_j). Each axis
// is one sign of degree 4: |w . (2 c_b - 2 c_a)| against twice the sum of the projected radii
// h_i |w . a_i| (see separating_axes for the flat cases). Before them the three coordinate axes,
// a cheap certificate for boxes whose bounding boxes are apart; and each of the 15 signs is first
// compared with a bound from the inputs' largest magnitudes (sat::box_box_static_bounds), the
// filter's own permanents only where that bound is too coarse.
// contains(obb3, obb3): the support functions compared on the same axes (sat::zonotope_contains).
// Source: Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5 (15 axes).
// Approximate tier: the same signs (coordinate axes included) in plain double. Error bound: for
// inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is within
// 2^-40 of its permanent (the sets touch or nearly touch); tests/query/obb_obb.cpp checks it.
module;
#include <type_traits>
#include <optional>
export module incidence.detail:engines.separating_axes;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;

export namespace incidence::detail::sat {

// The direction to - from, taken exactly in every number type.
struct direction {
    vec3 to;
    vec3 from;
};
enum class reach : unsigned char { none, ray, line };

// A zonotope: { (cp + cq) / 2 + sum_i t_i g_i : |t_i| <= (hp_i + hq_i) / 2 }, plus the unbounded
// direction u (t >= 0 for a ray, any t for a line) when r != none.
struct zonotope {
    point3 cp, cq;
    direction g[3];
    double hp[3], hq[3];
    int n = 0;
    direction u{};
    reach r = reach::none;
};

[[nodiscard]] constexpr zonotope zonotope_of(const obb3& b) {
    zonotope z{b.center, b.center, {}, {}, {}, 3, {}, reach::none};
    for (unsigned i = 0; i < 3; ++i) {
        z.g[i] = {b.axes[i], vec3{0, 0, 0}};
        z.hp[i] = z.hq[i] = b.half_extents[i];
    }
    return z;
}
[[nodiscard]] constexpr zonotope zonotope_of(const aabb3& b) {
    return {b.min,
            b.max,
            {direction{{1, 0, 0}, {0, 0, 0}}, direction{{0, 1, 0}, {0, 0, 0}}, direction{{0, 0, 1}, {0, 0, 0}}},
            {b.max.x, b.max.y, b.max.z},
            {-b.min.x, -b.min.y, -b.min.z},
            3,
            {},
            reach::none};
}
[[nodiscard]] constexpr zonotope zonotope_of(const segment3& s) {
    return {s.a, s.b, {direction{{s.b.x, s.b.y, s.b.z}, {s.a.x, s.a.y, s.a.z}}, {}, {}}, {1, 0, 0}, {0, 0, 0}, 1, {}, reach::none};
}
[[nodiscard]] constexpr zonotope zonotope_of(const point3& p) { return {p, p, {}, {}, {}, 0, {}, reach::none}; }
[[nodiscard]] constexpr zonotope zonotope_of(const ray3& r) {
    return {r.origin, r.origin, {}, {}, {}, 0, direction{r.direction, {0, 0, 0}}, reach::ray};
}
[[nodiscard]] constexpr zonotope zonotope_of(const line3& l) {
    return {l.origin, l.origin, {}, {}, {}, 0, direction{l.direction, {0, 0, 0}}, reach::line};
}

// A box's extents must be ordered numbers (NaN or a negative extent: an empty box).
[[nodiscard]] constexpr bool well_formed(const obb3& b) {
    return b.half_extents[0] >= 0.0 && b.half_extents[1] >= 0.0 && b.half_extents[2] >= 0.0;
}
[[nodiscard]] constexpr bool well_formed(const aabb3& b) { return b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z; }

// |x| in any number type (found by argument-dependent lookup for the tests' own types).
template <class T>
[[nodiscard]] constexpr T magnitude(const T& x) {
    using arith::abs;
    return abs(x);
}

template <class L>
[[nodiscard]] constexpr auto lift(L l, const direction& d) {
    return arith::lift(l, d.to) - arith::lift(l, d.from);
}
template <class L>
[[nodiscard]] constexpr auto centre2(L l, const zonotope& z) {
    return arith::lift(l, z.cp) + arith::lift(l, z.cq);
}
// Twice the projected radius of z's bounded part along w (unused generators have zero extent).
template <class L, class W>
[[nodiscard]] constexpr auto radius2(L l, const zonotope& z, const W& w) {
    auto term = [&](unsigned i) { return (l(z.hp[i]) + l(z.hq[i])) * magnitude(arith::dot(w, lift(l, z.g[i]))); };
    return term(0) + term(1) + term(2);
}

// The generating directions of a pair, in one list: a's bounded ones, b's bounded ones, b's
// unbounded one, a triangle's three edges.
struct directions {
    direction d[7];
    bool live[7];
    int n = 0;
    int unbounded = -1; // the index of a ray's or line's direction

    constexpr void add(const direction& x, bool is_live) {
        d[n] = x;
        live[n] = is_live;
        ++n;
    }
};
[[nodiscard]] constexpr bool same(const vec3& a, const vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
constexpr void add_generators(directions& ds, const zonotope& z) {
    for (int i = 0; i < z.n; ++i) {
        const auto u = static_cast<unsigned>(i);
        ds.add(z.g[u], z.hp[u] != -z.hq[u] && !same(z.g[u].to, z.g[u].from));
    }
    if (z.r != reach::none) {
        ds.unbounded = ds.n;
        ds.add(z.u, !same(z.u.to, z.u.from));
    }
}

// Candidate axes, each a generic function of the lift: w(L).
template <class L>
[[nodiscard]] constexpr auto axis_cross(L l, const direction& a, const direction& b) {
    return arith::cross(lift(l, a), lift(l, b));
}

// Visit the axes until `separates(w, perpendicular)` says yes; true when one did. `perpendicular`
// says the axis is perpendicular to the unbounded direction by construction (u x g, (g x u) x u),
// where w . u is identically zero and must not be left to rounding. `offset(L)` is the difference
// of a point of the second shape and a point of the first (any two points: it is only used when
// every live direction is parallel, so both shapes lie on parallel lines).
template <class K, class Separates, class Offset>
[[nodiscard]] constexpr bool some_axis_separates(K& k, const directions& ds, bool skip_triangle_pairs, int first_edge,
                                                 const Separates& separates, const Offset& offset) {
    // 1. the cross products of two directions
    for (int i = 0; i < ds.n; ++i)
        for (int j = i + 1; j < ds.n; ++j) {
            if (skip_triangle_pairs && i >= first_edge && !(i == first_edge && j == first_edge + 1)) continue;
            const direction a = ds.d[i], b = ds.d[j];
            if (separates([=](auto L) { return axis_cross(L, a, b); }, i == ds.unbounded || j == ds.unbounded)) return true;
        }
    // 2. If three live directions are independent, those axes were complete.
    for (int i = 0; i < ds.n; ++i)
        for (int j = i + 1; j < ds.n; ++j)
            for (int m = j + 1; m < ds.n; ++m) {
                if (!ds.live[i] || !ds.live[j] || !ds.live[m]) continue;
                const direction a = ds.d[i], b = ds.d[j], c = ds.d[m];
                if (!arith::is_zero(k, [=](auto L) { return arith::det3(lift(L, a), lift(L, b), lift(L, c)); })) return false;
            }
    // 3. Flat configurations: in-plane normals (a x b) x c, the directions, (a x d) x a, the
    //    coordinate axes.
    for (int i = 0; i < ds.n; ++i)
        for (int j = i + 1; j < ds.n; ++j)
            for (int m = 0; m < ds.n; ++m) {
                const direction a = ds.d[i], b = ds.d[j], c = ds.d[m];
                if (separates([=](auto L) { return arith::cross(axis_cross(L, a, b), lift(L, c)); }, m == ds.unbounded)) return true;
            }
    for (int i = 0; i < ds.n; ++i) {
        const direction a = ds.d[i];
        if (separates([=](auto L) { return lift(L, a); }, false)) return true;
        if (separates([=](auto L) { return arith::cross(arith::cross(lift(L, a), offset(L)), lift(L, a)); }, i == ds.unbounded))
            return true;
    }
    for (int i = 0; i < 3; ++i) {
        const vec3 e{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0};
        if (separates([=](auto L) { return arith::lift(L, e); }, false)) return true;
    }
    return false;
}

// Zonotope a (bounded) against zonotope b (bounded, or with a ray or line direction): the general
// path alone, for a caller that tried box_box_fast already; zonotopes_intersect tries it first.
template <class K>
[[nodiscard]] constexpr bool zonotopes_intersect_general(K& k, const zonotope& a, const zonotope& b) {
    directions ds;
    add_generators(ds, a);
    add_generators(ds, b);
    auto separates = [&](auto axis, bool perpendicular) {
        if (b.r != reach::none && !perpendicular) {
            const direction u = b.u;
            const sign s = k.sgn([=](auto L) { return arith::dot(axis(L), lift(L, u)); });
            if (s != sign::zero) {
                if (b.r == reach::line) return false;
                // a ray reaching +infinity along w: separated iff it starts beyond a's far end
                const sign t = k.sgn([=](auto L) {
                    const auto w = axis(L);
                    const auto gap = L(1.0) * arith::dot(w, centre2(L, b) - centre2(L, a));
                    return s == sign::positive ? gap - radius2(L, a, w) : gap + radius2(L, a, w);
                });
                return t == s;
            }
        }
        return k.sgn([=](auto L) {
            const auto w = axis(L);
            return L(1.0) * magnitude(arith::dot(w, centre2(L, b) - centre2(L, a))) - radius2(L, a, w) - radius2(L, b, w);
        }) == sign::positive;
    };
    auto offset = [=](auto L) { return centre2(L, b) - centre2(L, a); };
    return !some_axis_separates(k, ds, false, ds.n, separates, offset);
}
template <class K>
[[nodiscard]] constexpr bool zonotopes_intersect(K& k, const zonotope& a, const zonotope& b) {
    if (a.n == 3 && b.n == 3 && b.r == reach::none)
        if (const certainty f = box_box_fast(k, a, b); f != certainty::uncertain) return f == certainty::yes;
    return zonotopes_intersect_general(k, a, b);
}

// Is the bounded zonotope `in` inside the bounded zonotope `out`? Support functions: in lies in out
// iff h_in(w) <= h_out(w) for every w, that is |w . (2 c_in - 2 c_out)| + 2 r_in(w) <= 2 r_out(w).
// h_out - h_in is linear on each cone of the arrangement of the planes w . g = 0 (g any generator
// of either), so it is enough to test the rays of that arrangement: the same axes as the
// separating test (the cross products of two generators when three are independent; in flat and
// lower-dimensional configurations the normal n = a x b, the in-plane normals n x g, the
// generators, (g x d) x g and the coordinate axes, where the difference must vanish on the
// lineality space). Every axis is a necessary condition, so the extra axes never hurt.
// Source: Schneider, Convex Bodies: The Brunn-Minkowski Theory (2014), theorem 1.7.1 (K in L iff
// h_K <= h_L); the zonotope's normal fan, ibid. section 3.5.
template <class K>
[[nodiscard]] constexpr bool zonotope_contains(K& k, const zonotope& out, const zonotope& in) {
    directions ds;
    add_generators(ds, out);
    add_generators(ds, in);
    auto pokes_out = [&](auto axis, bool) {
        return k.sgn([=](auto L) {
            const auto w = axis(L);
            return L(1.0) * magnitude(arith::dot(w, centre2(L, in) - centre2(L, out))) + radius2(L, in, w) - radius2(L, out, w);
        }) == sign::positive;
    };
    auto offset = [=](auto L) { return centre2(L, in) - centre2(L, out); };
    return !some_axis_separates(k, ds, false, ds.n, pokes_out, offset);
}

// Two boxes (three generators each) in one pass: the 15 axis polynomials of zonotopes_intersect,
// rewritten over shared determinants so each is a few operations (Gottschalk's R = A^T B idea,
// with the parallelepipeds' face normals). With the face normals n_m = a_j x a_k (m, j, k cyclic):
//   face axis n_m of a:   |n_m . d| - h_m |det a| - sum_j g_j |n_m . b_j|
//   edge axis a_i x b_j:  |a_i . (b_j x d)| - sum_{k != i} h_k |n_{m(i,k)} . b_j|
//                                             - sum_{k != j} g_k |a_i . n'_{m(j,k)}|
// (d = 2 c_b - 2 c_a, h and g twice the extents, m(i, k) the third index), the same polynomials
// as the general path's up to terms that vanish identically, so the same signs. The filter
// answers when every sign is proven; then one separating axis is a certificate, and when none
// separates and one box is solid (nonzero extents, nonzero determinant) the 15 axes were
// complete. Anything else (a sign it cannot prove, flat boxes) is uncertain: the general path
// decides. The approximate kernel evaluates the same in double.
// A box is a zonotope with three generators or an obb3 read in place (no zonotope is built:
// obb_obb's own call); box_generator, box_centre2, box_extent2 and box_solid read either.
// sign_of(v, kind): +1 proven positive, -1 proven negative or zero-or-less, 0 unknown; kind says
// which of the five families v belongs to, for a bound per family (box_box_bounds).
template <class L>
[[nodiscard]] constexpr auto box_generator(L l, const zonotope& z, unsigned i) {
    return lift(l, z.g[i]);
}
template <class L>
[[nodiscard]] constexpr auto box_generator(L l, const obb3& b, unsigned i) {
    return arith::lift(l, b.axes[i]);
}
template <class L>
[[nodiscard]] constexpr auto box_centre2(L l, const zonotope& z) {
    return centre2(l, z);
}
template <class L>
[[nodiscard]] constexpr auto box_centre2(L l, const obb3& b) {
    return arith::lift(l, b.center) + arith::lift(l, b.center);
}
template <class L>
[[nodiscard]] constexpr auto box_extent2(L l, const zonotope& z, unsigned i) {
    return l(z.hp[i]) + l(z.hq[i]);
}
template <class L>
[[nodiscard]] constexpr auto box_extent2(L l, const obb3& b, unsigned i) {
    return l(b.half_extents[i]) + l(b.half_extents[i]);
}
[[nodiscard]] constexpr bool box_solid(const zonotope& z) { return z.hp[0] != -z.hq[0] && z.hp[1] != -z.hq[1] && z.hp[2] != -z.hq[2]; }
[[nodiscard]] constexpr bool box_solid(const obb3& b) { return b.half_extents[0] != 0 && b.half_extents[1] != 0 && b.half_extents[2] != 0; }

// The coordinate axes first (box_box_fast): not among the 15, but they separate most pairs that
// lie far apart (their bounding boxes are apart) for a few products. A separating one is a
// certificate like any other; one that does not separate, or is not proven, decides nothing.
// sign_of(v): +1 proven positive, anything else otherwise.
template <class L, class BoxA, class BoxB, class Sign>
[[nodiscard]] constexpr bool coordinate_axis_separates(L l, const BoxA& a, const BoxB& b, Sign sign_of) {
    const auto d = box_centre2(l, b) - box_centre2(l, a);
    const auto one = l(1.0);
    const auto A0 = box_generator(l, a, 0), A1 = box_generator(l, a, 1), A2 = box_generator(l, a, 2);
    const auto B0 = box_generator(l, b, 0), B1 = box_generator(l, b, 1), B2 = box_generator(l, b, 2);
    const auto a0 = box_extent2(l, a, 0), a1 = box_extent2(l, a, 1), a2 = box_extent2(l, a, 2);
    const auto b0 = box_extent2(l, b, 0), b1 = box_extent2(l, b, 1), b2 = box_extent2(l, b, 2);
    for (unsigned c = 0; c < 3; ++c) {
        auto at = [c](const auto& v) { return c == 0 ? v.x : c == 1 ? v.y : v.z; };
        if (sign_of(one * magnitude(at(d)) - (a0 * magnitude(at(A0)) + a1 * magnitude(at(A1)) + a2 * magnitude(at(A2))) -
                    (b0 * magnitude(at(B0)) + b1 * magnitude(at(B1)) + b2 * magnitude(at(B2)))) > 0)
            return true;
    }
    return false;
}

enum box_axis_kind : unsigned { face_of_a, face_of_b, edge_pair, det_of_a, det_of_b };
template <class L, class BoxA, class BoxB, class Sign>
[[nodiscard]] constexpr certainty box_box_pass(L l, const BoxA& a, const BoxB& b, Sign sign_of) {
    using arith::cross;
    using arith::dot;
    const auto A0 = box_generator(l, a, 0), A1 = box_generator(l, a, 1), A2 = box_generator(l, a, 2);
    const auto B0 = box_generator(l, b, 0), B1 = box_generator(l, b, 1), B2 = box_generator(l, b, 2);
    const decltype(A0) A[3] = {A0, A1, A2};
    const decltype(B0) B[3] = {B0, B1, B2};
    const auto d = box_centre2(l, b) - box_centre2(l, a);
    const auto one = l(1.0);
    using H = decltype(l(0.0) + l(0.0));
    const H hA[3] = {box_extent2(l, a, 0), box_extent2(l, a, 1), box_extent2(l, a, 2)};
    const H hB[3] = {box_extent2(l, b, 0), box_extent2(l, b, 1), box_extent2(l, b, 2)};
    bool all = true; // every axis proven not to separate so far
    auto axis = [&](const auto& v, box_axis_kind kind) {
        const int s = sign_of(v, kind);
        all = all && s < 0;
        return s > 0;
    };
    // a's faces
    const auto n0 = cross(A1, A2), n1 = cross(A2, A0), n2 = cross(A0, A1);
    const decltype(n0) nA[3] = {n0, n1, n2};
    const auto detA = dot(n0, A0);
    decltype(magnitude(dot(n0, B0))) NA[3][3]; // |n_m . b_j|
    for (unsigned m = 0; m < 3; ++m) {
        for (unsigned j = 0; j < 3; ++j) NA[m][j] = magnitude(dot(nA[m], B[j]));
        if (axis(one * magnitude(dot(nA[m], d)) - hA[m] * magnitude(detA) - (hB[0] * NA[m][0] + hB[1] * NA[m][1] + hB[2] * NA[m][2]),
                 face_of_a))
            return certainty::no;
    }
    // b's faces
    const auto m0 = cross(B1, B2), m1 = cross(B2, B0), m2 = cross(B0, B1);
    const decltype(m0) nB[3] = {m0, m1, m2};
    const auto detB = dot(m0, B0);
    decltype(magnitude(dot(A0, m0))) NB[3][3]; // |a_i . n'_m|
    for (unsigned m = 0; m < 3; ++m) {
        for (unsigned i = 0; i < 3; ++i) NB[i][m] = magnitude(dot(A[i], nB[m]));
        if (axis(one * magnitude(dot(nB[m], d)) - hB[m] * magnitude(detB) - (hA[0] * NB[0][m] + hA[1] * NB[1][m] + hA[2] * NB[2][m]),
                 face_of_b))
            return certainty::no;
    }
    // the nine edge axes a_i x b_j (k = i + 1 leaves m = i + 2, and so on); (a_i x b_j) . d is
    // a_i . (b_j x d), three cross products shared by the nine
    const auto e0 = cross(B0, d), e1 = cross(B1, d), e2 = cross(B2, d);
    const decltype(e0) E[3] = {e0, e1, e2};
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) {
            const unsigned i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            if (axis(one * magnitude(dot(A[i], E[j])) - (hA[i1] * NA[i2][j] + hA[i2] * NA[i1][j]) -
                         (hB[j1] * NB[i][j2] + hB[j2] * NB[i][j1]),
                     edge_pair))
                return certainty::no;
        }
    auto nonzero = [&](const auto& v, box_axis_kind kind) { return sign_of(v, kind) > 0 || sign_of(-v, kind) > 0; };
    if (all && ((box_solid(a) && nonzero(detA, det_of_a)) || (box_solid(b) && nonzero(detB, det_of_b)))) return certainty::yes;
    return certainty::uncertain;
}

// A bound, per axis family, on the permanent of box_box_pass's signs (the permanent arith::filtered
// carries: the polynomial with every input by its magnitude and every - by +), from five
// magnitudes: alpha and beta the largest |component| of a's and b's generators, delta the largest
// component of |2 c_a| + |2 c_b|, eta_a and eta_b twice the largest extents. With n_m = a_j x a_k
// (each component 2 alpha^2 at most) and b_j x d (2 beta delta), term by term:
//   face of a: 6 alpha^2 (delta + alpha eta_a + 3 beta eta_b), face of b likewise,
//   edge pair: 6 alpha beta (delta + 2 alpha eta_a + 2 beta eta_b), det a: 6 alpha^3.
// Each of the five is then an upper bound of the filter's permanent for every sign of its family,
// so gamma_K times it bounds the double value's error (arith::filtered's invariant I1). The
// permanent's own 2^-1020 per product (arith::filtered, for underflow) sums to less than 2^-700
// when every magnitude is at most 2^150 (fewer than 200 products, cofactors below 2^310), so
// 2^-600 is added to every bound; larger or non-finite magnitudes give no bounds (nullopt).
// Source: the semi-static filters of Meyer and Pion, "FPG: A code generator for fast and
// certified geometric predicates", Real Numbers and Computers 2008 (one bound from the inputs'
// maxima per predicate, instead of one carried through every operation).
struct box_magnitudes {
    double generator; // the largest |component| of a generator (|to| + |from| for a difference)
    double extent;    // the largest twice-extent (|hp| + |hq|)
    double centre[3]; // |cp| + |cq| per coordinate
};
// In trees, so the maxima do not wait on each other. A NaN operand may be passed over: the signs
// it enters are NaN, hence unproven, and the bounds stay valid for the others.
[[nodiscard]] constexpr double largest(double x, double y) { return x > y ? x : y; }
[[nodiscard]] constexpr double largest(double x, double y, double z) { return largest(largest(x, y), z); }
[[nodiscard]] constexpr box_magnitudes magnitudes_of(const zonotope& z) {
    using arith::abs;
    auto g = [&](unsigned i) {
        const vec3 t = z.g[i].to, f = z.g[i].from;
        return largest(abs(t.x) + abs(f.x), abs(t.y) + abs(f.y), abs(t.z) + abs(f.z));
    };
    auto h = [&](unsigned i) { return abs(z.hp[i]) + abs(z.hq[i]); };
    return {largest(g(0), g(1), g(2)),
            largest(h(0), h(1), h(2)),
            {abs(z.cp.x) + abs(z.cq.x), abs(z.cp.y) + abs(z.cq.y), abs(z.cp.z) + abs(z.cq.z)}};
}
[[nodiscard]] constexpr box_magnitudes magnitudes_of(const obb3& b) {
    using arith::abs;
    auto g = [&](unsigned i) { return largest(abs(b.axes[i].x), abs(b.axes[i].y), abs(b.axes[i].z)); };
    const auto& h = b.half_extents;
    return {largest(g(0), g(1), g(2)),
            2.0 * largest(abs(h[0]), abs(h[1]), abs(h[2])),
            {2.0 * abs(b.center.x), 2.0 * abs(b.center.y), 2.0 * abs(b.center.z)}};
}
struct box_box_bounds {
    double permanent[5]; // by box_axis_kind
};
template <class BoxA, class BoxB>
[[nodiscard]] constexpr std::optional<box_box_bounds> box_box_static_bounds(const BoxA& a, const BoxB& b) {
    const box_magnitudes ma = magnitudes_of(a), mb = magnitudes_of(b);
    const double al = ma.generator, be = mb.generator, ea = ma.extent, eb = mb.extent;
    const double de = largest(ma.centre[0] + mb.centre[0], ma.centre[1] + mb.centre[1], ma.centre[2] + mb.centre[2]);
    constexpr double top = 0x1p150;
    if (!((al <= top) & (be <= top) & (ea <= top) & (eb <= top) & (de <= top))) return std::nullopt;
    // (1 + 2^-30) covers the rounding of these few operations (each loses a factor 1 - 2^-53 at most)
    constexpr double six = 6.0 * (1.0 + 0x1p-30);
    return box_box_bounds{{six * al * al * (de + al * ea + 3.0 * be * eb), six * be * be * (de + be * eb + 3.0 * al * ea),
                           six * al * be * (de + 2.0 * al * ea + 2.0 * be * eb), six * al * al * al, six * be * be * be}};
}

// box_box_pass with every sign against those bounds alone: uncertain where it cannot tell (no bounds,
// a sign too close to call, flat boxes).
template <class BoxA, class BoxB>
[[nodiscard]] constexpr certainty box_box_bounded_pass(const BoxA& a, const BoxB& b) {
    const auto s = box_box_static_bounds(a, b);
    if (!s) return certainty::uncertain;
    return box_box_pass(arith::lift_filter{}, a, b, [&]<int N>(const arith::filtered<N>& v, box_axis_kind kind) {
        const double bound = arith::error_bound(arith::filtered<N>{0.0, s->permanent[kind]}) + 0x1p-600;
        return v.v > bound ? 1 : v.v < -bound ? -1 : 0;
    });
}

template <class K, class BoxA, class BoxB>
[[nodiscard]] constexpr certainty box_box_fast(K&, const BoxA& a, const BoxB& b) {
    if constexpr (std::is_base_of_v<arith::filter_kernel, K> || std::is_same_v<K, arith::exact_kernel>) {
        // First the double values against the bounds from the inputs' maxima (no permanent is
        // computed: the filtered type's permanents are dead code here, only its K is read), then,
        // if some sign was too close to call, the filter with every permanent.
        if (coordinate_axis_separates(arith::lift_filter{}, a, b, [](const auto& v) { return arith::proven_sign(v); }))
            return certainty::no;
        if (const certainty r = box_box_bounded_pass(a, b); r != certainty::uncertain) return r;
        return box_box_pass(arith::lift_filter{}, a, b, [](const auto& v, box_axis_kind) { return arith::proven_sign(v); });
    } else if constexpr (std::is_same_v<K, arith::approx_kernel>) {
        if (coordinate_axis_separates(arith::lift_double{}, a, b, [](double v) { return v > 0 ? 1 : -1; })) return certainty::no;
        return box_box_pass(arith::lift_double{}, a, b, [](double v, box_axis_kind) { return v > 0 ? 1 : -1; });
    } else {
        return certainty::uncertain; // other kernels (the tests' margin kernel) take the general path
    }
}

// Zonotope a (bounded) against the closed triangle t (a collinear triangle is its hull).
template <class K>
[[nodiscard]] constexpr bool zonotope_triangle_intersect(K& k, const zonotope& a, const triangle3& t) {
    directions ds;
    add_generators(ds, a);
    const int first_edge = ds.n;
    const point3 v[3] = {t.a, t.b, t.c};
    for (int e = 0; e < 3; ++e) {
        const point3 p = v[e], q = v[(e + 1) % 3];
        ds.add(direction{{q.x, q.y, q.z}, {p.x, p.y, p.z}}, !(p.x == q.x && p.y == q.y && p.z == q.z));
    }
    auto separates = [&](auto axis, bool) {
        // side of vertex x against a's slab along w: + beyond the far end, - before the near end
        auto beyond = [&](point3 x, bool far) {
            return k.sgn([=](auto L) {
                const auto w = axis(L);
                const auto gap = L(1.0) * arith::dot(w, (arith::lift(L, x) + arith::lift(L, x)) - centre2(L, a));
                return far ? gap - radius2(L, a, w) : gap + radius2(L, a, w);
            });
        };
        if (beyond(v[0], true) == sign::positive) return beyond(v[1], true) == sign::positive && beyond(v[2], true) == sign::positive;
        if (beyond(v[0], false) == sign::negative) return beyond(v[1], false) == sign::negative && beyond(v[2], false) == sign::negative;
        return false;
    };
    const point3 v0 = v[0];
    auto offset = [=](auto L) { return (arith::lift(L, v0) + arith::lift(L, v0)) - centre2(L, a); };
    return !some_axis_separates(k, ds, true, first_edge, separates, offset);
}

} // namespace incidence::detail::sat
export namespace incidence::detail {

// The boxes in a fixed order (their numbers, see numbers_before), so that the plain-double tier
// also answers the same for (a, b) and (b, a).
[[nodiscard]] constexpr bool obb_before(const obb3& a, const obb3& b) {
    const double x[15] = {a.center.x,  a.center.y,  a.center.z,        a.axes[0].x,       a.axes[0].y,
                          a.axes[0].z, a.axes[1].x, a.axes[1].y,       a.axes[1].z,       a.axes[2].x,
                          a.axes[2].y, a.axes[2].z, a.half_extents[0], a.half_extents[1], a.half_extents[2]};
    const double y[15] = {b.center.x,  b.center.y,  b.center.z,        b.axes[0].x,       b.axes[0].y,
                          b.axes[0].z, b.axes[1].x, b.axes[1].y,       b.axes[1].z,       b.axes[2].x,
                          b.axes[2].y, b.axes[2].z, b.half_extents[0], b.half_extents[1], b.half_extents[2]};
    return numbers_before(x, y, 15);
}

// The classic test in plain double (an alternative, compared in the audit): the rotation
// R = A^T B and the centre offset in A's frame, 15 axes with A's and B's axes as face normals
// (so it assumes orthonormal axes), and a small constant added to |R| so that nearly parallel
// edge pairs do not produce a null cross-product axis.
// Source: Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5; Ericson, Real-Time
// Collision Detection (2005), section 4.4.1 (the epsilon on |R|, here 1e-6 as in FCL's obbDisjoint).
[[nodiscard]] constexpr bool obb_obb_gottschalk(const obb3& a, const obb3& b) {
    if (!sat::well_formed(a) || !sat::well_formed(b)) return false;
    double R[3][3], F[3][3];
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) {
            R[i][j] = dot(a.axes[i], b.axes[j]);
            F[i][j] = (R[i][j] < 0 ? -R[i][j] : R[i][j]) + 1e-6;
        }
    const vec3 d = b.center - a.center;
    const double t[3] = {dot(d, a.axes[0]), dot(d, a.axes[1]), dot(d, a.axes[2])};
    const auto& ha = a.half_extents;
    const auto& hb = b.half_extents;
    for (unsigned i = 0; i < 3; ++i)
        if (arith::abs(t[i]) > ha[i] + hb[0] * F[i][0] + hb[1] * F[i][1] + hb[2] * F[i][2]) return false;
    for (unsigned j = 0; j < 3; ++j)
        if (arith::abs(t[0] * R[0][j] + t[1] * R[1][j] + t[2] * R[2][j]) > ha[0] * F[0][j] + ha[1] * F[1][j] + ha[2] * F[2][j] + hb[j])
            return false;
    for (unsigned i = 0; i < 3; ++i) {
        const unsigned i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (unsigned j = 0; j < 3; ++j) {
            const unsigned j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const double ra = ha[i1] * F[i2][j] + ha[i2] * F[i1][j];
            const double rb = hb[j1] * F[i][j2] + hb[j2] * F[i][j1];
            if (arith::abs(t[i2] * R[i1][j] - t[i1] * R[i2][j]) > ra + rb) return false;
        }
    }
    return true;
}

} // namespace incidence::detail
