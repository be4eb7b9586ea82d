// The part of a linear object inside a set of constraints, and its values: what intersection()
// returns for a line, a ray or a segment against a plane, a box, an oriented box, a k-DOP, a
// frustum, a convex polyhedron, a tetrahedron, a triangle's plane section, or a segment.
// Semantics: the object is o + t D over its own range (ray t >= 0, segment t in [0, 1] with D taken
// exactly as e - o inside each polynomial, line every t); each constraint is g(t) = A + t B >= 0 with
// A, B polynomials in the inputs (a half-space n . x <= c gives A = c - n . o, B = -n . D). The
// object's part in the set is the range between the tightest lower bound t = -A / B (B > 0) and the
// tightest upper one (B < 0), clipped to the object's range; with B = 0 the constraint holds
// everywhere (A >= 0) or nowhere.
// Method (every tier): the generalised slab method of Cyrus and Beck (Computers & Graphics 3(1),
// 1978), with every comparison of two bounds written as the sign of a product instead of a quotient:
// for two bounds of one kind (B_i B_j > 0), t_i - t_j has the sign of A_j B_i - A_i B_j; a lower
// bound against an upper one, of A_l B_u - A_u B_l; a bound against 0, of -A / B; against 1, of
// -(A + B) / B. The kernel decides each sign (degree 2 deg(A) at most), so the chosen bounds are the
// exact ones in the exact tier; the values t = -A / B and the point o + t D are then computed once,
// as the kernel computes values (arith::value, arith::point_at: correctly rounded, enclosed, or plain).
module;
#include <optional>
#include <utility>
export module incidence.detail:engines.clip;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;

