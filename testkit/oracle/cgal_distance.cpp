// The signed and squared distance from a point to a solid, exactly (cgal_oracle.hpp,
// check_distance): each value is s sqrt(Q) + t with s = +-1 and Q >= 0, t exact rationals, from
//   a capsule (a ball when a = b): Q0 = CGAL::squared_distance(Point_3, Segment_3 | Point_3) over
//     Epeck; signed: sqrt(Q0) - |r|; squared: (sqrt(Q0) - |r|)^2 = Q0 + r^2 - sqrt(4 r^2 Q0), or 0;
//   a convex set of the LP oracle (a box, an OBB, a tetrahedron, a k-DOP, a frustum, a convex
//     polyhedron): Q0 = the QP's exact minimum of |x - p|^2; outside sqrt(Q0); inside minus the
//     distance to the boundary, the smallest (c - n . p)^2 / |n|^2 over the set's rows (its faces,
//     in rationals: a tetrahedron's from its vertices);
//   a mesh: Q0 = the least CGAL::squared_distance(Point_3, Triangle_3) over its triangles (a
//     collinear one as its segments), the side by mesh_inside (cgal_mesh.cpp).
// Between two points, segments, rays or lines (check_flat_distance): Q0 = CGAL::squared_distance
// over Epeck of the two (a degenerate one as its point; a ray against a segment as the segment of
// the ray that holds the nearest point: see there); a point against a triangle: CGAL's
// squared_distance over Epeck (a collinear triangle as its edges); a triangle against a segment,
// ray, line or triangle: the exact QP's minimum of |x - y|^2 (cgal_lp.cpp); the distance
// sqrt(Q0), the squared Q0.
// Correct rounding is decided at the midpoints next to x, exactly (ties to even).
#include "cgal_oracle.hpp"
#include "cgal_lp_point.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/squared_distance_3.h>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <variant>

#include <gmpxx.h>

namespace oracle {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Q = std::decay_t<decltype(CGAL::exact(std::declval<K::FT>()))>;

static_assert(std::is_same_v<Q, mpq_class>, "CGAL's exact numbers are gmpxx's rationals here");
mpq_class to_mpq(const K::FT& x) { return CGAL::exact(x); }
K::Point_3 point(const double* p) { return {p[0], p[1], p[2]}; }

// s sqrt(q) + t; infinite: +-infinity (s its sign).
struct exact_value {
    int s = 1;
    mpq_class q = 0, t = 0;
    bool infinite = false;
};

// sign(v - y) for a rational y.
int compare(const exact_value& v, const mpq_class& y) {
    if (v.infinite) return v.s;
    const mpq_class u = y - v.t; // sign(s sqrt(q) - u)
    if (v.s > 0) {
        if (sgn(u) < 0) return 1;
        return sgn(v.q - u * u);
    }
    if (sgn(u) > 0) return -1;
    if (sgn(u) == 0) return sgn(v.q) > 0 ? -1 : 0;
    return sgn(u * u - v.q);
}

bool rounds_to(const exact_value& v, double x) {
    if (std::isnan(x)) return false;
    const mpq_class top = mpq_class(0x1.fffffffffffffp1023) + mpq_class(0x1p970);
    if (std::isinf(x)) return x > 0 ? compare(v, top) >= 0 : compare(v, -top) <= 0;
    const double up = std::nextafter(x, INFINITY), down = std::nextafter(x, -INFINITY);
    const mpq_class mp = std::isinf(up) ? top : mpq_class((mpq_class(x) + mpq_class(up)) / 2);
    const mpq_class mm = std::isinf(down) ? mpq_class(-top) : mpq_class((mpq_class(x) + mpq_class(down)) / 2);
    std::uint64_t bits;
    std::memcpy(&bits, &x, 8);
    const bool even = (bits & 1u) == 0;
    const int above = compare(v, mp), below = compare(v, mm);
    return (even ? above <= 0 : above < 0) && (even ? below >= 0 : below > 0);
}

// v to about 200 bits, then to double.
double approximate(const exact_value& v) {
    if (v.infinite) return v.s * INFINITY;
    mpf_class r(v.q, 256);
    r = sqrt(r);
    mpf_class t(v.t, 256);
    const mpf_class out = v.s > 0 ? mpf_class(t + r, 256) : mpf_class(t - r, 256);
    return out.get_d();
}

// The squared distance from p to segment ab (a point when a = b), over Epeck.
mpq_class segment_sqdist(const double* p, const double* a, const double* b) {
    const K::Point_3 P = point(p), A = point(a), B = point(b);
    if (A == B) return to_mpq(CGAL::squared_distance(P, A));
    return to_mpq(CGAL::squared_distance(P, K::Segment_3(A, B)));
}
mpq_class triangle_sqdist(const K::Point_3& p, const K::Point_3& a, const K::Point_3& b, const K::Point_3& c) {
    if (!CGAL::collinear(a, b, c)) return to_mpq(CGAL::squared_distance(p, K::Triangle_3(a, b, c)));
    mpq_class best = -1;
    for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        const mpq_class d = u == v ? to_mpq(CGAL::squared_distance(p, u)) : to_mpq(CGAL::squared_distance(p, K::Segment_3(u, v)));
        if (best < 0 || d < best) best = d;
    }
    return best;
}

