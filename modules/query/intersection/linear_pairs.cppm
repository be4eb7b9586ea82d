// intersection: a line, a ray or a segment against a plane, a box, an oriented box, a k-DOP, a
// frustum, a convex polyhedron, a tetrahedron, a ball (span_hit: t_enter, t_exit, the point at
// t_enter), a triangle (triangle_hit), a polygon (polygon_hit) and a closed mesh (mesh_hit).
// Semantics: closed sets, so touching counts (t_enter = t_exit at a touching point); the object's
// own range bounds the span (a ray starting inside a box enters at 0); a zero direction, or a
// segment with equal end points, is its point, met over its whole range. Every hit is about the
// linear object: its parameters, the point o + t D. A non-finite input, an inverted or negative
// extent, or a k-DOP slab with min > max: no set, no hit.
// Method: each row below is one call of an engine, written for the kernel so that the four tiers
// come from one body (the tier driver in query/intersection.cppm):
//   | row                                        | engine (method)                                    | signs   |
//   | plane, box, half-space sets, k-DOP, OBB    | engines/clip.cppm (Cyrus and Beck 1978, as signs)  | <= 8    |
//   | tetrahedron                                | clip on its face planes; flat: its faces' union    | <= 6    |
//   | ball                                       | roots of |o + t D - c|^2 = r^2 (value.cppm)        | <= 4    |
//   | triangle, polygon, mesh                    | engines/contact.cppm (first contact)               | <= 6    |
// Values: t, the point and the barycentrics are ratios of polynomials (a ball's t a quadratic's
// root): correctly rounded in the exact tier, enclosed in the conservative and aggressive tiers,
// plain double in the approximate tier. The approximate tier evaluates the same body in double; its
// error bound: where every sign of the body is at least 2^-40 of its permanent from zero (the
// filter then decides each one, and plain double takes the same branch), each value lies within
// the conservative tier's interval of the same inputs, a point coordinate within |D_i| times the
// width of t's interval plus 2^-50 (|o_i| + |t D_i|) + 2^-1073 (the last term for subnormal
// coordinates; tests/query/intersection/linear_pairs.cpp). A conservative hit can be sure where a
// sign is within that margin (a mesh's or a polygon's signs are settled exactly as they arise):
// there the approximate tier may take another branch, as its yes/no answer may.
module;
#include <array>
#include <cstddef>
#include <optional>
#include <type_traits>
export module incidence.detail:intersection.linear_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.clip;
import :engines.triangle;
import :engines.contact;
import :engines.halfspace_slabs;
import :engines.polygon3;
import :engines.mesh;
import :intersects.mesh_pairs;
import :intersects.polygon_pairs;
import :exactly;