export namespace incidence::detail {

// g(t) = a + t b; a and b lifted polynomials of one lift.
template <class A, class B>
struct affine {
    A a;
    B b;
};
template <class A, class B>
affine(A, B) -> affine<A, B>;

// The clipped range as the constraints that bound it: lower/upper index a constraint, or is -1 for
// the object's own bound (0 or -infinity below, 1 or +infinity above).
struct clipped {
    int lower = -1, upper = -1;
};

// Constraints: con(i, L) -> affine{A_i(L), B_i(L)} for i in [0, m).
template <class K, class Con>
[[nodiscard]] constexpr std::optional<clipped> clip(K& k, const Con& con, int m, extent x) {
    clipped r;
    for (int i = 0; i < m; ++i) {
        const sign sb = arith::sgn<arith::hint::structural>(k, [&](auto L) { return con(i, L).b; });
        if (sb == sign::zero) { // parallel: the constraint holds everywhere or nowhere
            if (k.sgn([&](auto L) { return con(i, L).a; }) == sign::negative) return std::nullopt;
            continue;
        }
        int& bound = sb == sign::positive ? r.lower : r.upper;
        if (bound < 0) {
            bound = i;
            continue;
        }
        const int j = bound;
        // t_i - t_j has the sign of A_j B_i - A_i B_j (B_i B_j > 0); a lower bound tightens when larger
        const sign order = k.sgn([&](auto L) {
            const auto gi = con(i, L);
            const auto gj = con(j, L);
            return gj.a * gi.b - gi.a * gj.b;
        });
        if (order == (sb == sign::positive ? sign::positive : sign::negative)) bound = i;
    }
    // The object's own range: t >= 0 (ray, segment), t <= 1 (segment). A bound at exactly 0 or 1 gives
    // way to the range's own bound, which is the same number and exact.
    if (x != extent::line && r.lower >= 0) { // t_l = -A_l / B_l <= 0 iff A_l >= 0
        const int l = r.lower;
        if (k.sgn([&](auto L) { return con(l, L).a; }) != sign::negative) r.lower = -1;
    }
    if (x != extent::line && r.upper >= 0) { // t_u = -A_u / B_u >= 0 iff A_u >= 0
        const int u = r.upper;
        if (k.sgn([&](auto L) { return con(u, L).a; }) == sign::negative) return std::nullopt;
    }
    if (x == extent::segment && r.upper >= 0) { // t_u >= 1 iff A_u + B_u >= 0 (B_u < 0)
        const int u = r.upper;
        if (k.sgn([&](auto L) {
                const auto g = con(u, L);
                return g.a + g.b;
            }) != sign::negative)
            r.upper = -1;
    }
    if (x == extent::segment && r.lower >= 0) { // t_l <= 1 iff A_l + B_l >= 0 (B_l > 0)
        const int l = r.lower;
        if (k.sgn([&](auto L) {
                const auto g = con(l, L);
                return g.a + g.b;
            }) == sign::negative)
            return std::nullopt;
    }
    if (r.lower >= 0 && r.upper >= 0) { // t_l - t_u has the sign of A_l B_u - A_u B_l
        const int l = r.lower, u = r.upper;
        if (k.sgn([&](auto L) {
                const auto gl = con(l, L);
                const auto gu = con(u, L);
                return gl.a * gu.b - gu.a * gl.b;
            }) == sign::positive)
            return std::nullopt;
    }
    return r;
}

// The object's part in the plane A + t B = 0 (one equality, con(0, L)): where B != 0 the single
// parameter t = -A / B, if the object's range holds it (t >= 0 iff A and B differ in sign or A = 0;
// t <= 1 iff A + B and B do not differ); where B = 0, the whole range if A = 0. (As two half-spaces,
// the clip above would compare the plane's bound with itself: a zero no filter proves.)
template <class K, class Con>
[[nodiscard]] constexpr std::optional<clipped> clip_equality(K& k, const Con& con, extent x) {
    const sign sb = arith::sgn<arith::hint::structural>(k, [&](auto L) { return con(0, L).b; });
    if (sb == sign::zero) {
        if (!arith::is_zero<arith::hint::structural>(k, [&](auto L) { return con(0, L).a; })) return std::nullopt;
        return clipped{};
    }
    if (x != extent::line && k.sgn([&](auto L) { return con(0, L).a; }) == sb) return std::nullopt; // t < 0
    if (x == extent::segment && k.sgn([&](auto L) {
            const auto g = con(0, L);
            return g.a + g.b;
        }) == -sb)
        return std::nullopt; // t > 1
    return clipped{0, 0};
}

// The parameter -A_i / B_i of constraint i as a ratio.
template <class Con>
[[nodiscard]] constexpr auto bound_parameter(const Con& con, int i) {
    return [=](auto L) {
        const auto g = con(i, L);
        return arith::ratio{-g.a, g.b};
    };
}

// The values of a clipped range: t_enter, t_exit and the point at t_enter (where t_enter is
// -infinity, at the range's parameter nearest 0: the line's origin, or its exit when that is < 0).
template <class K, class Con>
[[nodiscard]] constexpr span_hit<arith::value_t<K>> clipped_values(K& k, const Con& con, const clipped& r, const linear3& s) {
    constexpr double inf = __builtin_huge_val();
    const double lo = s.kind == extent::line ? -inf : 0.0, hi = s.kind == extent::segment ? 1.0 : inf;
    auto O = [=](auto L) { return s.O(L); };
    auto D = [=](auto L) { return s.D(L); };
    span_hit<arith::value_t<K>> h{arith::exact_value(k, lo), arith::exact_value(k, hi), arith::exact_point(k, s.o)};
    if (r.upper >= 0 && r.upper != r.lower) h.t_exit = arith::value(k, bound_parameter(con, r.upper));
    if (r.lower >= 0) {
        const auto e = arith::value_and_point(k, bound_parameter(con, r.lower), O, D);
        h.t_enter = e.t;
        h.point = e.point;
        if (r.upper == r.lower) h.t_exit = e.t; // an equality: one parameter
    } else if (s.kind == extent::line && r.upper >= 0) {
        const int u = r.upper; // the exit t_u < 0 iff A_u < 0 (B_u < 0)
        if (k.sgn([=](auto L) { return con(u, L).a; }) == sign::negative) h.point = arith::point_at(k, bound_parameter(con, u), O, D);
    }
    return h;
}

template <class K, class Con>
[[nodiscard]] constexpr std::optional<span_hit<arith::value_t<K>>> clip_span(K& k, const Con& con, int m, const linear3& s) {
    const auto r = clip(k, con, m, s.kind);
    if (!r) return std::nullopt;
    return clipped_values(k, con, *r, s);
}

// --- several constraint families -----------------------------------------------------------------
// A set given by families of constraints whose polynomials have different types (the faces of a flat
// zonotope: its plane, its in-plane edges): each family is clipped alone, and the ranges are met
// (the greatest lower bound, the least upper one), comparing bounds of two families by the sign of
// A_j B_i - A_i B_j as within one.
struct family_bound {
    int family = -1; // -1: the object's own bound
    int index = -1;
};
template <class F, class Con, class... More>
constexpr decltype(auto) with_family(int family, F&& f, const Con& con, const More&... more) {
    if constexpr (sizeof...(More) == 0) return f(con);
    else {
        if (family == 0) return f(con);
        return with_family(family - 1, f, more...);
    }
}
// sign(t_a - t_b) for two constraint bounds; lower (B > 0) or upper (B < 0) each.
template <class K, class... Con>
[[nodiscard]] constexpr sign compare_bounds(K& k, family_bound a, bool a_lower, family_bound b, bool b_lower, const Con&... cons) {
    return with_family(
        a.family,
        [&](const auto& ca) {
            return with_family(
                b.family,
                [&](const auto& cb) {
                    // t_a - t_b = (A_b B_a - A_a B_b) / (B_a B_b)
                    const sign s = k.sgn([=, ia = a.index, ib = b.index](auto L) {
                        const auto ga = ca(ia, L);
                        const auto gb = cb(ib, L);
                        return gb.a * ga.b - ga.a * gb.b;
                    });
                    return a_lower == b_lower ? s : -s;
                },
                cons...);
        },
        cons...);
}
// The object's part in the set given by families (con_f, m_f): one clip per family, then the ranges
// met. The values as clipped_values gives them.
template <class K, class... Con>
[[nodiscard]] constexpr std::optional<span_hit<arith::value_t<K>>> clip_families(K& k, const linear3& s,
                                                                                 const std::pair<Con, int>&... fams) {
    family_bound lower, upper;
    int f = 0;
    bool empty = false;
    auto one = [&](const auto& fam) {
        if (empty) return;
        const auto r = clip(k, fam.first, fam.second, s.kind);
        if (!r) {
            empty = true;
            return;
        }
        const family_bound lo{f, r->lower}, hi{f, r->upper};
        if (r->lower >= 0 && (lower.index < 0 || compare_bounds(k, lo, true, lower, true, fams.first...) == sign::positive)) lower = lo;
        if (r->upper >= 0 && (upper.index < 0 || compare_bounds(k, hi, false, upper, false, fams.first...) == sign::negative)) upper = hi;
        ++f;
    };
    (one(fams), ...);
    if (empty) return std::nullopt;
    if (lower.index >= 0 && upper.index >= 0 && compare_bounds(k, lower, true, upper, false, fams.first...) == sign::positive)
        return std::nullopt;
    constexpr double inf = __builtin_huge_val();
    const double lo = s.kind == extent::line ? -inf : 0.0, hi = s.kind == extent::segment ? 1.0 : inf;
    span_hit<arith::value_t<K>> h{arith::exact_value(k, lo), arith::exact_value(k, hi), arith::exact_point(k, s.o)};
    auto O = [=](auto L) { return s.O(L); };
    auto D = [=](auto L) { return s.D(L); };
    if (upper.index >= 0)
        h.t_exit =
            with_family(upper.family, [&](const auto& c) { return arith::value(k, bound_parameter(c, upper.index)); }, fams.first...);
    if (lower.index >= 0) {
        const auto e = with_family(
            lower.family, [&](const auto& c) { return arith::value_and_point(k, bound_parameter(c, lower.index), O, D); }, fams.first...);
        h.t_enter = e.t;
        h.point = e.point;
    } else if (s.kind == extent::line && upper.index >= 0) {
        const bool behind = with_family(
            upper.family, [&](const auto& c) { return k.sgn([=, u = upper.index](auto L) { return c(u, L).a; }) == sign::negative; },
            fams.first...);
        if (behind)
            h.point = with_family(
                upper.family, [&](const auto& c) { return arith::point_at(k, bound_parameter(c, upper.index), O, D); }, fams.first...);
    }
    return h;
}

// --- constraints of the convex shapes --------------------------------------------------------------
// n . x <= c for each plane of a half-space set: A = c 1 - n . o, B = -n . D (degree 2; the lifted 1
// keeps the polynomial homogeneous, see arith's kernel).
[[nodiscard]] constexpr auto halfspace_constraints(const plane3* planes, const linear3& s) {
    return [=](int i, auto L) {
        const auto n = arith::lift(L, planes[i].normal);
        return affine{L(planes[i].offset) * L(1.0) - arith::dot(n, s.O(L)), -arith::dot(n, s.D(L))};
    };
}
// The plane n . x = c as one equality: A = c 1 - n . o, B = -n . D (degree 2).
[[nodiscard]] constexpr auto plane_constraint(const plane3& p, const linear3& s) {
    return [=](int, auto L) {
        const auto n = arith::lift(L, p.normal);
        return affine{L(p.offset) * L(1.0) - arith::dot(n, s.O(L)), -arith::dot(n, s.D(L))};
    };
}
[[nodiscard]] constexpr double component(point3 p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }
// The box's six faces: min_i <= x_i <= max_i (degree 1).
[[nodiscard]] constexpr auto box_constraints(const aabb3& box, const linear3& s) {
    return [=](int i, auto L) {
        const int axis = i / 2;
        const auto o = pick(s.O(L), axis);
        const auto d = pick(s.D(L), axis);
        if (i % 2 == 0) return affine{o - L(component(box.min, axis)), d};
        return affine{L(component(box.max, axis)) - o, -d};
    };
}

} // namespace incidence::detail
