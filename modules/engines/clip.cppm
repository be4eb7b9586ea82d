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
// For a box (every tier), an oriented box and a tetrahedron (the exact tier), the slab test on
// enclosures of the bounds' parameters in double comes first (box_slabs, clip_in_double): where they
// are apart, its choice is the exact one, at the cost of one division per constraint instead of a
// product per comparison.
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

[[nodiscard]] constexpr double component(point3 p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }
[[nodiscard]] constexpr double component(vec3 v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

// --- the clip decided in double --------------------------------------------------------------------
// Where every comparison the clip makes (the tightest lower and upper bounds, each against the others
// of its kind, against 0 and 1, and against each other) holds between enclosures of the bounds'
// parameters that are apart, the choice is the exact one, so every kernel may take it; a tie, or a
// bound at 0 or 1, is left to the kernel's clip (decided false). The slab test of Kay and Kajiya
// (SIGGRAPH 1986) on enclosures.
struct slab_choice {
    bool decided = false;
    std::optional<clipped> range; // nullopt: the object misses the set
};
inline constexpr slab_choice slab_undecided{};
inline constexpr slab_choice slab_misses{true, std::nullopt};

// An enclosure [lo, hi] of a bound's parameter, of constraint `index`.
struct bound_enclosure {
    double lo = 0.0, hi = 0.0;
    int index = -1;
};
// The tightest of the bounds of one kind seen so far, and the nearest end of the others: the largest
// upper end of the other lower bounds (the least lower end of the other upper bounds).
struct tightest {
    bound_enclosure best;
    double rival;
    [[nodiscard]] constexpr bool apart(bool lower) const { return best.index < 0 || (lower ? rival < best.lo : rival > best.hi); }
};
[[nodiscard]] constexpr tightest no_bound(bool lower) { return {{}, lower ? -__builtin_huge_val() : __builtin_huge_val()}; }
constexpr void add_lower(tightest& t, const bound_enclosure& b) {
    if (t.best.index < 0 || b.lo > t.best.lo) {
        if (t.best.index >= 0) t.rival = t.rival < t.best.hi ? t.best.hi : t.rival;
        t.best = b;
    } else t.rival = t.rival < b.hi ? b.hi : t.rival;
}
constexpr void add_upper(tightest& t, const bound_enclosure& b) {
    if (t.best.index < 0 || b.hi < t.best.hi) {
        if (t.best.index >= 0) t.rival = t.rival > t.best.lo ? t.best.lo : t.rival;
        t.best = b;
    } else t.rival = t.rival > b.lo ? b.lo : t.rival;
}

// The range from the tightest bounds, as clip() decides it, where the enclosures decide.
[[nodiscard]] constexpr slab_choice decided_range(const tightest& lower, const tightest& upper, extent x) {
    if (!lower.apart(true) || !upper.apart(false)) return slab_undecided;
    clipped r{lower.best.index, upper.best.index};
    const double ll = lower.best.lo, lh = lower.best.hi, ul = upper.best.lo, uh = upper.best.hi;
    if (x != extent::line && r.lower >= 0) { // t_l <= 0 gives way to the range's own 0
        if (lh < 0.0) r.lower = -1;
        else if (!(ll > 0.0)) return slab_undecided;
    }
    if (x != extent::line && r.upper >= 0) { // t_u < 0: behind the start
        if (uh < 0.0) return slab_misses;
        if (!(ul > 0.0)) return slab_undecided;
    }
    if (x == extent::segment && r.upper >= 0) { // t_u >= 1 gives way to the range's own 1
        if (ul > 1.0) r.upper = -1;
        else if (!(uh < 1.0)) return slab_undecided;
    }
    if (x == extent::segment && r.lower >= 0) { // t_l > 1: beyond the end
        if (ll > 1.0) return slab_misses;
        if (!(lh < 1.0)) return slab_undecided;
    }
    if (r.lower >= 0 && r.upper >= 0) {
        if (ll > uh) return slab_misses;
        if (!(lh < ul)) return slab_undecided;
    }
    return {true, r};
}

// Any constraints, from the semi-static filter's A and B (filtered.cppm: |A - A.v| <= e_A): with
// |B.v| > 2 e_B, the bound t = -A / B is within (e_A + |t| e_B) / (|B.v| - e_B) <= 2 (e_A + |t| e_B) / |B.v|
// of -A.v / B.v, which t = -A.v (1 / B.v) in double approaches within 2.01 u |t| (1 / B.v normal:
// |B.v| < 2^1021). A constraint with B exactly zero (B.p = 0) holds everywhere or nowhere by A's sign.
template <class Con>
[[nodiscard]] constexpr slab_choice clip_in_double(const Con& con, int m, extent x) {
    tightest lower = no_bound(true), upper = no_bound(false);
    for (int i = 0; i < m; ++i) {
        const auto g = con(i, arith::lift_filter{});
        if (g.b.p == 0.0 && g.b.v == 0.0) { // parallel, exactly
            if (g.a.p == 0.0 && g.a.v == 0.0) continue;
            const int sa = arith::proven_sign(g.a);
            if (sa < 0) return slab_misses;
            if (sa == 0) return slab_undecided;
            continue;
        }
        const double ea = arith::error_bound(g.a), eb = arith::error_bound(g.b), bv = g.b.v;
        if (!(g.a.p >= 0x1p-900 && g.b.p >= 0x1p-900 && arith::abs(bv) > 2.0 * eb && arith::abs(bv) < 0x1p1021 && finite(g.a.v)))
            return slab_undecided;
        const double inv = 1.0 / bv;
        const double t = -g.a.v * inv;
        const double w = ((ea + arith::abs(t) * eb) * (2.0 * arith::abs(inv)) + arith::abs(t) * 0x1p-51) * (1.0 + 0x1p-20) + 0x1p-1020;
        if (!finite(t) || !finite(w)) return slab_undecided;
        const bound_enclosure e{t - w, t + w, i};
        if (bv > 0.0) add_lower(lower, e);
        else add_upper(upper, e);
    }
    return decided_range(lower, upper, x);
}

// The box's faces (box_constraints: 2 axis for min, 2 axis + 1 for max): t = (f - o_i) (1 / D_i) in
// double (D_i = q_i - o_i for a segment) has at most four roundings, so |t - exact| <= 4.01 u |t| +
// 2^-1074 while 1 / D_i is normal (|D_i| < 2^1021); t -+ (2^-50 |t| + 2^-1020) holds it with room
// for its own rounding (the slack a normal number: a subnormal operand costs a microcode assist).
// The direction's signs select without branches, which random rays mispredict.
[[nodiscard]] constexpr slab_choice box_slabs(const aabb3& box, const linear3& s) {
    tightest lower = no_bound(true), upper = no_bound(false);
    bool usable = true;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = component(s.o, axis), lo_face = component(box.min, axis), hi_face = component(box.max, axis);
        const double d = s.kind == extent::segment ? component(s.q, axis) - o : component(s.d, axis);
        if (d == 0.0) { // parallel (the sign of q_i - o_i in double is exact)
            if (o < lo_face || o > hi_face) return slab_misses;
            continue;
        }
        usable = usable && arith::abs(d) < 0x1p1021;
        const double inv = 1.0 / d;
        const double t_min = (lo_face - o) * inv, t_max = (hi_face - o) * inv;
        const bool up = d > 0.0;
        const double tn = up ? t_min : t_max, tf = up ? t_max : t_min;
        const double wn = arith::abs(tn) * 0x1p-50 + 0x1p-1020, wf = arith::abs(tf) * 0x1p-50 + 0x1p-1020;
        usable = usable && finite(tn) && finite(tf);
        add_lower(lower, {tn - wn, tn + wn, up ? 2 * axis : 2 * axis + 1});
        add_upper(upper, {tf - wf, tf + wf, up ? 2 * axis + 1 : 2 * axis});
    }
    if (!usable) return slab_undecided;
    return decided_range(lower, upper, s.kind);
}

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
// clip_span, the exact tier first trying the choice in double (clip_in_double). Taken where it
// measured faster: the oriented box's faces and the tetrahedron's in the exact tier (bench/NOTES.md).
// On the half-space sets of a frustum or a convex polyhedron it measured slower, and in the
// approximate tier, whose signs are plain double already; the other tiers keep the body whose
// branches the approximate tier's stated bound refers to (the plain filter deciding every sign).
template <class K, class Con>
[[nodiscard]] constexpr std::optional<span_hit<arith::value_t<K>>> clip_span_in_double(K& k, const Con& con, int m, const linear3& s) {
    if (arith::value_mode_of<K>() == arith::value_mode::rounded &&
        !__builtin_is_constant_evaluated()) // the filter's infinities are run-time only
        if (const slab_choice c = clip_in_double(con, m, s.kind); c.decided) {
            if (!c.range) return std::nullopt;
            return clipped_values(k, con, *c.range, s);
        }
    return clip_span(k, con, m, s);
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
