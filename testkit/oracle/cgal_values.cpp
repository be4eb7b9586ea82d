// The exact values of intersection(): where a line, a ray or a segment meets a set, computed over
// CGAL's Epeck (exact rationals) by methods other than the library's, and compared with a double
// (is it the nearest double, ties to even?) or an interval (does it contain the value?).
//   half-space sets (plane, box, k-DOP, convex polyhedron, frustum): t = -a / b per constraint in
//     exact rationals, the largest lower and smallest upper bound (Liang and Barsky);
//   oriented box: the box frame's coordinates u(t) = A^-1 (o + t D - c) by Cramer's rule, clipped
//     to |u_i| <= h_i (declined: dependent axes);
//   tetrahedron, triangle: CGAL::intersection with Tetrahedron_3 / Triangle_3 (a point or a
//     segment), a flat tetrahedron by its faces, a degenerate triangle by its edges;
//   polygon: CGAL's constrained triangulation of it (polygon3_triangles), each triangle as above;
//   mesh: the triangles as above, in the order of a lower bound on their parameters until that
//     bound passes the first contact found, and the object's start inside (mesh_inside);
//   a triangle or tetrahedron that a plane surely separates from the object (interval arithmetic:
//     surely_misses, surely_misses_solid) skips the exact test;
//   ball: the roots of a t^2 + 2 b t + c, compared with a rational y by the signs of a y^2 + 2 b y
//     + c and a y + b (irrational values are never formed).
// The parameter of a point P on the object: (P - o) . D / D . D.
#include "cgal_oracle.hpp"
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <type_traits>
#include <variant>