export namespace incidence::detail {

template <class S>
concept linear_shape = std::is_same_v<S, ray3> || std::is_same_v<S, segment3> || std::is_same_v<S, line3>;

template <class K>
using span_of = std::optional<span_hit<arith::value_t<K>>>;

[[nodiscard]] constexpr double coordinate(point3 p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }

// --- the convex sets ------------------------------------------------------------------------------

template <class K, linear_shape S>
[[nodiscard]] constexpr span_of<K> intersection(K& k, const plane3& p, const S& x) {
    if (!finite(p.normal) || !finite(p.offset) || !finite(x)) return std::nullopt;
    const linear3 s = as_linear(x);
    const auto con = plane_constraint(p, s);
    const auto r = clip_equality(k, con, s.kind);
    if (!r) return std::nullopt;
    return clipped_values(k, con, *r, s);
}

template <class K, linear_shape S>
[[nodiscard]] constexpr span_of<K> intersection(K& k, const aabb3& b, const S& x) {
    if (!finite(b.min) || !finite(b.max) || !finite(x)) return std::nullopt;
    const linear3 s = as_linear(x);
    if (!__builtin_is_constant_evaluated()) // the faces' parameters in double may overflow to infinity
        if (const slab_choice c = box_slabs(b, s); c.decided) {
            if (!c.range) return std::nullopt;
            return clipped_values(k, box_constraints(b, s), *c.range, s);
        }
    return clip_span(k, box_constraints(b, s), 6, s);
}

template <class K, linear_shape S>
[[nodiscard]] constexpr span_of<K> intersection(K& k, const convex_polyhedron3& c, const S& x) {
    if (!halfspaces::well_formed(c.planes.data(), c.count, convex_polyhedron3::capacity) || !finite(x)) return std::nullopt;
    const linear3 s = as_linear(x);
    return clip_span(k, halfspace_constraints(c.planes.data(), s), c.count, s);
}

template <class K, linear_shape S>
[[nodiscard]] constexpr span_of<K> intersection(K& k, const frustum3& f, const S& x) {
    if (!halfspaces::well_formed(f.planes.data(), 6, 6) || !finite(x)) return std::nullopt;
    const linear3 s = as_linear(x);
    return clip_span(k, halfspace_constraints(f.planes.data(), s), 6, s);
}

// The k-DOP's slabs min_j <= d_j . x <= max_j, with d_j's components -1, 0 or 1 lifted as inputs and
// the bounds times a lifted 1 (degree 2).
template <class K, int N, linear_shape S>
[[nodiscard]] constexpr span_of<K> intersection(K& k, const kdop<N>& b, const S& x) {
    for (int j = 0; j < N / 2; ++j)
        if (!finite(b.min[static_cast<unsigned>(j)]) || !finite(b.max[static_cast<unsigned>(j)])) return std::nullopt;
    if (!finite(x)) return std::nullopt;
    const linear3 s = as_linear(x);
    constexpr auto dirs = kdop<N>::directions();
    auto con = [=](int i, auto L) {
        const auto j = static_cast<unsigned>(i / 2);
        const auto d = arith::lift(L, vec3{double(dirs[j].x), double(dirs[j].y), double(dirs[j].z)});
        const auto a = arith::dot(d, s.O(L));
        const auto bb = arith::dot(d, s.D(L));
        if (i % 2 == 0) return affine{a - L(b.min[j]) * L(1.0), bb};
        return affine{L(b.max[j]) * L(1.0) - a, -bb};
    };
    return clip_span(k, con, N, s);
}

// The oriented box {c + sum u_i h_i a_i : |u_i| <= 1}. With det = a_0 . (a_1 x a_2) != 0 its faces are
// |N_i . (x - c)| <= h_i |det|, N_i = a_j x a_k (i, j, k cyclic), degree 4 with a lifted 1. With
// dependent axes (only an unchecked aggregate has them) it is a zonotope of lower dimension, written
// with absolute values (obb_flat_constraints).
template <class K>
[[nodiscard]] constexpr auto obb_face_constraints(const obb3& b, const linear3& s, sign det_sign) {
    return [=](int i, auto L) {
        const int f = i / 2;
        const auto a0 = arith::lift(L, b.axes[static_cast<unsigned>(f)]);
        const auto a1 = arith::lift(L, b.axes[static_cast<unsigned>((f + 1) % 3)]);
        const auto a2 = arith::lift(L, b.axes[static_cast<unsigned>((f + 2) % 3)]);
        const auto n = arith::cross(a1, a2);
        const auto one = L(1.0);
        const auto det = arith::dot(a0, n);
        const auto r = L(b.half_extents[static_cast<unsigned>(f)]) * (det_sign == sign::negative ? -det : det);
        const auto w = arith::dot(n, s.O(L) - arith::lift(L, b.center)) * one;
        const auto v = arith::dot(n, s.D(L)) * one;
        if (i % 2 == 0) return affine{r - w, -v};
        return affine{r + w, v};
    };
}
// A zonotope c + sum u_i g_i (g_i = h_i a_i) whose generators span a plane or less: the constraints
// |m . (x - c)| <= sum_i |m . g_i| for m the plane's normal n = g_i x g_j (both sides together force
// m . (x - c) = 0) and the in-plane normals n x g_l; in rank 1 (all generators parallel to g), m over
// g x e_axis (the line) and g; in rank 0, the coordinate axes (the point c). Each kind of normal is
// one constraint family (their polynomials differ in degree), met by clip_families. Degree <= 12.
template <class K>
[[nodiscard]] constexpr span_of<K> obb_flat(K& k, const obb3& b, const linear3& s) {
    auto g = [=](auto L, int i) {
        const auto a = arith::lift(L, b.axes[static_cast<unsigned>(i)]);
        const auto h = L(b.half_extents[static_cast<unsigned>(i)]);
        return arith::v3<decltype(a.x * h)>{a.x * h, a.y * h, a.z * h};
    };
    auto unit = [](int axis) { return vec3{axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0}; };
    auto family = [=](auto normal) {
        return [=](int i, auto L) {
            const auto m = normal(L, i / 2);
            const auto reach = arith::abs(arith::dot(m, g(L, 0))) + arith::abs(arith::dot(m, g(L, 1))) + arith::abs(arith::dot(m, g(L, 2)));
            const auto one = L(1.0);
            const auto w = arith::dot(m, s.O(L) - arith::lift(L, b.center)) * one;
            const auto v = arith::dot(m, s.D(L)) * one;
            if (i % 2 == 0) return affine{reach - w, -v};
            return affine{reach + w, v};
        };
    };
    int pi = -1, pj = -1; // generators with g_i x g_j != 0
    for (int i = 0; i < 3 && pi < 0; ++i)
        for (int j = i + 1; j < 3 && pi < 0; ++j)
            for (int axis = 0; axis < 3 && pi < 0; ++axis)
                if (arith::sgn<arith::hint::structural>(k, [=](auto L) { return pick(arith::cross(g(L, i), g(L, j)), axis); }) !=
                    sign::zero)
                    pi = i, pj = j;
    if (pi >= 0) {
        auto plane = family([=](auto L, int) { return arith::cross(g(L, pi), g(L, pj)); });
        auto edges = family([=](auto L, int l) { return arith::cross(arith::cross(g(L, pi), g(L, pj)), g(L, l)); });
        return clip_families(k, s, std::pair{plane, 2}, std::pair{edges, 6});
    }
    int gi = -1; // a nonzero generator
    for (int i = 0; i < 3 && gi < 0; ++i)
        for (int axis = 0; axis < 3 && gi < 0; ++axis)
            if (arith::sgn<arith::hint::structural>(k, [=](auto L) { return pick(g(L, i), axis); }) != sign::zero) gi = i;
    if (gi >= 0) {
        auto line = family([=](auto L, int axis) { return arith::cross(g(L, gi), arith::lift(L, unit(axis))); });
        auto along = family([=](auto L, int) { return g(L, gi); });
        return clip_families(k, s, std::pair{line, 6}, std::pair{along, 2});
    }
    auto point = family([=](auto L, int axis) { return arith::lift(L, unit(axis)); });
    return clip_span(k, point, 6, s);
}

template <class K, linear_shape S>
[[nodiscard]] constexpr span_of<K> intersection(K& k, const obb3& b, const S& x) {
    if (!finite(b.center) || !finite(x)) return std::nullopt;
    for (int i = 0; i < 3; ++i)
        if (!finite(b.axes[static_cast<unsigned>(i)]) || !(b.half_extents[static_cast<unsigned>(i)] >= 0.0) ||
            !finite(b.half_extents[static_cast<unsigned>(i)]))
            return std::nullopt;
    const linear3 s = as_linear(x);
    const sign det =
        k.sgn([=](auto L) { return arith::det3(arith::lift(L, b.axes[0]), arith::lift(L, b.axes[1]), arith::lift(L, b.axes[2])); });
    if (det == sign::zero) return obb_flat(k, b, s);
    return clip_span_in_double(k, obb_face_constraints<K>(b, s, det), 6, s);
}

// The tetrahedron: with o = orient3d(a, b, c, d) != 0, inside its four face planes, each face's
// orient3d with x having the sign it has at the opposite vertex (o or -o by the permutation's
// parity); a flat tetrahedron is the union of its four faces (Caratheodory in the plane).
template <class K, linear_shape S>
[[nodiscard]] constexpr span_of<K> intersection(K& k, const tetrahedron3& t, const S& x) {
    if (!finite(t) || !finite(x)) return std::nullopt;
    const linear3 s = as_linear(x);
    const sign o = k.sgn([=](auto L) {
        const auto A = arith::lift(L, t.a);
        return arith::det3(arith::lift(L, t.b) - A, arith::lift(L, t.c) - A, arith::lift(L, t.d) - A);
    });
    if (o == sign::zero) {
        std::optional<contact_span> r;
        for (int f = 0; f < 4; ++f) r = hull_of(k, r, triangle_span(k, s, t.face(f)), s);
        if (!r) return std::nullopt;
        const auto enter = end_value_and_point(k, r->enter, s);
        return span_hit<arith::value_t<K>>{enter.t, end_value(k, r->exit, s), enter.point};
    }
    // faces (p, q, r) with the sign of orient3d(p, q, r, x) inside: (a b c) o, (a b d) -o, (a c d) o, (b c d) -o
    const std::array<point3, 4> v{t.a, t.b, t.c, t.d};
    constexpr int face[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    auto con = [=](int i, auto L) {
        const auto P = arith::lift(L, v[static_cast<unsigned>(face[i][0])]);
        const auto n = arith::cross(arith::lift(L, v[static_cast<unsigned>(face[i][1])]) - P,
                                    arith::lift(L, v[static_cast<unsigned>(face[i][2])]) - P);
        const auto A = arith::dot(n, s.O(L) - P);
        const auto B = arith::dot(n, s.D(L));
        const bool flip = (i % 2 == 1) != (o == sign::negative);
        return flip ? affine{-A, -B} : affine{A, B};
    };
    return clip_span_in_double(k, con, 4, s);
}

// The ball |x - c| <= |r|: o + t D inside iff a t^2 + 2 b t + c' <= 0 with a = D . D, b = m . D,
// c' = m . m - r^2, m = o - c; the roots t1 <= t2 exist iff b^2 - a c' >= 0. Each root against 0 and
// 1 is the sign of f and of the vertex test at that point (arith::root_minus), degree 2.
template <class K, linear_shape S>
[[nodiscard]] constexpr span_of<K> intersection(K& k, const sphere3& ball, const S& x) {
    if (!finite(ball.center) || !finite(ball.radius) || !finite(x)) return std::nullopt;
    const linear3 s = as_linear(x);
    const point3 c = ball.center;
    const double r = ball.radius;
    auto q = [=](auto L) {
        const auto m = s.O(L) - arith::lift(L, c);
        const auto D = s.D(L);
        const auto rr = L(r);
        return arith::quadratic{arith::dot(D, D), arith::dot(m, D), arith::dot(m, m) - rr * rr};
    };
    using V = arith::value_t<K>;
    constexpr double inf = __builtin_huge_val();
    if (s.is_point()) {
        if (k.sgn([=](auto L) { return q(L).c; }) == sign::positive) return std::nullopt;
        return span_hit<V>{arith::exact_value(k, domain_low(s)), arith::exact_value(k, domain_high(s)), arith::exact_point(k, s.o)};
    }
    if (k.sgn([=](auto L) {
            const auto e = q(L);
            return e.b * e.b - e.a * e.c;
        }) == sign::negative)
        return std::nullopt;
    // sign(t_root - y) for y = 0 (f(0) = c', vertex b) and y = 1 (f(1) = a + 2b + c', vertex a + b)
    auto against = [&](arith::root w, bool at_one) {
        const sign f = at_one ? k.sgn([=](auto L) {
            const auto e = q(L);
            return e.a + (e.b + e.b) + e.c;
        })
                              : k.sgn([=](auto L) { return q(L).c; });
        const sign v = at_one ? k.sgn([=](auto L) {
            const auto e = q(L);
            return e.a + e.b;
        })
                              : k.sgn([=](auto L) { return q(L).b; });
        return *arith::root_side(w, f, v);
    };
    bool enter_at_root = true, exit_at_root = true;
    if (s.bounded_below()) {
        if (against(arith::root::larger, false) == sign::negative) return std::nullopt;    // t2 < 0
        if (against(arith::root::smaller, false) != sign::positive) enter_at_root = false; // t1 <= 0: enters at 0
    }
    if (s.bounded_above()) {
        if (against(arith::root::smaller, true) == sign::positive) return std::nullopt; // t1 > 1
        if (against(arith::root::larger, true) != sign::negative) exit_at_root = false; // t2 >= 1: leaves at 1
    }
    span_hit<V> h{arith::exact_value(k, 0.0), arith::exact_value(k, s.bounded_above() ? 1.0 : inf), arith::exact_point(k, s.o)};
    auto O = [=](auto L) { return s.O(L); };
    auto D = [=](auto L) { return s.D(L); };
    if (enter_at_root) {
        const auto e = arith::value_and_point_at_root(k, q, arith::root::smaller, O, D);
        h.t_enter = e.t;
        h.point = e.point;
    }
    if (exit_at_root) h.t_exit = arith::root_value(k, q, arith::root::larger);
    return h;
}

// --- the triangle, the polygon, the mesh: first contact ---------------------------------------------

// The values of a hit on a triangle, each a ratio (or polynomial) lambda f(L) lifted like a sign:
// - the normal's component `axis`, (b - a) x (c - a);
// - crossing the plane, the barycentric of the vertex opposite p q by Pluecker's coordinates:
//   det(D, p - o, q - o) / n . D;
// - in the plane (the projection dropping `axis`, where the area is not zero), at X = o + (N / S) D:
//   cross2(p - X, q - X) / area = (S cross2(p - o, q - o) - N cross2(D, q - p)) / (S area), the
//   terms in t^2 cancelling (cross2(D, D) = 0); at the point o itself, cross2(p - o, q - o) / area.
[[nodiscard]] constexpr auto normal_component(const triangle3& t, int axis) {
    return [=](auto L) {
        const auto A = arith::lift(L, t.a);
        return pick(arith::cross(arith::lift(L, t.b) - A, arith::lift(L, t.c) - A), axis);
    };
}
[[nodiscard]] constexpr auto pluecker_barycentric(const linear3& s, const triangle3& t, point3 p, point3 q) {
    return [=](auto L) {
        const auto A = arith::lift(L, t.a);
        const auto n = arith::cross(arith::lift(L, t.b) - A, arith::lift(L, t.c) - A);
        return arith::ratio{arith::det3(s.D(L), arith::lift(L, p) - s.O(L), arith::lift(L, q) - s.O(L)), arith::dot(n, s.D(L))};
    };
}
template <class L>
[[nodiscard]] constexpr auto projected_area(L l, const triangle3& t, int axis) {
    const auto A = arith::lift(l, t.a);
    return arith::cross(drop_axis(arith::lift(l, t.b) - A, axis), drop_axis(arith::lift(l, t.c) - A, axis));
}
[[nodiscard]] constexpr auto area_barycentric_at_origin(const linear3& s, const triangle3& t, int axis, point3 p, point3 q) {
    return [=](auto L) {
        const auto O = s.O(L);
        return arith::ratio{arith::cross(drop_axis(arith::lift(L, p) - O, axis), drop_axis(arith::lift(L, q) - O, axis)),
                            projected_area(L, t, axis)};
    };
}
template <class T>
[[nodiscard]] constexpr auto area_barycentric(const T& tr, const linear3& s, const triangle3& t, int axis, point3 p, point3 q) {
    return [=](auto L) {
        const auto x = tr(L);
        const auto P = arith::lift(L, p), Q = arith::lift(L, q), O = s.O(L);
        return arith::ratio{x.den * arith::cross(drop_axis(P - O, axis), drop_axis(Q - O, axis)) -
                                x.num * arith::cross(drop_axis(s.D(L), axis), drop_axis(Q - P, axis)),
                            x.den * projected_area(L, t, axis)};
    };
}

// Whether the end lies on the edge p q by construction (entering or leaving a coplanar triangle
// there): the barycentric of the vertex opposite p q is then exactly 0.
[[nodiscard]] constexpr bool on_edge(const contact_end& e, point3 p, point3 q) {
    return e.kind == end_kind::edge_clip && e.p == p && e.q == q;
}

// The axis whose projection keeps a proper triangle's area (-1: degenerate, no barycentrics).
template <class K>
[[nodiscard]] constexpr int area_axis(K& k, const triangle3& t) {
    for (int i = 0; i < 3; ++i)
        if (arith::sgn<arith::hint::structural>(k, normal_component(t, i)) != sign::zero) return i;
    return -1;
}

// The barycentrics of the point at a contact end of s with the proper or degenerate triangle t.
template <class K>
constexpr void barycentrics(K& k, triangle_hit<arith::value_t<K>>& h, const contact_end& e, const linear3& s, const triangle3& t) {
    const point3 a = t.a, b = t.b, c = t.c;
    h.u = h.v = h.w = arith::exact_value(k, 0.0);
    if (e.kind == end_kind::plane_crossing) {
        h.u = arith::value(k, pluecker_barycentric(s, t, b, c));
        h.v = arith::value(k, pluecker_barycentric(s, t, c, a));
        h.w = arith::value(k, pluecker_barycentric(s, t, a, b));
        return;
    }
    const int axis = area_axis(k, t);
    if (axis < 0) return;             // degenerate: no barycentrics
    if (e.kind == end_kind::domain) { // the point o itself
        h.u = arith::value(k, area_barycentric_at_origin(s, t, axis, b, c));
        h.v = arith::value(k, area_barycentric_at_origin(s, t, axis, c, a));
        h.w = arith::value(k, area_barycentric_at_origin(s, t, axis, a, b));
        return;
    }
    with_ratio(e, s, [&](const auto& tr) {
        auto one = [&](point3 p, point3 q) {
            return on_edge(e, p, q) ? arith::exact_value(k, 0.0) : arith::value(k, area_barycentric(tr, s, t, axis, p, q));
        };
        h.u = one(b, c);
        h.v = one(c, a);
        h.w = one(a, b);
    });
}

template <class K>
[[nodiscard]] constexpr arith::vec_value_t<K> normal_value(K& k, const triangle3& t) {
    auto component = [&](int axis) { return arith::value(k, normal_component(t, axis)); };
    if constexpr (arith::encloses<K>) return interval3{component(0), component(1), component(2)};
    else return vec3{component(0), component(1), component(2)};
}

// The exact tier at run time: every value of a hit from one pass in the double-double filter (each
// value's lambda evaluated in one function, so the parts they share, n and the end's ratio, are
// computed once), each rounded from it where its test decides (arith::rounded_from), by its own
// exact stages otherwise. The general path evaluates each value alone.
template <class K>
[[nodiscard]] triangle_hit<double> rounded_triangle_values(K& k, const contact_end& e, const linear3& s, const triangle3& t) {
    const arith::lift_filter_dd L{};
    const auto n0 = normal_component(t, 0), n1 = normal_component(t, 1), n2 = normal_component(t, 2);
    const auto x0 = n0(L), x1 = n1(L), x2 = n2(L);
    const int axis = e.kind == end_kind::plane_crossing ? -1 : area_axis(k, t);
    triangle_hit<double> h{};
    auto round3 = [&](const auto& fu, const auto& fv, const auto& fw) {
        const auto u = fu(L), v = fv(L), w = fw(L);
        h.u = on_edge(e, t.b, t.c) ? 0.0 : arith::rounded_from(fu, u);
        h.v = on_edge(e, t.c, t.a) ? 0.0 : arith::rounded_from(fv, v);
        h.w = on_edge(e, t.a, t.b) ? 0.0 : arith::rounded_from(fw, w);
    };
    if (e.kind == end_kind::domain) {
        h.t = e.bound;
        h.point = e.bound == 1.0 ? s.q : s.o;
        if (axis >= 0)
            round3(area_barycentric_at_origin(s, t, axis, t.b, t.c), area_barycentric_at_origin(s, t, axis, t.c, t.a),
                   area_barycentric_at_origin(s, t, axis, t.a, t.b));
    } else {
        with_ratio(e, s, [&](const auto& tr) {
            const auto v = arith::rounded_value_and_point(k, tr, [=](auto M) { return s.O(M); }, [=](auto M) { return s.D(M); }, tr(L));
            h.t = v.t;
            h.point = v.point;
            if (e.kind == end_kind::plane_crossing)
                round3(pluecker_barycentric(s, t, t.b, t.c), pluecker_barycentric(s, t, t.c, t.a), pluecker_barycentric(s, t, t.a, t.b));
            else if (axis >= 0)
                round3(area_barycentric(tr, s, t, axis, t.b, t.c), area_barycentric(tr, s, t, axis, t.c, t.a),
                       area_barycentric(tr, s, t, axis, t.a, t.b));
        });
    }
    h.normal = vec3{arith::rounded_from(n0, x0), arith::rounded_from(n1, x1), arith::rounded_from(n2, x2)};
    return h;
}

template <class K>
[[nodiscard]] constexpr triangle_hit<arith::value_t<K>> triangle_values(K& k, const contact_end& e, const linear3& s, const triangle3& t) {
    if constexpr (arith::value_mode_of<K>() == arith::value_mode::rounded)
        if (!__builtin_is_constant_evaluated()) return rounded_triangle_values(k, e, s, t);
    const auto v = end_value_and_point(k, e, s);
    triangle_hit<arith::value_t<K>> h{v.t, v.point, normal_value(k, t), {}, {}, {}};
    barycentrics(k, h, e, s, t);
    return h;
}

template <class K, linear_shape S>
[[nodiscard]] constexpr std::optional<triangle_hit<arith::value_t<K>>> intersection(K& k, const triangle3& t, const S& x) {
    if (!finite(t) || !finite(x)) return std::nullopt;
    const linear3 s = as_linear(x);
    if (boxes_apart(k, x, t)) return std::nullopt;
    const auto r = triangle_span(k, s, t);
    if (!r) return std::nullopt;
    return triangle_values(k, r->enter, s, t);
}

// The polygon: where it crosses the polygon's plane; lying in the plane, at 0 when the object starts
// inside, else the least parameter on its edges.
template <class K, linear_shape S>
[[nodiscard]] constexpr std::optional<polygon_hit<arith::value_t<K>>> intersection(K& k, const polygon3& g, const S& x) {
    if (!finite(x) || !polygon3d::usable(k, g) || !polygon3d::linear_meets(k, g, as_linear(x))) return std::nullopt;
    const linear3 s = as_linear(x);
    auto hit = [&](const contact_end& e) {
        const auto v = end_value_and_point(k, e, s);
        return polygon_hit<arith::value_t<K>>{v.t, v.point};
    };
    if (s.is_point()) return hit(domain_end(domain_low(s)));
    const point3 a = g.vertices[g.plane_vertices[0]], b = g.vertices[g.plane_vertices[1]], c = g.vertices[g.plane_vertices[2]];
    const sign nd = arith::sgn<arith::hint::structural>(k, [=](auto L) { return arith::dot(polygon3d::normal(L, g), s.D(L)); });
    if (nd != sign::zero) return hit(contact_end{end_kind::plane_crossing, 0.0, a, b, c, 2, nd});
    if (s.bounded_below() && intersects(k, s.o, g)) return hit(domain_end(0.0));
    std::optional<contact_end> first;
    (void)polygon3d::any_edge(g, [&](const segment3& e) {
        if (const auto r = segment_span(k, s, e.a, e.b))
            if (!first || compare_ends(k, r->enter, *first, s) == sign::negative) first = r->enter;
        return false;
    });
    if (!first) return std::nullopt; // not reached: the polygon is met
    return hit(*first);
}

// The mesh (a closed solid): the least parameter over its triangles; the object's start when that
// lies inside the solid and on no triangle.
template <class K, linear_shape S>
[[nodiscard]] constexpr std::optional<mesh_hit<arith::value_t<K>>> intersection(K& k, const mesh3& m, const S& x) {
    if (!finite(x) || !solid_mesh::well_formed(m)) return std::nullopt;
    const linear3 s = as_linear(x);
    const aabb3 xb = bounds(x);
    std::optional<contact_end> first;
    std::size_t first_triangle = 0;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        if (!boxes_meet(xb, bounds(t))) continue;
        if (const auto r = triangle_span(k, s, t))
            if (!first || compare_ends(k, r->enter, *first, s) == sign::negative) {
                first = r->enter;
                first_triangle = i;
            }
    }
    using V = arith::value_t<K>;
    const bool at_start = first && s.bounded_below() && compare_ends(k, *first, domain_end(0.0), s) == sign::zero; // on a triangle at 0
    // a line with a zero direction is its origin: inside the solid, it is hit there (at t = 0)
    const bool point_line = !s.bounded_below() && s.is_point();
    if ((s.bounded_below() || (point_line && !first)) && !at_start && intersects(k, m, s.o)) {
        const V zero = arith::exact_value(k, 0.0);
        return mesh_hit<V>{zero, arith::exact_point(k, s.o), arith::vec_value_t<K>{}, zero, zero, zero, mesh_hit<V>::inside};
    }
    if (!first) return std::nullopt;
    const triangle3 t = m.triangle(first_triangle);
    const auto h = triangle_values(k, *first, s, t);
    return mesh_hit<V>{h.t, h.point, h.normal, h.u, h.v, h.w, first_triangle};
}

// --- what conservative reports where its filter could not decide ----------------------------------
// A hit that may exist (exists uncertain), every value enclosed whatever the hit is: t within the
// object's range, the point within the set's bounds and the object's, barycentrics within [0, 1].
[[nodiscard]] constexpr interval range_of(const linear3& s) {
    constexpr double inf = __builtin_huge_val();
    return {s.kind == extent::line ? -inf : 0.0, s.kind == extent::segment ? 1.0 : inf};
}
inline constexpr interval3 everywhere{arith::whole_line, arith::whole_line, arith::whole_line};
[[nodiscard]] constexpr interval3 box_interval(const aabb3& b) { return {{b.min.x, b.max.x}, {b.min.y, b.max.y}, {b.min.z, b.max.z}}; }
[[nodiscard]] constexpr interval3 met(const interval3& a, const interval3& b) {
    return {arith::intersected(a.x, b.x), arith::intersected(a.y, b.y), arith::intersected(a.z, b.z)};
}
[[nodiscard]] constexpr interval3 reach_of(const plane3&) { return everywhere; }
[[nodiscard]] constexpr interval3 reach_of(const convex_polyhedron3&) { return everywhere; }
[[nodiscard]] constexpr interval3 reach_of(const frustum3&) { return everywhere; }
[[nodiscard]] constexpr interval3 reach_of(const aabb3& b) { return box_interval(b); }
template <int N>
[[nodiscard]] constexpr interval3 reach_of(const kdop<N>& b) {
    return {{b.min[0], b.max[0]}, {b.min[1], b.max[1]}, {b.min[2], b.max[2]}};
}
[[nodiscard]] constexpr interval3 reach_of(const obb3& b) { // c +- sum |h_i a_i|, rounded outward
    auto axis = [&](double c, double a0, double a1, double a2) {
        interval r = arith::point_interval(c);
        const double a[3] = {a0, a1, a2};
        for (int i = 0; i < 3; ++i) {
            const interval e =
                arith::mul(arith::point_interval(arith::abs(a[i])), arith::point_interval(b.half_extents[static_cast<unsigned>(i)]));
            r = arith::add(r, interval{-e.hi, e.hi});
        }
        return r;
    };
    return {axis(b.center.x, b.axes[0].x, b.axes[1].x, b.axes[2].x), axis(b.center.y, b.axes[0].y, b.axes[1].y, b.axes[2].y),
            axis(b.center.z, b.axes[0].z, b.axes[1].z, b.axes[2].z)};
}
[[nodiscard]] constexpr interval3 reach_of(const tetrahedron3& t) { return box_interval(bounds(t)); }
[[nodiscard]] constexpr interval3 reach_of(const triangle3& t) { return box_interval(bounds(t)); }
[[nodiscard]] constexpr interval3 reach_of(const sphere3& b) {
    const double r = arith::abs(b.radius);
    return {arith::add(arith::point_interval(b.center.x), {-r, r}), arith::add(arith::point_interval(b.center.y), {-r, r}),
            arith::add(arith::point_interval(b.center.z), {-r, r})};
}
[[nodiscard]] constexpr interval3 reach_of(const polygon3& g) {
    if (g.vertices.empty()) return everywhere;
    return box_interval(bounds(g.vertices.data(), g.vertices.size()));
}
[[nodiscard]] constexpr interval3 reach_of(const mesh3& m) {
    if (m.vertices.empty()) return everywhere;
    return box_interval(bounds(m.vertices.data(), m.vertices.size()));
}
template <linear_shape S>
[[nodiscard]] constexpr interval3 reach_of_linear(const S& x) {
    return box_interval(bounds(x));
}

template <class Set, linear_shape S>
[[nodiscard]] constexpr auto possible_hit(const Set& set, const S& x) {
    const linear3 s = as_linear(x);
    const interval t = range_of(s);
    const interval3 point = met(reach_of(set), reach_of_linear(x));
    constexpr interval unit{0.0, 1.0};
    constexpr certainty maybe = certainty::uncertain;
    if constexpr (std::is_same_v<Set, triangle3>) {
        auto n = [&](int axis) {
            return arith::enclosed_value([=](auto L) {
                const auto A = arith::lift(L, set.a);
                return pick(arith::cross(arith::lift(L, set.b) - A, arith::lift(L, set.c) - A), axis);
            });
        };
        return std::optional{triangle_hit<interval>{t, point, interval3{n(0), n(1), n(2)}, unit, unit, unit, maybe}};
    } else if constexpr (std::is_same_v<Set, mesh3>) {
        return std::optional{mesh_hit<interval>{t, point, everywhere, unit, unit, unit, mesh_hit<interval>::unknown, maybe}};
    } else if constexpr (std::is_same_v<Set, polygon3>) {
        return std::optional{polygon_hit<interval>{t, point, maybe}};
    } else {
        return std::optional{span_hit<interval>{t, t, point, maybe}};
    }
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template std::optional<span_hit<double>> exactly<intersection_body>(const plane3&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const plane3&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const plane3&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const aabb3&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const aabb3&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const aabb3&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const obb3&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const obb3&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const obb3&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<6>&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<6>&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<6>&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<14>&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<14>&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<14>&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<18>&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<18>&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<18>&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<26>&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<26>&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const kdop<26>&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const frustum3&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const frustum3&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const frustum3&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const convex_polyhedron3&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const convex_polyhedron3&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const convex_polyhedron3&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const tetrahedron3&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const tetrahedron3&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const tetrahedron3&, const line3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const sphere3&, const ray3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const sphere3&, const segment3&);
extern template std::optional<span_hit<double>> exactly<intersection_body>(const sphere3&, const line3&);
extern template std::optional<triangle_hit<double>> exactly<intersection_body>(const triangle3&, const ray3&);
extern template std::optional<triangle_hit<double>> exactly<intersection_body>(const triangle3&, const segment3&);
extern template std::optional<triangle_hit<double>> exactly<intersection_body>(const triangle3&, const line3&);
extern template std::optional<polygon_hit<double>> exactly<intersection_body>(const polygon3&, const ray3&);
extern template std::optional<polygon_hit<double>> exactly<intersection_body>(const polygon3&, const segment3&);
extern template std::optional<polygon_hit<double>> exactly<intersection_body>(const polygon3&, const line3&);
extern template std::optional<mesh_hit<double>> exactly<intersection_body>(const mesh3&, const ray3&);
extern template std::optional<mesh_hit<double>> exactly<intersection_body>(const mesh3&, const segment3&);
extern template std::optional<mesh_hit<double>> exactly<intersection_body>(const mesh3&, const line3&);
} // namespace incidence::detail
