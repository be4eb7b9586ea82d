// Where a linear object meets a segment, a triangle, a flat tetrahedron's faces, a polygon's edges
// or a mesh: the parameter range of the contact, as ends that can be compared across shapes, and
// their values. What intersection() shares for the triangle, the tetrahedron, the polygon and the
// mesh.
// Semantics: the object is o + t D over its own range (ray t >= 0, segment [0, 1] with D = e - o
// taken exactly, line every t; D = 0 is the point o, met at every t of its range). Closed sets.
// Method: each end of a contact range is one of five parameters, kept as data (contact_end) and
// turned back into a ratio t = N / S of polynomials when compared or evaluated (with_ratio):
//   domain          0, 1 or +-infinity (the object's own bound);
//   plane_crossing  the crossing with the plane of p, q, r: n . (p - o) / n . D, n = (q - p) x (r - p)
//                   (degree 3 / 3);
//   edge_clip       an in-plane edge p -> q of a coplanar triangle, in the projection dropping `axis`:
//                   -cross2(q - p, o - p) / cross2(q - p, D) (degree 2 / 2);
//   segment_cross   the crossing with the segment p q in that projection:
//                   cross2(p - o, q - p) / cross2(D, q - p) (degree 2 / 2);
//   on_line         the point p on the object's line: (p - o) . D / D . D (degree 2 / 2).
// Two ends compare by the sign of N1 S2 - N2 S1 times the signs of S1 and S2 (kept with each end),
// degree <= 6. A segment: skew (det(D, p - o, q - o) != 0) misses; crossing in the plane they share
// (a projection where D x (q - p) is not zero) meets at one parameter when both parameters lie in
// range (Schneider and Eberly, Geometric Tools for Computer Graphics, 2003, section 11.1); parallel
// and on the line, the range between the end points' on_line parameters. A triangle: existence by
// linear_triangle (engines/triangle.cppm); crossing its plane (n . D != 0), one plane_crossing end;
// in its plane, the range inside the three edges' half-planes (the clip of engines/clip.cppm in 2D,
// Cyrus and Beck 1978); a degenerate triangle, the union of its edges' ranges (they overlap, as
// the edges are connected).
module;
#include <optional>
export module incidence.detail:engines.contact;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.triangle;
import :engines.clip;