using qpoint = std::array<mpq_class, 3>;
mpq_class dot(const qpoint& a, const qpoint& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
qpoint cross(const qpoint& a, const qpoint& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
qpoint minus(const qpoint& a, const qpoint& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
qpoint rational(const double* p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }

// The smallest (c - n . p)^2 / |n|^2 over the rows (zero normals skipped); -1 when there is none.
mpq_class depth_squared(const std::vector<exact_row>& rows, const qpoint& p) {
    mpq_class best = -1;
    for (const auto& r : rows) {
        const mpq_class nn = dot(r.n, r.n);
        if (sgn(nn) == 0) continue;
        const mpq_class room = r.c - dot(r.n, p);
        const mpq_class d = room * room / nn;
        if (best < 0 || d < best) best = d;
    }
    return best;
}

// The signed (or squared) distance from outside value q0 and the inside depth squared (-1: none).
exact_value from_parts(const mpq_class& q0, const mpq_class& depth2, bool squared) {
    exact_value v;
    if (sgn(q0) > 0) {
        if (squared) v.t = q0, v.q = 0;
        else v.q = q0;
        return v;
    }
    if (squared) return v; // 0
    if (depth2 < 0) {
        v.s = -1, v.infinite = true;
        return v;
    }
    v.s = -1, v.q = depth2;
    return v;
}

std::optional<exact_value> truth(const distance_solid& s, const std::array<double, 3>& p, bool squared) {
    const qpoint P = rational(p.data());
    switch (s.kind) {
    case distance_solid::capsule: {
        const mpq_class q0 = segment_sqdist(p.data(), s.v.data(), s.v.data() + 3);
        const mpq_class r = abs(mpq_class(s.v[6]));
        exact_value v;
        if (!squared) {
            v.q = q0, v.t = -r;
            return v;
        }
        if (q0 <= r * r) return v; // 0
        v.s = -1, v.q = 4 * r * r * q0, v.t = q0 + r * r;
        return v;
    }
    case distance_solid::rows: {
        const auto q0 = qp_squared_distance(s.set, p);
        if (!q0) return std::nullopt;
        if (!*q0) {
            exact_value v;
            v.infinite = true;
            return v;
        }
        mpq_class depth2 = -1;
        if (sgn(**q0) == 0 && !squared) {
            const auto rows = exact_rows(s.set);
            if (rows) depth2 = depth_squared(*rows, P);
            else if (s.set.points.size() == 1 && s.set.generators.size() == 3) depth2 = 0; // a flat box: no inside
            else return std::nullopt;
        }
        return from_parts(**q0, depth2, squared);
    }
    case distance_solid::tetrahedron: {
        convex_set set;
        for (int i = 0; i < 4; ++i) set.points.push_back({s.v[3 * i], s.v[3 * i + 1], s.v[3 * i + 2]});
        const auto q0 = qp_squared_distance(set, p);
        if (!q0 || !*q0) return std::nullopt;
        mpq_class depth2 = -1;
        if (sgn(**q0) == 0 && !squared) {
            // the four faces, each oriented away from the fourth vertex
            std::vector<exact_row> rows;
            const qpoint V[4] = {rational(&s.v[0]), rational(&s.v[3]), rational(&s.v[6]), rational(&s.v[9])};
            for (int f = 0; f < 4; ++f) {
                const qpoint& a = V[(f + 1) % 4];
                qpoint n = cross(minus(V[(f + 2) % 4], a), minus(V[(f + 3) % 4], a));
                mpq_class c = dot(n, a);
                if (dot(n, V[f]) > c) n = {-n[0], -n[1], -n[2]}, c = -c;
                rows.push_back({n, c});
            }
            depth2 = depth_squared(rows, P);
            // a flat tetrahedron has no inside: its points are on its boundary
            const qpoint n0 = cross(minus(V[1], V[0]), minus(V[2], V[0]));
            if (sgn(dot(n0, minus(V[3], V[0]))) == 0) depth2 = 0;
        }
        return from_parts(**q0, depth2, squared);
    }
    case distance_solid::mesh: {
        mpq_class best = -1;
        const K::Point_3 X = point(p.data());
        for (const auto& t : s.mesh_ptr->t) {
            const mpq_class d =
                triangle_sqdist(X, point(s.mesh_ptr->v[t[0]].data()), point(s.mesh_ptr->v[t[1]].data()), point(s.mesh_ptr->v[t[2]].data()));
            if (best < 0 || d < best) best = d;
        }
        exact_value v;
        if (sgn(best) == 0) return v;
        const bool inside = mesh_inside(*s.mesh_ptr, p);
        if (squared) {
            if (!inside) v.t = best;
            return v;
        }
        v.s = inside ? -1 : 1, v.q = best;
        return v;
    }
    }
    return std::nullopt;
}

// The checks of x, [lo, hi] and approx against v.
distance_check check_value(const std::optional<exact_value>& v, double x, double lo, double hi, double approx) {
    distance_check out;
    if (!v) return out;
    out.known = true;
    out.rounded = rounds_to(*v, x);
    // lo <= v and v <= hi, for ends that may be infinite (or NaN: never)
    const auto at_least = [&](double end) { // v >= end
        if (std::isnan(end)) return false;
        if (std::isinf(end)) return end < 0 || (v->infinite && v->s > 0);
        return compare(*v, mpq_class(end)) >= 0;
    };
    const auto at_most = [&](double end) { // v <= end
        if (std::isnan(end)) return false;
        if (std::isinf(end)) return end > 0 || (v->infinite && v->s < 0);
        return compare(*v, mpq_class(end)) <= 0;
    };
    out.enclosed = at_least(lo) && at_most(hi);
    out.value = approximate(*v);
    out.sign = compare(*v, 0);
    out.error = v->infinite ? (approx == out.value ? 0.0 : INFINITY) : std::fabs(approx - out.value);
    if (!v->infinite && std::isfinite(approx)) {
        const mpf_class d = mpf_class(mpq_class(approx), 256) - mpf_class(v->t, 256) -
                            (v->s > 0 ? mpf_class(sqrt(mpf_class(v->q, 256)), 256) : mpf_class(-sqrt(mpf_class(v->q, 256)), 256));
        out.error = std::fabs(d.get_d());
    }
    return out;
}

// A point, segment, ray or line over kernel Kernel: the degenerate ones as their point.
template <class Kernel>
using linear_shape = std::variant<typename Kernel::Point_3, typename Kernel::Segment_3, typename Kernel::Ray_3, typename Kernel::Line_3>;
template <class Kernel>
std::optional<linear_shape<Kernel>> linear_of(const flat& f) {
    using P = typename Kernel::Point_3;
    using V = typename Kernel::Vector_3;
    const P a(f.v[0], f.v[1], f.v[2]);
    const bool zero = f.v[3] == 0 && f.v[4] == 0 && f.v[5] == 0;
    switch (f.kind) {
    case flat::point: return linear_shape<Kernel>(a);
    case flat::segment: {
        const P b(f.v[3], f.v[4], f.v[5]);
        if (a == b) return linear_shape<Kernel>(a);
        return linear_shape<Kernel>(typename Kernel::Segment_3(a, b));
    }
    case flat::ray:
        if (zero) return linear_shape<Kernel>(a);
        return linear_shape<Kernel>(typename Kernel::Ray_3(a, V(f.v[3], f.v[4], f.v[5])));
    case flat::line:
        if (zero) return linear_shape<Kernel>(a);
        return linear_shape<Kernel>(typename Kernel::Line_3(a, V(f.v[3], f.v[4], f.v[5])));
    default: return std::nullopt;
    }
}

} // namespace

distance_check check_distance(const distance_solid& s, const std::array<double, 3>& p, bool squared, double x, double lo, double hi,
                              double approx) {
    return check_value(truth(s, p, squared), x, lo, hi, approx);
}

// A point against a triangle: CGAL's squared_distance (a collinear triangle as its edges); a
// triangle against a segment, a ray, a line or a triangle: the exact QP on the two sets.
static std::optional<mpq_class> triangle_truth(const flat& a, const flat& b) {
    if (b.kind != flat::triangle) return triangle_truth(b, a);
    if (a.kind == flat::point) return triangle_sqdist(point(a.v), point(b.v), point(b.v + 3), point(b.v + 6));
    return qp_sets_squared_distance(lp_set(a), lp_set(b));
}

distance_check check_flat_distance(const flat& a, const flat& b, bool squared, double x, double lo, double hi, double approx) {
    const auto of = [&](const mpq_class& q0) {
        exact_value v;
        if (squared) v.t = q0;
        else v.q = q0;
        return check_value(v, x, lo, hi, approx);
    };
    if (a.kind == flat::triangle || b.kind == flat::triangle) {
        const auto q0 = triangle_truth(a, b);
        if (!q0) return {};
        return of(*q0);
    }
    auto u = linear_of<K>(a), w = linear_of<K>(b);
    if (!u || !w) return {};
    // CGAL 5.5's squared_distance(Ray_3, Segment_3) is wrong for a segment on the ray's line ahead
    // of its origin and pointing back at it (the ray from 0 along z and the segment from (0, 0, 3)
    // to (0, 0, 2): 4, not 0); so a ray against a segment is the ray's part that can hold the
    // nearest point, the segment from the origin O to O + (t + 1) D, t the larger of 0 and the
    // segment's end points' parameters along D (exact).
    const auto cut = [](std::optional<linear_shape<K>>& x, const std::optional<linear_shape<K>>& other) {
        const auto* r = std::get_if<K::Ray_3>(&*x);
        const auto* s = std::get_if<K::Segment_3>(&*other);
        if (r == nullptr || s == nullptr) return;
        const K::Vector_3 d = r->to_vector();
        K::FT t = 0;
        for (const K::Point_3& p : {s->source(), s->target()}) t = CGAL::max(t, (p - r->source()) * d / (d * d));
        x = linear_shape<K>(K::Segment_3(r->source(), r->source() + (t + 1) * d));
    };
    cut(u, w), cut(w, u);
    return of(std::visit([](const auto& g, const auto& h) { return to_mpq(CGAL::squared_distance(g, h)); }, *u, *w));
}

double flat_distance_epick(const flat& a, const flat& b) {
    using E = CGAL::Exact_predicates_inexact_constructions_kernel;
    const auto u = linear_of<E>(a), w = linear_of<E>(b);
    if (!u || !w) return std::nan("");
    return std::sqrt(std::visit([](const auto& g, const auto& h) { return CGAL::to_double(CGAL::squared_distance(g, h)); }, *u, *w));
}

} // namespace oracle
