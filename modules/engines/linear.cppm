// segment3 against segment3, and the body every pair of linear objects shares: points, segments,
// rays and lines against each other (line_line, line_point, line_ray, line_segment, point_point,
// point_ray, point_segment, ray_ray, ray_segment, segment_segment), the linear object of
// ray_triangle, segment_triangle and line_triangle, and the same ten pairs in the plane
// (line2_line2 ... segment2_segment2, where the projection below is the identity).
// Semantics: closed sets. A segment includes its end points, a ray its origin; a segment with
// equal end points, a ray or a line with a zero direction, is its one point. Touching at an end
// point counts; collinear overlaps (even in one point) count.
// Method (exact tiers): for points, segments and rays, bounding boxes apart reject first
// (comparisons, exact; a ray's box is unbounded where its direction moves). Then signs only, as
// CGAL's Segment_3/Segment_3 do_intersect. For s = O + t D and r = P + u E (D = q - o taken
// exactly inside each predicate for a segment), w = P - O:
//   a point against a point: the three coordinate differences are zero;
//   det(D, E, w) != 0: skew, no;
//   D x E != 0 (coplanar, not parallel): drop an axis where (D x E)_i != 0 (injective on the
//     common plane); with c = cross2(D, E), t = cross2(w, E) / c and u = cross2(w, D) / c, each
//     bound is a sign: t >= 0 iff cross2(w, E) c >= 0, t <= 1 iff (c - cross2(w, E)) c >= 0;
//   D x E == 0 (parallel, or r a point): D x w == 0 (on s's line), then the 1D overlap of the
//     positions along D, (x - O) . D: s spans [0, D . D] (a ray [0, inf), a line everything),
//     r starts at w . D and runs towards sign(E . D).
// Every sign is of a homogeneous polynomial of degree <= 4 (<= 2 in the plane). Two lines that
// cross decide without their origins, which are then checked to be finite (see finite()).
// Source: the coplanar reduction of Schneider and Eberly, Geometric Tools for Computer Graphics
// (2003), section 11.1 (linear components), with the parameter comparisons written as signs of
// products instead of quotients; the 2D crossing as in O'Rourke, Computational Geometry in C,
// 2nd ed. (1998), section 1.5; Ericson, Real-Time Collision Detection (2005), section 4.2.1 (the
// bounding boxes).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/segment_segment.cpp and the other linear pairs' tests).
module;
#include <type_traits>
#include <cstddef>
export module incidence.detail:engines.linear;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::detail {

enum class extent : unsigned char { ray, segment, line };

// The linear object o + t d: t >= 0 for a ray, 0 <= t <= 1 for a segment (d = q - o, exact),
// every t for a line; in 3D (linear3) or in the plane (linear2).
template <class Point, class Vec>
struct basic_linear {
    Point o;
    Vec d;   // ray or line direction (unused for a segment)
    Point q; // segment end (unused for a ray or a line)
    extent kind;