namespace oracle {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using P3 = K::Point_3;
using V3 = K::Vector_3;

namespace {

// A value: -infinity, +infinity, a rational, or o + t d at a root t of a t^2 + 2 b t + c (a > 0).
struct value {
    enum kind_t { minus_infinity, plus_infinity, rational, root } kind = rational;
    FT q;
    FT a, b, c, o, d;
    bool larger = false;
};
value rational_value(const FT& q) {
    value v;
    v.q = q;
    return v;
}
int sgn(const FT& x) { return CGAL::sign(x); }
// The exact number behind FT: values are compared on it, without building lazy nodes.
using Q = std::decay_t<decltype(CGAL::exact(FT()))>;
int sgn_q(const Q& x) { return CGAL::sign(x); }
// sign(t - z) for the root t
int root_minus(const value& v, const Q& z) {
    const Q& a = CGAL::exact(v.a);
    const Q& b = CGAL::exact(v.b);
    const Q& c = CGAL::exact(v.c);
    const int f = sgn_q(Q(a * z * z + 2 * b * z + c)), w = sgn_q(Q(a * z + b));
    if (!v.larger) {
        if (f < 0) return -1;
        if (f > 0) return w < 0 ? 1 : -1;
        return w <= 0 ? 0 : -1;
    }
    if (f < 0) return 1;
    if (f > 0) return w < 0 ? 1 : -1;
    return w >= 0 ? 0 : 1;
}
// sign(value - y)
int compare(const value& v, const Q& y) {
    switch (v.kind) {
    case value::minus_infinity: return -1;
    case value::plus_infinity: return 1;
    case value::rational: return sgn_q(CGAL::exact(v.q) - y);
    default: {
        const Q& o = CGAL::exact(v.o);
        const Q& d = CGAL::exact(v.d);
        if (sgn_q(d) == 0) return sgn_q(o - y);
        return sgn_q(d) * root_minus(v, Q((y - o) / d));
    }
    }
}
bool rounds_to(const value& v, double x) {
    if (std::isnan(x)) return false;
    // beyond the largest double's upper midpoint 2^1024 - 2^970 (a tie there goes to the even 2^1024)
    const Q overflow = Q(0x1.fffffffffffffp1023) + Q(0x1p970);
    if (std::isinf(x)) {
        if (v.kind == value::plus_infinity || v.kind == value::minus_infinity) return (x > 0) == (v.kind == value::plus_infinity);
        return x > 0 ? compare(v, overflow) >= 0 : compare(v, Q(-overflow)) <= 0;
    }
    if (v.kind == value::minus_infinity || v.kind == value::plus_infinity) return false;
    const double down = std::nextafter(x, -INFINITY), up = std::nextafter(x, INFINITY);
    const Q X(x);
    const int lo = std::isinf(down) ? 1 : compare(v, Q((Q(down) + X) / 2));
    const int hi = std::isinf(up) ? -1 : compare(v, Q((X + Q(up)) / 2));
    if (lo < 0 || hi > 0) return false;
    if (lo == 0 || hi == 0) { // a tie: the even one
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return (bits & 1u) == 0;
    }
    return true;
}
bool within(const value& v, double lo, double hi) {
    if (std::isnan(lo) || std::isnan(hi)) return false;
    const bool above = lo == -INFINITY || (std::isinf(lo) ? false : compare(v, Q(lo)) >= 0);
    const bool below = hi == INFINITY || (std::isinf(hi) ? false : compare(v, Q(hi)) <= 0);
    if (v.kind == value::minus_infinity) return lo == -INFINITY;
    if (v.kind == value::plus_infinity) return hi == INFINITY;
    return above && below;
}
double approx(const value& v) {
    switch (v.kind) {
    case value::minus_infinity: return -INFINITY;
    case value::plus_infinity: return INFINITY;
    case value::rational: return CGAL::to_double(v.q);
    default: {
        const double a = CGAL::to_double(v.a), b = CGAL::to_double(v.b), c = CGAL::to_double(v.c);
        const double s = std::sqrt(std::max(0.0, b * b - a * c));
        const double t = v.larger ? (-b + s) / a : (-b - s) / a;
        return CGAL::to_double(v.o) + t * CGAL::to_double(v.d);
    }
    }
}

// o + t d; q = o + d and the line through them are built once (a mesh's triangles share them).
struct object {
    P3 o;
    V3 d;
    linear_object::kind_t kind;
    P3 q;
    K::Line_3 line;
    bool bounded_below() const { return kind != linear_object::line; }
    bool bounded_above() const { return kind == linear_object::segment; }
};
object object_of(const linear_object& x) {
    const P3 o(x.o[0], x.o[1], x.o[2]);
    if (x.kind == linear_object::segment) {
        const P3 e(x.d[0], x.d[1], x.d[2]);
        return {o, e - o, x.kind, e, o == e ? K::Line_3() : K::Line_3(o, e)};
    }
    const V3 d(x.d[0], x.d[1], x.d[2]);
    return {o, d, x.kind, o + d, d == CGAL::NULL_VECTOR ? K::Line_3() : K::Line_3(o, d)};
}
FT parameter(const object& s, const P3& p) { return (p - s.o) * s.d / (s.d * s.d); }
P3 point_at(const object& s, const FT& t) { return s.o + t * s.d; }

// A span [lo, hi] of parameters (nullopt ends: infinite).
struct span {
    std::optional<FT> lo, hi;
};
std::optional<span> domain(const object& s) {
    span r;
    if (s.bounded_below()) r.lo = FT(0);
    if (s.bounded_above()) r.hi = FT(1);
    return r;
}
// The span within the object's range where a_i + t b_i >= 0 for every constraint.
std::optional<span> clip(const object& s, const std::vector<std::pair<FT, FT>>& g) {
    span r = *domain(s);
    for (const auto& [a, b] : g) {
        if (sgn(b) == 0) {
            if (sgn(a) < 0) return std::nullopt;
            continue;
        }
        const FT t = -a / b;
        if (sgn(b) > 0) {
            if (!r.lo || t > *r.lo) r.lo = t;
        } else if (!r.hi || t < *r.hi) r.hi = t;
    }
    if (r.lo && r.hi && *r.lo > *r.hi) return std::nullopt;
    return r;
}
// The span of a CGAL intersection result (a point or a segment), within the object's range.
std::optional<span> span_of_points(const object& s, const P3& p, const P3& q) {
    FT a = parameter(s, p), b = parameter(s, q);
    if (a > b) std::swap(a, b);
    return span{a, b};
}
std::optional<span> hull(const std::optional<span>& x, const std::optional<span>& y) {
    if (!x) return y;
    if (!y) return x;
    span r;
    if (x->lo && y->lo) r.lo = *x->lo < *y->lo ? *x->lo : *y->lo;
    if (x->hi && y->hi) r.hi = *x->hi > *y->hi ? *x->hi : *y->hi;
    return r;
}
template <class Result>
std::optional<span> span_of_result(const object& s, const Result& res) {
    if (!res) return std::nullopt;
    if (const P3* p = boost::get<P3>(&*res)) return span_of_points(s, *p, *p);
    if (const K::Segment_3* e = boost::get<K::Segment_3>(&*res)) return span_of_points(s, e->source(), e->target());
    return std::nullopt;
}
// The object (not a point) against a CGAL object X. CGAL 5.5's Ray_3 (and Segment_3) against a
// coplanar Triangle_3 can return a segment reaching behind the ray's origin (seen in
// tests/query/intersection/linear_pairs.cpp's polygon cases): the line's part in the triangle. So
// the line's part is asked for and clipped to the object's range here, which is exact either way.
std::optional<span> clipped_to_range(const object& s, std::optional<span> r) {
    if (!r) return r;
    if (s.bounded_below()) {
        if (*r->hi < 0) return std::nullopt;
        if (*r->lo < 0) r->lo = FT(0);
    }
    if (s.bounded_above()) {
        if (*r->lo > 1) return std::nullopt;
        if (*r->hi > 1) r->hi = FT(1);
    }
    return r;
}
template <class X>
std::optional<span> meet(const object& s, const X& x) {
    return clipped_to_range(s, span_of_result(s, CGAL::intersection(s.line, x)));
}
bool is_point(const object& s) { return s.d == CGAL::NULL_VECTOR; }
// The object in interval arithmetic over the exact objects' approximations, for the certified
// misses below: points relative to o, its direction D. Callers hold the rounding upwards
// (CGAL::Protect_FPU_rounding<true>) while they compute with it; a sign is sure when the interval
// excludes zero, and an undecided one decides nothing (the exact test follows).
using I = CGAL::Interval_nt<false>;
using IV = CGAL::Simple_cartesian<I>::Vector_3;
int sure_sign(const I& x) { return x.inf() > 0 ? 1 : (x.sup() < 0 ? -1 : 0); }
struct interval_object {
    const object& s;
    IV D;
    explicit interval_object(const object& x) : s(x), D(CGAL::approx(x.d)) {}
    IV at(const P3& p) const { return CGAL::approx(p) - CGAL::approx(s.o); }
    IV at(const std::array<double, 3>& p) const { return IV(p[0], p[1], p[2]) - (CGAL::approx(s.o) - CGAL::ORIGIN); }
    // The line misses the triangle A B C: its Pluecker products with the edges, det(D, p, q), have
    // strictly opposite signs (a line meeting the closed triangle, degenerate or not, has none).
    bool line_misses(const IV& A, const IV& B, const IV& C) const {
        const int p[3] = {sure_sign(D * CGAL::cross_product(A, B)), sure_sign(D * CGAL::cross_product(B, C)),
                          sure_sign(D * CGAL::cross_product(C, A))};
        return (p[0] > 0 || p[1] > 0 || p[2] > 0) && (p[0] < 0 || p[1] < 0 || p[2] < 0);
    }
    // The object's range lies strictly on the `side` (1 or -1) of the plane n . (x - A) = 0: both ends
    // of a segment, a ray's start with its direction not turning back; never a line.
    bool range_strictly(const IV& n, const IV& A, int side) const {
        if (!s.bounded_below()) return false;
        const I g0 = -(n * A) * I(side), gd = (n * D) * I(side); // the height at t = 0 and its rate
        if (s.bounded_above()) return g0.inf() > 0 && (g0 + gd).inf() > 0;
        return g0.inf() > 0 && gd.inf() >= 0;
    }
    // Every point strictly behind the object's start, or strictly beyond a segment's end, along D.
    bool past_range(std::initializer_list<IV> points) const {
        if (!s.bounded_below()) return false;
        const I dd = D * D;
        bool behind = true, beyond = s.bounded_above();
        for (const IV& x : points) {
            const I t = x * D; // t D . D at the point's projection
            behind = behind && t.sup() < 0;
            beyond = beyond && (t - dd).inf() > 0;
        }
        return behind || beyond;
    }
};
// A certified miss of the triangle a b c by the object (not a point): a plane separates them. Tried:
// the triangle's plane; the plane through the line with normal D x n (n the triangle's normal:
// within the triangle's plane, the line's side); the Pluecker signs of the edges; the planes normal
// to D at the object's ends. Most of a mesh's or a polygon's triangles end here.
bool surely_misses(const object& s, const P3& a, const P3& b, const P3& c) {
    CGAL::Protect_FPU_rounding<true> upwards;
    const interval_object io(s);
    const IV A = io.at(a), B = io.at(b), C = io.at(c);
    const IV n = CGAL::cross_product(B - A, C - A);
    if (io.range_strictly(n, A, 1) || io.range_strictly(n, A, -1)) return true;
    const IV m = CGAL::cross_product(io.D, n);
    const int side = sure_sign(A * m);
    if (side != 0 && sure_sign(B * m) == side && sure_sign(C * m) == side) return true;
    return io.line_misses(A, B, C) || io.past_range({A, B, C});
}
// The sides of a, b, c (in the plane of a proper triangle that holds the line) of the line: 1 or
// -1 where the side is sure, 0 where it is not.
std::array<int, 3> sides_in_plane(const object& s, const P3& a, const P3& b, const P3& c) {
    CGAL::Protect_FPU_rounding<true> upwards;
    const interval_object io(s);
    const IV A = io.at(a), B = io.at(b), C = io.at(c);
    const IV m = CGAL::cross_product(io.D, CGAL::cross_product(B - A, C - A));
    return {sure_sign(A * m), sure_sign(B * m), sure_sign(C * m)};
}
// A certified miss of the solid tetrahedron (not flat) by the object (not a point): the line misses
// every face (a line meets the solid only through its boundary), the object's range lies strictly
// outside one face's plane, or all four vertices lie strictly behind its start or beyond its end.
bool surely_misses_solid(const object& s, const std::array<P3, 4>& v) {
    CGAL::Protect_FPU_rounding<true> upwards;
    const interval_object io(s);
    const std::array<IV, 4> P{io.at(v[0]), io.at(v[1]), io.at(v[2]), io.at(v[3])};
    bool misses_every_face = true;
    for (std::size_t f = 0; f < 4; ++f) {
        const IV& A = P[(f + 1) % 4];
        const IV& B = P[(f + 2) % 4];
        const IV& C = P[(f + 3) % 4];
        misses_every_face = misses_every_face && io.line_misses(A, B, C);
        const IV n = CGAL::cross_product(B - A, C - A);
        const int inside = sure_sign(n * (P[f] - A)); // the fourth vertex's side
        if (inside != 0 && io.range_strictly(n, A, -inside)) return true;
    }
    return misses_every_face || io.past_range({P[0], P[1], P[2], P[3]});
}
// The object against the closed triangle a b c (degenerate ones included).
std::optional<span> triangle_span(const object& s, const P3& a, const P3& b, const P3& c) {
    if (is_point(s)) {
        const bool in = CGAL::collinear(a, b, c) ? (K::Segment_3(a, b).has_on(s.o) || K::Segment_3(b, c).has_on(s.o) ||
                                                    K::Segment_3(c, a).has_on(s.o) || s.o == a)
                                                 : K::Triangle_3(a, b, c).has_on(s.o);
        return in ? domain(s) : std::nullopt;
    }
    // A line in the triangle's plane meets the closed triangle in the hull of what it meets of
    // the three edges (below: CGAL 5.5's coplanar Line_3/Triangle_3 intersection and do_intersect
    // miss touching lines, found on meshes' near-degenerate lines). Otherwise the exact, filtered
    // predicate first: most of a mesh's triangles miss the line, and constructing the intersection
    // is what costs.
    if (surely_misses(s, a, b, c)) return std::nullopt;
    const bool in_plane = CGAL::orientation(a, b, c, s.o) == CGAL::COPLANAR && CGAL::orientation(a, b, c, s.q) == CGAL::COPLANAR;
    if (!CGAL::collinear(a, b, c)) {
        const K::Line_3& line = s.line;
        if (in_plane) { // the line's span, then clipped to the ray's or the segment's range
            const auto side = sides_in_plane(s, a, b, c);
            auto along = [&](const P3& p, int sp, const P3& q, int sq) -> std::optional<span> {
                if (sp != 0 && sp == sq) return std::nullopt; // both ends surely on one side of the line
                return span_of_result(s, CGAL::intersection(line, K::Segment_3(p, q)));
            };
            return clipped_to_range(
                s, hull(hull(along(a, side[0], b, side[1]), along(b, side[1], c, side[2])), along(c, side[2], a, side[0])));
        }
        // across the plane: the line's one point in it, inside the closed triangle or not (CGAL
        // 5.5's Line_3/Triangle_3 intersection misses some lines through an edge or a vertex)
        const K::Triangle_3 t(a, b, c);
        if (!CGAL::do_intersect(line, t)) return std::nullopt;
        const auto res = CGAL::intersection(line, K::Plane_3(a, b, c));
        const P3* p = res ? boost::get<P3>(&*res) : nullptr;
        if (p == nullptr || !t.has_on(*p)) return std::nullopt;
        const FT u = parameter(s, *p);
        return clipped_to_range(s, span{u, u});
    }
    auto edge = [&](const P3& p, const P3& q) -> std::optional<span> {
        if (p == q) {
            if (!CGAL::collinear(s.o, s.q, p)) return std::nullopt;
            const FT t = parameter(s, p);
            if ((s.bounded_below() && t < 0) || (s.bounded_above() && t > 1)) return std::nullopt;
            return span{t, t};
        }
        return meet(s, K::Segment_3(p, q));
    };
    return hull(hull(edge(a, b), edge(b, c)), edge(c, a));
}

value end_value(const std::optional<FT>& t, bool low) {
    if (t) return rational_value(*t);
    value v;
    v.kind = low ? value::minus_infinity : value::plus_infinity;
    return v;
}

} // namespace

struct exact_hit::impl {
    bool exists = false;
    value q[11];
    bool has[11] = {};
    std::vector<std::size_t> first_triangles; // mesh: every triangle at the first contact
    bool start_inside = false;
};

exact_hit::exact_hit() : p(std::make_unique<impl>()) {}
exact_hit::~exact_hit() = default;
exact_hit::exact_hit(exact_hit&&) noexcept = default;
exact_hit& exact_hit::operator=(exact_hit&&) noexcept = default;
bool exact_hit::exists() const { return p->exists; }
bool exact_hit::has(quantity x) const { return p->has[static_cast<int>(x)]; }
bool exact_hit::rounds_to(quantity x, double v) const { return rounds_to_value(static_cast<int>(x), v); }
bool exact_hit::rounds_to_value(int i, double v) const { return oracle::rounds_to(p->q[i], v); }
bool exact_hit::within(quantity x, double lo, double hi) const { return oracle::within(p->q[static_cast<int>(x)], lo, hi); }
double exact_hit::nearest(quantity x) const { return approx(p->q[static_cast<int>(x)]); }
bool exact_hit::first_triangle_ok(std::size_t i) const {
    if (i == static_cast<std::size_t>(-1)) return p->start_inside;
    for (std::size_t j : p->first_triangles)
        if (j == i) return true;
    return false;
}

namespace {
void set(exact_hit::impl& h, quantity x, const value& v) {
    h.q[static_cast<int>(x)] = v;
    h.has[static_cast<int>(x)] = true;
}
// t_enter, t_exit and the point at t_enter (where t_enter is -infinity, at the parameter of the
// span nearest 0).
void fill_span(exact_hit::impl& h, const object& s, const std::optional<span>& r) {
    h.exists = r.has_value();
    if (!r) return;
    set(h, quantity::t_enter, end_value(r->lo, true));
    set(h, quantity::t_exit, end_value(r->hi, false));
    FT at = 0;
    if (r->lo) at = *r->lo;
    else if (r->hi && *r->hi < 0) at = *r->hi;
    const P3 x = point_at(s, at);
    set(h, quantity::x, rational_value(x.x()));
    set(h, quantity::y, rational_value(x.y()));
    set(h, quantity::z, rational_value(x.z()));
}
std::vector<std::pair<FT, FT>> plane_rows(const object& s, const V3& n, const FT& c) {
    // n . x <= c: a = c - n . o, b = -n . D
    return {{c - n * (s.o - CGAL::ORIGIN), -(n * s.d)}};
}
} // namespace

exact_hit exact_plane(const linear_object& x, const double n[3], double c) {
    exact_hit h;
    const object s = object_of(x);
    const V3 N(n[0], n[1], n[2]);
    auto g = plane_rows(s, N, FT(c));
    const auto g2 = plane_rows(s, -N, -FT(c));
    g.insert(g.end(), g2.begin(), g2.end());
    fill_span(*h.p, s, clip(s, g));
    return h;
}
exact_hit exact_halfspaces(const linear_object& x, const std::vector<std::array<double, 4>>& planes) {
    exact_hit h;
    const object s = object_of(x);
    std::vector<std::pair<FT, FT>> g;
    for (const auto& p : planes) {
        const auto r = plane_rows(s, V3(p[0], p[1], p[2]), FT(p[3]));
        g.insert(g.end(), r.begin(), r.end());
    }
    fill_span(*h.p, s, clip(s, g));
    return h;
}
exact_hit exact_box(const linear_object& x, const double mn[3], const double mx[3]) {
    std::vector<std::array<double, 4>> planes;
    for (int i = 0; i < 3; ++i) {
        std::array<double, 4> lo{0, 0, 0, -mn[i]}, hi{0, 0, 0, mx[i]};
        lo[static_cast<unsigned>(i)] = -1;
        hi[static_cast<unsigned>(i)] = 1;
        planes.push_back(lo);
        planes.push_back(hi);
    }
    return exact_halfspaces(x, planes);
}
exact_hit exact_kdop(const linear_object& x, const std::vector<std::array<double, 3>>& dirs, const double* mn, const double* mx) {
    exact_hit h;
    const object s = object_of(x);
    std::vector<std::pair<FT, FT>> g;
    for (std::size_t j = 0; j < dirs.size(); ++j) {
        const V3 d(dirs[j][0], dirs[j][1], dirs[j][2]);
        const FT a = d * (s.o - CGAL::ORIGIN), b = d * s.d;
        g.push_back({a - FT(mn[j]), b});
        g.push_back({FT(mx[j]) - a, -b});
    }
    fill_span(*h.p, s, clip(s, g));
    return h;
}
exact_hit exact_obb(const linear_object& x, const double c[3], const double axes[9], const double half[3]) {
    exact_hit h;
    const object s = object_of(x);
    // columns a_i; u'(x) = A^-1 (x - c) by Cramer's rule, |u'_i| <= h_i
    const V3 A[3] = {V3(axes[0], axes[1], axes[2]), V3(axes[3], axes[4], axes[5]), V3(axes[6], axes[7], axes[8])};
    const FT det = CGAL::determinant(A[0], A[1], A[2]);
    if (sgn(det) == 0) {
        h.declined = "oriented box with dependent axes";
        return h;
    }
    auto coord = [&](int i, const V3& v) { // (A^-1 v)_i: v in place of column i
        V3 m[3] = {A[0], A[1], A[2]};
        m[i] = v;
        return CGAL::determinant(m[0], m[1], m[2]) / det;
    };
    const V3 w = s.o - P3(c[0], c[1], c[2]);
    std::vector<std::pair<FT, FT>> g;
    for (int i = 0; i < 3; ++i) {
        const FT u0 = coord(i, w), u1 = coord(i, s.d);
        g.push_back({FT(half[i]) - u0, -u1});
        g.push_back({FT(half[i]) + u0, u1});
    }
    fill_span(*h.p, s, clip(s, g));
    return h;
}
exact_hit exact_tetrahedron(const linear_object& x, const double v[12]) {
    exact_hit h;
    const object s = object_of(x);
    const P3 a(v[0], v[1], v[2]), b(v[3], v[4], v[5]), c(v[6], v[7], v[8]), d(v[9], v[10], v[11]);
    std::optional<span> r;
    if (CGAL::coplanar(a, b, c, d)) // flat: the union of its faces
        r = hull(hull(triangle_span(s, a, b, c), triangle_span(s, a, b, d)), hull(triangle_span(s, a, c, d), triangle_span(s, b, c, d)));
    else if (is_point(s)) r = K::Tetrahedron_3(a, b, c, d).has_on_unbounded_side(s.o) ? std::nullopt : domain(s);
    else if (surely_misses_solid(s, {a, b, c, d})) r = std::nullopt;
    else r = meet(s, K::Tetrahedron_3(a, b, c, d));
    fill_span(*h.p, s, r);
    return h;
}
exact_hit exact_ball(const linear_object& x, const double c[3], double radius) {
    exact_hit h;
    const object s = object_of(x);
    const V3 m = s.o - P3(c[0], c[1], c[2]);
    const FT a = s.d * s.d, b = m * s.d, cc = m * m - FT(radius) * FT(radius);
    if (sgn(a) == 0) { // a point
        h.p->exists = sgn(cc) <= 0;
        if (!h.p->exists) return h;
        const auto r = domain(s);
        fill_span(*h.p, s, r);
        return h;
    }
    if (sgn(b * b - a * cc) < 0) return h;
    value t1, t2;
    t1.kind = t2.kind = value::root;
    t1.a = t2.a = a, t1.b = t2.b = b, t1.c = t2.c = cc, t1.o = t2.o = 0, t1.d = t2.d = 1;
    t2.larger = true;
    // the roots against the object's range
    value enter = t1, exit = t2;
    if (s.bounded_below()) {
        if (compare(t2, Q(0)) < 0) return h;
        if (compare(t1, Q(0)) <= 0) enter = rational_value(0);
    }
    if (s.bounded_above()) {
        if (compare(t1, Q(1)) > 0) return h;
        if (compare(t2, Q(1)) >= 0) exit = rational_value(1);
    }
    h.p->exists = true;
    set(*h.p, quantity::t_enter, enter);
    set(*h.p, quantity::t_exit, exit);
    auto coordinate = [&](const FT& o, const FT& d) {
        if (enter.kind == value::rational) return rational_value(o + enter.q * d);
        value v = t1;
        v.o = o, v.d = d;
        return v;
    };
    const V3 O = s.o - CGAL::ORIGIN;
    set(*h.p, quantity::x, coordinate(O.x(), s.d.x()));
    set(*h.p, quantity::y, coordinate(O.y(), s.d.y()));
    set(*h.p, quantity::z, coordinate(O.z(), s.d.z()));
    return h;
}

namespace {
// The barycentrics of X in the proper triangle a b c (areas in a projection where the normal is
// not zero), and the normal (b - a) x (c - a).
void triangle_extras(exact_hit::impl& h, const P3& X, const P3& a, const P3& b, const P3& c) {
    const V3 n = CGAL::cross_product(b - a, c - a);
    set(h, quantity::nx, rational_value(n.x()));
    set(h, quantity::ny, rational_value(n.y()));
    set(h, quantity::nz, rational_value(n.z()));
    auto area = [&](const P3& p, const P3& q, const P3& r) { return CGAL::cross_product(q - p, r - p); };
    const FT zero = 0;
    if (n == CGAL::NULL_VECTOR) {
        set(h, quantity::u, rational_value(zero));
        set(h, quantity::v, rational_value(zero));
        set(h, quantity::w, rational_value(zero));
        return;
    }
    const int axis = sgn(n.x()) != 0 ? 0 : (sgn(n.y()) != 0 ? 1 : 2);
    auto comp = [&](const V3& v) { return axis == 0 ? v.x() : (axis == 1 ? v.y() : v.z()); };
    const FT whole = comp(n);
    set(h, quantity::u, rational_value(comp(area(X, b, c)) / whole));
    set(h, quantity::v, rational_value(comp(area(a, X, c)) / whole));
    set(h, quantity::w, rational_value(comp(area(a, b, X)) / whole));
}
void first_contact(exact_hit::impl& h, const object& s, const std::optional<span>& r) {
    h.exists = r.has_value();
    if (!r) return;
    set(h, quantity::t_enter, end_value(r->lo, true));
    const P3 x = point_at(s, r->lo ? *r->lo : FT(0));
    set(h, quantity::x, rational_value(x.x()));
    set(h, quantity::y, rational_value(x.y()));
    set(h, quantity::z, rational_value(x.z()));
}
} // namespace

exact_hit exact_triangle(const linear_object& x, const double a[3], const double b[3], const double c[3]) {
    exact_hit h;
    const object s = object_of(x);
    const P3 A(a[0], a[1], a[2]), B(b[0], b[1], b[2]), C(c[0], c[1], c[2]);
    const auto r = triangle_span(s, A, B, C);
    first_contact(*h.p, s, r);
    if (r) triangle_extras(*h.p, point_at(s, r->lo ? *r->lo : FT(0)), A, B, C);
    return h;
}
exact_hit exact_polygon(const linear_object& x, const polygon3_data& g) {
    exact_hit h;
    const object s = object_of(x);
    std::optional<span> r;
    for (const auto& t : polygon3_triangles(g))
        r = hull(r, triangle_span(s, P3(t[0], t[1], t[2]), P3(t[3], t[4], t[5]), P3(t[6], t[7], t[8])));
    first_contact(*h.p, s, r);
    return h;
}
exact_hit exact_mesh(const linear_object& x, const mesh_data& m) {
    exact_hit h;
    const object s = object_of(x);
    if (is_point(s) && !s.bounded_below()) { // a line with a zero direction: its origin, every t
        bool on = false;
        for (std::size_t i = 0; i < m.t.size(); ++i) {
            const auto& a = m.v[m.t[i][0]];
            const auto& b = m.v[m.t[i][1]];
            const auto& c = m.v[m.t[i][2]];
            if (triangle_span(s, P3(a[0], a[1], a[2]), P3(b[0], b[1], b[2]), P3(c[0], c[1], c[2])))
                on = true, h.p->first_triangles.push_back(i);
        }
        if (on) {
            first_contact(*h.p, s, domain(s));
        } else if (mesh_inside(m, {x.o[0], x.o[1], x.o[2]})) { // inside: hit at t = 0
            h.p->start_inside = true;
            first_contact(*h.p, s, span{FT(0), FT(0)});
        }
        return h;
    }
    // The triangles in the order of a lower bound on their parameters (their vertices' (v - o) . D
    // / D . D, in interval arithmetic); once that bound passes the first contact found, no later
    // triangle can hold a contact as early, and the exact tests stop.
    std::vector<std::pair<double, std::size_t>> order;
    {
        CGAL::Protect_FPU_rounding<true> upwards;
        const interval_object io(s);
        const I dd = io.D * io.D;
        std::vector<double> lower(m.v.size()); // per vertex, once (a vertex has several triangles)
        for (std::size_t k = 0; k < m.v.size(); ++k) lower[k] = (io.at(m.v[k]) * io.D / dd).inf();
        for (std::size_t i = 0; i < m.t.size(); ++i) order.push_back({std::min({lower[m.t[i][0]], lower[m.t[i][1]], lower[m.t[i][2]]}), i});
    }
    std::sort(order.begin(), order.end());
    std::optional<FT> first;
    std::vector<std::pair<FT, std::size_t>> contacts;
    for (const auto& [lo, i] : order) {
        if (first && lo > CGAL::approx(*first).sup()) break;
        const auto& a = m.v[m.t[i][0]];
        const auto& b = m.v[m.t[i][1]];
        const auto& c = m.v[m.t[i][2]];
        const auto r = triangle_span(s, P3(a[0], a[1], a[2]), P3(b[0], b[1], b[2]), P3(c[0], c[1], c[2]));
        if (!r || !r->lo) continue;
        contacts.push_back({*r->lo, i});
        if (!first || *r->lo < *first) first = *r->lo;
    }
    const bool at_zero = first && sgn(*first) == 0;
    if (s.bounded_below() && !at_zero && mesh_inside(m, {x.o[0], x.o[1], x.o[2]})) {
        h.p->start_inside = true;
        first = FT(0);
    } else {
        for (const auto& [t, i] : contacts)
            if (t == *first) h.p->first_triangles.push_back(i);
    }
    first_contact(*h.p, s, first ? std::optional<span>{span{*first, *first}} : std::nullopt);
    return h;
}

} // namespace oracle