export namespace incidence::detail {

enum class end_kind : unsigned char { domain, plane_crossing, edge_clip, segment_cross, on_line };

struct contact_end {
    end_kind kind = end_kind::domain;
    double bound = 0.0;        // domain: the object's own bound
    point3 p{}, q{}, r{};      // the plane's, edge's or segment's points (on_line: p)
    int axis = 2;              // the projection of edge_clip and segment_cross
    sign den = sign::positive; // the sign of the ratio's denominator
};

// A range of parameters, enter <= exit.
struct contact_span {
    contact_end enter, exit;
};

[[nodiscard]] constexpr contact_end domain_end(double bound) { return {end_kind::domain, bound}; }
[[nodiscard]] constexpr double domain_low(const linear3& s) { return s.kind == extent::line ? -__builtin_huge_val() : 0.0; }
[[nodiscard]] constexpr double domain_high(const linear3& s) { return s.kind == extent::segment ? 1.0 : __builtin_huge_val(); }

// Calls f with the ratio t(L) of a non-domain end (f(ratio_fn) for a generic ratio_fn(L) -> ratio).
template <class F>
constexpr decltype(auto) with_ratio(const contact_end& e, const linear3& s, F&& f) {
    const point3 p = e.p, q = e.q, r = e.r;
    const int axis = e.axis;
    switch (e.kind) {
    case end_kind::plane_crossing:
        return f([=](auto L) {
            const auto P = arith::lift(L, p);
            const auto n = arith::cross(arith::lift(L, q) - P, arith::lift(L, r) - P);
            return arith::ratio{arith::dot(n, P - s.O(L)), arith::dot(n, s.D(L))};
        });
    case end_kind::edge_clip:
        return f([=](auto L) {
            const auto P = arith::lift(L, p);
            const auto E = drop_axis(arith::lift(L, q) - P, axis);
            return arith::ratio{-arith::cross(E, drop_axis(s.O(L) - P, axis)), arith::cross(E, drop_axis(s.D(L), axis))};
        });
    case end_kind::segment_cross:
        return f([=](auto L) {
            const auto P = arith::lift(L, p);
            const auto E = drop_axis(arith::lift(L, q) - P, axis);
            return arith::ratio{arith::cross(drop_axis(P - s.O(L), axis), E), arith::cross(drop_axis(s.D(L), axis), E)};
        });
    default: // on_line
        return f([=](auto L) {
            const auto D = s.D(L);
            return arith::ratio{arith::dot(arith::lift(L, p) - s.O(L), D), arith::dot(D, D)};
        });
    }
}

// sign(t(e1) - t(e2)).
template <class K>
[[nodiscard]] constexpr sign compare_ends(K& k, const contact_end& e1, const contact_end& e2, const linear3& s) {
    if (e1.kind == end_kind::domain && e2.kind == end_kind::domain)
        return e1.bound < e2.bound ? sign::negative : (e1.bound > e2.bound ? sign::positive : sign::zero);
    if (e2.kind == end_kind::domain) return -compare_ends(k, e2, e1, s);
    if (e1.kind == end_kind::domain) { // bound - N / S: 0 or 1 against the ratio, infinities against anything
        if (e1.bound == -__builtin_huge_val()) return sign::negative;
        if (e1.bound == __builtin_huge_val()) return sign::positive;
        if (e1.bound == 1.0) // sign(1 - N / S) = sign(S - N) sign(S)
            return with_ratio(e2, s, [&](const auto& t) {
                return k.sgn([=](auto L) {
                    const auto x = t(L);
                    return x.den - x.num;
                }) * e2.den;
            });
        return with_ratio(e2, s, [&](const auto& t) { return -(k.sgn([=](auto L) { return t(L).num; }) * e2.den); }); // 0 - N / S
    }
    return with_ratio(e1, s, [&](const auto& t1) {
        return with_ratio(e2, s, [&](const auto& t2) {
            return k.sgn([=](auto L) {
                const auto a = t1(L);
                const auto b = t2(L);
                return a.num * b.den - b.num * a.den;
            }) * e1.den *
                   e2.den;
        });
    });
}

// The hull of two ranges that meet or touch (the edges of a degenerate triangle, the faces of a flat
// tetrahedron: connected pieces of one convex set).
template <class K>
[[nodiscard]] constexpr contact_span hull_of(K& k, const contact_span& a, const contact_span& b, const linear3& s) {
    return {compare_ends(k, b.enter, a.enter, s) == sign::negative ? b.enter : a.enter,
            compare_ends(k, b.exit, a.exit, s) == sign::positive ? b.exit : a.exit};
}
template <class K>
[[nodiscard]] constexpr std::optional<contact_span> hull_of(K& k, const std::optional<contact_span>& a,
                                                            const std::optional<contact_span>& b, const linear3& s) {
    if (!a) return b;
    if (!b) return a;
    return hull_of(k, *a, *b, s);
}

// The range of s on the closed segment p q.
template <class K>
[[nodiscard]] constexpr std::optional<contact_span> segment_span(K& k, const linear3& s, point3 p, point3 q) {
    const contact_span whole{domain_end(domain_low(s)), domain_end(domain_high(s))};
    if (s.is_point()) {
        if (!linear_linear(k, s, as_linear(segment3{p, q}))) return std::nullopt;
        return whole;
    }
    if (!finite(p) || !finite(q)) return std::nullopt;
    if (p == q) { // a point: on s's line at one parameter
        if (!linear_linear(k, s, as_linear(p))) return std::nullopt;
        const contact_end e{end_kind::on_line, 0.0, p};
        return contact_span{e, e};
    }
    if (k.sgn([=](auto L) { return arith::det3(s.D(L), arith::lift(L, p) - s.O(L), arith::lift(L, q) - s.O(L)); }) != sign::zero)
        return std::nullopt; // skew
    for (int axis = 0; axis < 3; ++axis) {
        const sign c = arith::sgn<arith::hint::structural>(
            k, [=](auto L) { return pick(arith::cross(s.D(L), arith::lift(L, q) - arith::lift(L, p)), axis); });
        if (c == sign::zero) continue;
        // crossing in the common plane: t c = cross2(p - o, q - p), u c = cross2(p - o, D)
        auto lower = [&](bool of_s) { // cross2(p - o, q - p) (t c) or cross2(p - o, D) (u c)
            return k.sgn([=](auto L) {
                const auto P = arith::lift(L, p);
                const auto w = drop_axis(P - s.O(L), axis);
                return arith::cross(w, of_s ? drop_axis(arith::lift(L, q) - P, axis) : drop_axis(s.D(L), axis));
            });
        };
        auto upper = [&](bool of_s) { // (1 - t) c or (1 - u) c
            return k.sgn([=](auto L) {
                const auto P = arith::lift(L, p);
                const auto E = drop_axis(arith::lift(L, q) - P, axis);
                const auto D = drop_axis(s.D(L), axis);
                const auto w = drop_axis(P - s.O(L), axis);
                return arith::cross(D, E) - arith::cross(w, of_s ? E : D);
            });
        };
        auto part = [&](bool of_s, bool is_upper) { return is_upper ? upper(of_s) : lower(of_s); };
        if (part(false, false) == -c || part(false, true) == -c) return std::nullopt; // u outside [0, 1]
        if (s.bounded_below() && part(true, false) == -c) return std::nullopt;        // t < 0
        if (s.bounded_above() && part(true, true) == -c) return std::nullopt;         // t > 1
        const contact_end e{end_kind::segment_cross, 0.0, p, q, {}, axis, c};
        return contact_span{e, e};
    }
    // parallel: on s's line, then the range between the end points' positions
    for (int axis = 0; axis < 3; ++axis)
        if (!arith::is_zero<arith::hint::structural>(k,
                                                     [=](auto L) { return pick(arith::cross(s.D(L), arith::lift(L, p) - s.O(L)), axis); }))
            return std::nullopt;
    const contact_end ep{end_kind::on_line, 0.0, p}, eq{end_kind::on_line, 0.0, q};
    const bool p_first = k.sgn([=](auto L) { return arith::dot(arith::lift(L, q) - arith::lift(L, p), s.D(L)); }) != sign::negative;
    contact_span r{p_first ? ep : eq, p_first ? eq : ep};
    if (compare_ends(k, r.exit, whole.enter, s) == sign::negative || compare_ends(k, r.enter, whole.exit, s) == sign::positive)
        return std::nullopt;
    if (compare_ends(k, r.enter, whole.enter, s) == sign::negative) r.enter = whole.enter;
    if (compare_ends(k, r.exit, whole.exit, s) == sign::positive) r.exit = whole.exit;
    return r;
}

// The range of s on the closed triangle t (degenerate triangles included).
template <class K>
[[nodiscard]] constexpr std::optional<contact_span> triangle_span(K& k, const linear3& s, const triangle3& t) {
    if (!linear_triangle(k, s, t)) return std::nullopt;
    if (s.is_point()) return contact_span{domain_end(domain_low(s)), domain_end(domain_high(s))};
    const point3 a = t.a, b = t.b, c = t.c;
    auto n_of = [=](auto L) {
        const auto A = arith::lift(L, a);
        return arith::cross(arith::lift(L, b) - A, arith::lift(L, c) - A);
    };
    const sign nd = arith::sgn<arith::hint::structural>(k, [=](auto L) { return arith::dot(n_of(L), s.D(L)); });
    if (nd != sign::zero) {
        const contact_end e{end_kind::plane_crossing, 0.0, a, b, c, 2, nd};
        return contact_span{e, e};
    }
    for (int axis = 0; axis < 3; ++axis) {
        const sign o = arith::sgn<arith::hint::structural>(k, [=](auto L) { return pick(n_of(L), axis); });
        if (o == sign::zero) continue;
        // in the plane: the three edges' half-planes o cross2(q - p, x - p) >= 0
        const point3 v[3] = {a, b, c};
        auto con = [=](int i, auto L) {
            const auto P = arith::lift(L, v[i]);
            const auto E = drop_axis(arith::lift(L, v[(i + 1) % 3]) - P, axis);
            const auto A = arith::cross(E, drop_axis(s.O(L) - P, axis));
            const auto B = arith::cross(E, drop_axis(s.D(L), axis));
            return o == sign::positive ? affine{A, B} : affine{-A, -B};
        };
        const auto r = clip(k, con, 3, s.kind);
        if (!r) return std::nullopt;
        auto end_of = [&](int i, bool lower) {
            if (i < 0) return domain_end(lower ? domain_low(s) : domain_high(s));
            // -A / B with the orientation dropped: the denominator cross2(q - p, D) has sign o * sign(B)
            return contact_end{end_kind::edge_clip, 0.0, v[i], v[(i + 1) % 3], {}, axis, lower ? o : -o};
        };
        return contact_span{end_of(r->lower, true), end_of(r->upper, false)};
    }
    // degenerate: the union of its edges' ranges
    return hull_of(k, hull_of(k, segment_span(k, s, a, b), segment_span(k, s, b, c), s), segment_span(k, s, c, a), s);
}

// The value of an end, and the point of s there.
template <class K>
[[nodiscard]] constexpr arith::value_t<K> end_value(K& k, const contact_end& e, const linear3& s) {
    if (e.kind == end_kind::domain) return arith::exact_value(k, e.bound);
    return with_ratio(e, s, [&](const auto& t) { return arith::value(k, t); });
}
template <class K>
[[nodiscard]] constexpr arith::point_value_t<K> end_point(K& k, const contact_end& e, const linear3& s) {
    if (e.kind == end_kind::domain) {
        if (e.bound == 1.0) return arith::exact_point(k, s.q);
        return arith::exact_point(k, s.o); // 0, or a point object's own point
    }
    return with_ratio(e, s,
                      [&](const auto& t) { return arith::point_at(k, t, [=](auto L) { return s.O(L); }, [=](auto L) { return s.D(L); }); });
}
// Both, from one evaluation of the end's ratio.
template <class K>
[[nodiscard]] constexpr arith::value_with_point<K> end_value_and_point(K& k, const contact_end& e, const linear3& s) {
    if (e.kind == end_kind::domain) return {end_value(k, e, s), end_point(k, e, s)};
    return with_ratio(
        e, s, [&](const auto& t) { return arith::value_and_point(k, t, [=](auto L) { return s.O(L); }, [=](auto L) { return s.D(L); }); });
}

} // namespace incidence::detail