    template <class L>
    [[nodiscard]] constexpr auto O(L l) const {
        return arith::lift(l, o);
    }
    template <class L>
    [[nodiscard]] constexpr auto D(L l) const {
        if (kind == extent::segment) return arith::lift(l, q) - arith::lift(l, o);
        // Same expression type as the segment branch: d = (d - 0) with 0 exact.
        return arith::lift(l, d) - arith::lift(l, Vec{});
    }
    [[nodiscard]] constexpr bool is_point() const { return kind == extent::segment ? o == q : d == Vec{}; }
    [[nodiscard]] constexpr bool bounded_below() const { return kind != extent::line; }    // t >= 0
    [[nodiscard]] constexpr bool bounded_above() const { return kind == extent::segment; } // t <= 1
};
using linear3 = basic_linear<point3, vec3>;
using linear2 = basic_linear<point2, vec2>;

// Finite, by comparisons only (so also in constant evaluation, where inf - inf is ill-formed).
// Bodies that can decide without reading every input (a plane crossed by a line through a
// point on it needs no direction) check the unread inputs with it: a NaN or infinite input is
// no shape, and the exact tier answers no for it.
[[nodiscard]] constexpr bool finite(double x) { return x >= -0x1.fffffffffffffp1023 && x <= 0x1.fffffffffffffp1023; }
[[nodiscard]] constexpr bool finite(vec3 v) { return finite(v.x) && finite(v.y) && finite(v.z); }
[[nodiscard]] constexpr bool finite(point3 p) { return finite(p.x) && finite(p.y) && finite(p.z); }
[[nodiscard]] constexpr bool finite(vec2 v) { return finite(v.x) && finite(v.y); }
[[nodiscard]] constexpr bool finite(point2 p) { return finite(p.x) && finite(p.y); }
[[nodiscard]] constexpr bool finite(const tetrahedron3& t) { return finite(t.a) && finite(t.b) && finite(t.c) && finite(t.d); }
[[nodiscard]] constexpr bool finite(const triangle3& t) { return finite(t.a) && finite(t.b) && finite(t.c); }
[[nodiscard]] constexpr bool finite(const segment3& s) { return finite(s.a) && finite(s.b); }
[[nodiscard]] constexpr bool finite(const ray3& r) { return finite(r.origin) && finite(r.direction); }
[[nodiscard]] constexpr bool finite(const line3& l) { return finite(l.origin) && finite(l.direction); }
[[nodiscard]] constexpr bool finite(const segment2& s) { return finite(s.a) && finite(s.b); }
[[nodiscard]] constexpr bool finite(const ray2& r) { return finite(r.origin) && finite(r.direction); }

// A fixed order of two lists of n numbers (lexicographic; a NaN compares as equal), so a pair
// runs on one order of its two shapes whichever way they come: the plain-double tier then also
// answers the same for (a, b) and (b, a).
[[nodiscard]] constexpr bool numbers_before(const double* x, const double* y, int n) {
    for (int i = 0; i < n; ++i)
        if (x[i] != y[i] && x[i] == x[i] && y[i] == y[i]) return x[i] < y[i];
    return false;
}
// x clamped into [lo, hi] (lo <= hi); a NaN gives lo.
[[nodiscard]] constexpr double clamp(double x, double lo, double hi) { return x > lo ? (x < hi ? x : hi) : lo; }

[[nodiscard]] constexpr linear3 as_linear(const segment3& s) { return {s.a, vec3{0, 0, 0}, s.b, extent::segment}; }
[[nodiscard]] constexpr linear3 as_linear(const ray3& r) { return {r.origin, r.direction, r.origin, extent::ray}; }
[[nodiscard]] constexpr linear3 as_linear(const line3& l) { return {l.origin, l.direction, l.origin, extent::line}; }
[[nodiscard]] constexpr linear3 as_linear(const point3& p) { return {p, vec3{0, 0, 0}, p, extent::segment}; }
[[nodiscard]] constexpr linear2 as_linear(const segment2& s) { return {s.a, vec2{0, 0}, s.b, extent::segment}; }
[[nodiscard]] constexpr linear2 as_linear(const ray2& r) { return {r.origin, r.direction, r.origin, extent::ray}; }
[[nodiscard]] constexpr linear2 as_linear(const line2& l) { return {l.origin, l.direction, l.origin, extent::line}; }
[[nodiscard]] constexpr linear2 as_linear(const point2& p) { return {p, vec2{0, 0}, p, extent::segment}; }

// Axis-aligned bounds, for the rejection every tier shares: two closed sets whose bounds lie apart
// along some axis do not meet. Comparisons only, so exact in every kernel and in constant
// evaluation. The pair bodies read the bounds from the shapes as given (see linear_pair), not from
// a linear3 written just before. (A line's bounds are unbounded but where its direction is zero:
// the line pairs do without.)
// Source: Ericson, Real-Time Collision Detection (2005), section 4.2.1 (AABB overlap test).
struct box2 {
    point2 min, max;
};
[[nodiscard]] constexpr double min2(double a, double b) { return b < a ? b : a; }
[[nodiscard]] constexpr double max2(double a, double b) { return a < b ? b : a; }
[[nodiscard]] constexpr aabb3 bounds(const point3* pts, std::size_t n) {
    aabb3 b{pts[0], pts[0]};
    for (std::size_t i = 1; i < n; ++i) {
        const point3 v = pts[i];
        b.min = point3{min2(b.min.x, v.x), min2(b.min.y, v.y), min2(b.min.z, v.z)};
        b.max = point3{max2(b.max.x, v.x), max2(b.max.y, v.y), max2(b.max.z, v.z)};
    }
    return b;
}
[[nodiscard]] constexpr box2 bounds(const point2* pts, std::size_t n) {
    box2 b{pts[0], pts[0]};
    for (std::size_t i = 1; i < n; ++i) {
        const point2 v = pts[i];
        b.min = point2{min2(b.min.x, v.x), min2(b.min.y, v.y)};
        b.max = point2{max2(b.max.x, v.x), max2(b.max.y, v.y)};
    }
    return b;
}
[[nodiscard]] constexpr bool boxes_meet(const aabb3& a, const aabb3& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}
[[nodiscard]] constexpr bool boxes_meet(const box2& a, const box2& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}
[[nodiscard]] constexpr aabb3 bounds(point3 p) { return {p, p}; }
[[nodiscard]] constexpr box2 bounds(point2 p) { return {p, p}; }
[[nodiscard]] constexpr aabb3 bounds(const segment3& s) {
    const point3 v[2] = {s.a, s.b};
    return bounds(v, 2);
}
[[nodiscard]] constexpr box2 bounds(const segment2& s) {
    const point2 v[2] = {s.a, s.b};
    return bounds(v, 2);
}
[[nodiscard]] constexpr aabb3 bounds(const triangle3& t) {
    const point3 v[3] = {t.a, t.b, t.c};
    return bounds(v, 3);
}
[[nodiscard]] constexpr aabb3 bounds(const tetrahedron3& t) {
    const point3 v[4] = {t.a, t.b, t.c, t.d};
    return bounds(v, 4);
}
// A ray's bounds: unbounded along each axis its direction moves on, towards the direction's sign.
template <class Point, class Box>
[[nodiscard]] constexpr Box ray_box(const Point& o, const auto& d) {
    constexpr double inf = __builtin_huge_val();
    Box b{o, o};
    if (d.x < 0.0) b.min.x = -inf;
    if (d.x > 0.0) b.max.x = inf;
    if (d.y < 0.0) b.min.y = -inf;
    if (d.y > 0.0) b.max.y = inf;
    if constexpr (requires { o.z; }) {
        if (d.z < 0.0) b.min.z = -inf;
        if (d.z > 0.0) b.max.z = inf;
    }
    return b;
}
[[nodiscard]] constexpr aabb3 bounds(const ray3& r) { return ray_box<point3, aabb3>(r.origin, r.direction); }
[[nodiscard]] constexpr box2 bounds(const ray2& r) { return ray_box<point2, box2>(r.origin, r.direction); }
// A line's bounds: unbounded both ways along each axis its direction moves on.
[[nodiscard]] constexpr aabb3 bounds(const line3& l) {
    constexpr double inf = __builtin_huge_val();
    aabb3 b{l.origin, l.origin};
    if (l.direction.x != 0.0) b.min.x = -inf, b.max.x = inf;
    if (l.direction.y != 0.0) b.min.y = -inf, b.max.y = inf;
    if (l.direction.z != 0.0) b.min.z = -inf, b.max.z = inf;
    return b;
}
// The rejection itself: finite shapes whose bounds are apart. Not for a NaN or an infinite
// coordinate, which goes on to the signs (so classify still calls such input uncertain), and not in
// a kernel that observes the signs (the tests' margin kernel measures how close the signs of the
// case come to zero, whichever way a tier decides it).
template <class K, class A, class B>
[[nodiscard, gnu::always_inline]] constexpr bool boxes_apart(K& k, const A& a, const B& b) {
    if constexpr (requires { k.observe_compare(0.0, 0.0); }) return false;
    else return !boxes_meet(bounds(a), bounds(b)) && finite(a) && finite(b);
}

template <class T>
[[nodiscard]] constexpr auto pick(const arith::v3<T>& v, int axis) {
    return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}
// The projection dropping `axis`, in cyclic order, so cross2 of two projections is (a x b)_axis.
template <class T>
[[nodiscard]] constexpr auto drop_axis(const arith::v3<T>& v, int axis) {
    return axis == 0 ? arith::v2<T>{v.y, v.z} : (axis == 1 ? arith::v2<T>{v.z, v.x} : arith::v2<T>{v.x, v.y});
}

// In the plane there is nothing to drop: the identity projection.
template <class T>
[[nodiscard]] constexpr auto drop_axis(const arith::v2<T>& v, int) {
    return v;
}

// s and r lie on one line, s not a point: do their position ranges along D overlap?
template <class K, class Lin>
[[nodiscard]] constexpr bool collinear_overlap(K& k, const Lin& s, const Lin& r) {
    // Positions of r's end points: (x - O) . D against 0 (s's start) and against D . D (s's end).
    using Point = decltype(s.o);
    auto from_start = [&](Point x) { return k.sgn([&](auto L) { return arith::dot(arith::lift(L, x) - s.O(L), s.D(L)); }); };
    auto from_end = [&](Point x) {
        return k.sgn([&](auto L) {
            const auto D = s.D(L);
            return arith::dot(arith::lift(L, x) - s.O(L), D) - arith::dot(D, D);
        });
    };
    // Which way r runs along D (zero when r is a point).
    const sign dir = r.is_point() ? sign::zero : k.sgn([&](auto L) { return arith::dot(r.D(L), s.D(L)); });
    const bool r_segment = r.kind == extent::segment && dir != sign::zero;
    const bool up = dir != sign::zero && (r.kind == extent::line || (r.kind == extent::ray && dir == sign::positive));
    const bool down = dir != sign::zero && (r.kind == extent::line || (r.kind == extent::ray && dir == sign::negative));
    // Some point of r at a position >= 0 (s's start), unless s has none.
    const bool reaches_start =
        !s.bounded_below() || up || from_start(r.o) != sign::negative || (r_segment && from_start(r.q) != sign::negative);
    if (!reaches_start) return false;
    // Some point of r at a position <= D . D (s's end), unless s has none.
    return !s.bounded_above() || down || from_end(r.o) != sign::positive || (r_segment && from_end(r.q) != sign::positive);
}

// s and r lie in a plane on which dropping `axis` is injective, and cross2(D, E) != 0 there:
// the crossing's parameters t and u are checked against each object's bounds.
template <class K, class Lin>
[[nodiscard]] constexpr bool crossing_2d(K& k, const Lin& s, const Lin& r, int axis, sign c) {
    // t c = cross2(w, E), u c = cross2(w, D); the upper bounds compare them with c itself.
    auto lower = [&](bool of_s) {
        return k.sgn([&](auto L) {
            const auto w = drop_axis(r.O(L) - s.O(L), axis);
            return arith::cross(w, drop_axis(of_s ? r.D(L) : s.D(L), axis));
        });
    };
    auto upper = [&](bool of_s) {
        return k.sgn([&](auto L) {
            const auto D = drop_axis(s.D(L), axis), E = drop_axis(r.D(L), axis);
            const auto w = drop_axis(r.O(L) - s.O(L), axis);
            return arith::cross(D, E) - arith::cross(w, of_s ? E : D);
        });
    };
    if (!s.bounded_below() && !r.bounded_below()) return finite(s.o) && finite(r.o); // two lines cross; origins unread
    if (s.bounded_below() && lower(true) == -c) return false;                        // t < 0
    if (s.bounded_above() && upper(true) == -c) return false;                        // t > 1
    if (r.bounded_below() && lower(false) == -c) return false;                       // u < 0
    if (r.bounded_above() && upper(false) == -c) return false;                       // u > 1
    return true;
}

// Two linear objects in a plane on which dropping `axis` is injective (the triangle pairs' 2D
// step): a crossing, or the collinear overlap.
template <class K, class Lin>
[[nodiscard]] constexpr bool linear_linear_2d(K& k, const Lin& s, const Lin& r, int axis) {
    const sign c = k.sgn([&](auto L) { return arith::cross(drop_axis(s.D(L), axis), drop_axis(r.D(L), axis)); });
    if (c != sign::zero) return crossing_2d(k, s, r, axis, c);
    // Parallel in the plane: r must lie on s's line.
    if (!arith::is_zero(k, [&](auto L) { return arith::cross(drop_axis(s.D(L), axis), drop_axis(r.O(L) - s.O(L), axis)); })) return false;
    return collinear_overlap(k, s, r);
}

// Pairs of one shape type run in one canonical order (the lexicographically smaller shape
// first), so that every tier, plain double included, gives (a, b) and (b, a) the same answer.
[[nodiscard]] constexpr int lex_compare(const double* a, const double* b, int n) {
    for (int i = 0; i < n; ++i) {
        if (a[i] < b[i]) return -1;
        if (a[i] > b[i]) return 1;
    }
    return 0;
}
[[nodiscard]] constexpr bool before(point3 a, point3 b) {
    const double x[3] = {a.x, a.y, a.z}, y[3] = {b.x, b.y, b.z};
    return lex_compare(x, y, 3) < 0;
}
[[nodiscard]] constexpr bool before(point3 a, vec3 u, point3 b, vec3 v) {
    const double x[6] = {a.x, a.y, a.z, u.x, u.y, u.z}, y[6] = {b.x, b.y, b.z, v.x, v.y, v.z};
    return lex_compare(x, y, 6) < 0;
}
[[nodiscard]] constexpr bool before(const segment3& s, const segment3& t) {
    return before(s.a, vec3{s.b.x, s.b.y, s.b.z}, t.a, vec3{t.b.x, t.b.y, t.b.z});
}
[[nodiscard]] constexpr bool before(const ray3& s, const ray3& t) { return before(s.origin, s.direction, t.origin, t.direction); }
[[nodiscard]] constexpr bool before(const line3& s, const line3& t) { return before(s.origin, s.direction, t.origin, t.direction); }
[[nodiscard]] constexpr bool before(point2 a, vec2 u, point2 b, vec2 v) {
    const double x[4] = {a.x, a.y, u.x, u.y}, y[4] = {b.x, b.y, v.x, v.y};
    return lex_compare(x, y, 4) < 0;
}
[[nodiscard]] constexpr bool before(point2 a, point2 b) { return before(a, vec2{0, 0}, b, vec2{0, 0}); }
[[nodiscard]] constexpr bool before(const segment2& s, const segment2& t) {
    return before(s.a, vec2{s.b.x, s.b.y}, t.a, vec2{t.b.x, t.b.y});
}
[[nodiscard]] constexpr bool before(const ray2& s, const ray2& t) { return before(s.origin, s.direction, t.origin, t.direction); }
[[nodiscard]] constexpr bool before(const line2& s, const line2& t) { return before(s.origin, s.direction, t.origin, t.direction); }

// Do the closed linear objects s and r meet?
// The objects are taken by reference and the signs capture them by reference: copied by value
// (80 bytes each, written field by field just before), they were read back with wide loads that
// the stores could not forward, which cost a third of a random point_segment test.
template <class K>
[[nodiscard]] constexpr bool linear_linear(K& k, const linear3& s0, const linear3& r0) {
    const bool swap = s0.is_point() && !r0.is_point(); // a point goes second
    const linear3& s = swap ? r0 : s0;
    const linear3& r = swap ? s0 : r0;
    if (s.is_point()) { // both points
        const point3 a = s.o, b = r.o;
        return arith::is_zero(k, [&](auto L) { return L(a.x) - L(b.x); }) && arith::is_zero(k, [&](auto L) { return L(a.y) - L(b.y); }) &&
               arith::is_zero(k, [&](auto L) { return L(a.z) - L(b.z); });
    }
    // These signs are zero for coplanar objects, by structure in one plane z = c: the filter pass
    // proves those zeros (hint::structural), so such a pair needs no exact pass.
    if (!r.is_point()) {
        if (!arith::is_zero<arith::hint::structural>(k, [&](auto L) { return arith::det3(s.D(L), r.D(L), r.O(L) - s.O(L)); }))
            return false; // skew
        for (int axis = 0; axis < 3; ++axis) {
            const auto component = [&](auto L) { return pick(arith::cross(s.D(L), r.D(L)), axis); };
            // In a filter pass the structure first (compares only): the skew test's zero above
            // was proven by structure or settled exactly (so both directions are finite), or the
            // pass has failed already and its answer is not used. Random lines never get here.
            if constexpr (std::is_base_of_v<arith::filter_kernel, K>)
                if (arith::zero_by_structure(component)) continue;
            const sign c = arith::sgn<arith::hint::structural>(k, component);
            if (c != sign::zero) return crossing_2d(k, s, r, axis, c);
        }
    }
    // Parallel, or r a point: r must lie on s's line.
    for (int axis = 0; axis < 3; ++axis)
        if (!arith::is_zero<arith::hint::structural>(k, [&](auto L) { return pick(arith::cross(s.D(L), r.O(L) - s.O(L)), axis); }))
            return false;
    return collinear_overlap(k, s, r);
}

// The same in the plane: a crossing (cross2(D, E) != 0), or r on s's line and the 1D overlap.
template <class K>
[[nodiscard]] constexpr bool linear_linear(K& k, const linear2& s0, const linear2& r0) {
    const bool swap = s0.is_point() && !r0.is_point(); // a point goes second
    const linear2& s = swap ? r0 : s0;
    const linear2& r = swap ? s0 : r0;
    if (s.is_point()) { // both points
        const point2 a = s.o, b = r.o;
        return arith::is_zero(k, [&](auto L) { return L(a.x) - L(b.x); }) && arith::is_zero(k, [&](auto L) { return L(a.y) - L(b.y); });
    }
    if (!r.is_point()) return linear_linear_2d(k, s, r, 0);
    if (!arith::is_zero(k, [&](auto L) { return arith::cross(s.D(L), r.O(L) - s.O(L)); })) return false;
    return collinear_overlap(k, s, r);
}

// A pair of points, segments or rays as given: their bounds first (boxes_apart), read from the
// shapes (from a linear3 written just before, they would wait on its stores), then linear_linear.
// The line pairs call linear_linear directly.
template <class K, class A, class B>
[[nodiscard, gnu::always_inline]] constexpr bool linear_pair(K& k, const A& a, const B& b) {
    return !boxes_apart(k, a, b) && linear_linear(k, as_linear(a), as_linear(b));
}

} // namespace incidence::detail
