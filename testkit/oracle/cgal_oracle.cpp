#include "cgal_oracle.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Cartesian.h>
#include <CGAL/Min_sphere_annulus_d_traits_3.h>
#include <CGAL/Min_sphere_d.h>
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Min_sphere_of_spheres_d_traits_3.h>
#include <vector>
#include <algorithm>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>
#include <cmath>
#include <type_traits>
#include <utility>
#include <cstdint>
#include <cstring>

namespace oracle {
namespace {
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using KI = CGAL::Exact_predicates_inexact_constructions_kernel;
using FT = K::FT;
using Q = std::decay_t<decltype(CGAL::exact(std::declval<K::FT>()))>; // GMP rationals
Q qabs(const Q& x) { return x < 0 ? Q(-x) : x; }
template <class Kern = K>
typename Kern::Point_3 P(const double p[3]) {
    return {p[0], p[1], p[2]};
}
template <class Kern = K>
typename Kern::Vector_3 V(const double p[3]) {
    return {p[0], p[1], p[2]};
}
K::Point_2 P2(const double p[2]) { return {p[0], p[1]}; }
int sgn(CGAL::Sign s) { return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0); }
Q exact(const FT& x) { return CGAL::exact(x); }

// x is the nearest double to v (ties to even): |v - x| <= |v - neighbours|, with tie rule.
bool nearest(const Q& v, double x) {
    if (std::isnan(x)) return false;
    if (std::isinf(x)) { // rounds to infinity iff |v| >= DBL_MAX + ulp(DBL_MAX)/2 = 2^1024 - 2^970
        const Q limit = Q(0x1.fffffffffffffp1023) + Q(0x1p970);
        return x > 0 ? v >= limit : v <= -limit;
    }
    const Q qx(x);
    const double up = std::nextafter(x, INFINITY), dn = std::nextafter(x, -INFINITY);
    const Q dx = qabs(v - qx);
    for (double nb : {up, dn}) {
        if (!std::isfinite(nb)) continue;
        const Q dn_ = qabs(v - Q(nb));
        if (dn_ < dx) return false;
        if (dn_ == dx) { // tie: x must be even
            std::uint64_t bits;
            std::memcpy(&bits, &x, 8);
            if (bits & 1u) return false;
        }
    }
    return true;
}
} // namespace

int orient2d(const double a[2], const double b[2], const double c[2]) { return sgn(CGAL::orientation(P2(a), P2(b), P2(c))); }
// Shewchuk: positive when d is below the plane of ccw a, b, c; CGAL: positive when d is on the
// positive side, i.e. above. Hence the minus sign.
int orient3d(const double a[3], const double b[3], const double c[3], const double d[3]) {
    return -sgn(CGAL::orientation(P(a), P(b), P(c), P(d)));
}
int incircle(const double a[2], const double b[2], const double c[2], const double d[2]) {
    return sgn(CGAL::side_of_oriented_circle(P2(a), P2(b), P2(c), P2(d)));
}
// CGAL: side_of_oriented_sphere(p,q,r,s,t) positive when t is inside the sphere and p,q,r,s are
// positively oriented (CGAL orientation). Shewchuk's insphere is positive when e is inside and
// orient3d(a,b,c,d) > 0 (Shewchuk), which is CGAL-negative: the two differ by that sign.
int insphere(const double a[3], const double b[3], const double c[3], const double d[3], const double e[3]) {
    return -sgn(CGAL::side_of_oriented_sphere(P(a), P(b), P(c), P(d), P(e)));
}

bool triangle_is_degenerate(const double a[3], const double b[3], const double c[3]) { return CGAL::collinear(P(a), P(b), P(c)); }
bool ray_triangle(const double o[3], const double d[3], const double a[3], const double b[3], const double c[3]) {
    return CGAL::do_intersect(K::Ray_3(P(o), V(d)), K::Triangle_3(P(a), P(b), P(c)));
}
bool segment_triangle(const double p[3], const double q[3], const double a[3], const double b[3], const double c[3]) {
    return CGAL::do_intersect(K::Segment_3(P(p), P(q)), K::Triangle_3(P(a), P(b), P(c)));
}
bool triangle_triangle(const double a[3], const double b[3], const double c[3], const double d[3], const double e[3], const double f[3]) {
    return CGAL::do_intersect(K::Triangle_3(P(a), P(b), P(c)), K::Triangle_3(P(d), P(e), P(f)));
}
template <class Ker>
typename Ker::Plane_3 plane_of(const double n[3], double offset) {
    return typename Ker::Plane_3(n[0], n[1], n[2], -typename Ker::FT(offset));
}
template <class Ker>
bool box_plane_k(const double mn[3], const double mx[3], const double n[3], double offset) {
    return CGAL::do_intersect(plane_of<Ker>(n, offset), typename Ker::Iso_cuboid_3(P<Ker>(mn), P<Ker>(mx)));
}
template <class Ker>
bool plane_segment_k(const double n[3], double offset, const double p[3], const double q[3]) {
    const auto pl = plane_of<Ker>(n, offset);
    if (P<Ker>(p) == P<Ker>(q)) return pl.has_on(P<Ker>(p));
    return CGAL::do_intersect(pl, typename Ker::Segment_3(P<Ker>(p), P<Ker>(q)));
}
template <class Ker>
bool plane_triangle_k(const double n[3], double offset, const double a[3], const double b[3], const double c[3]) {
    return CGAL::do_intersect(plane_of<Ker>(n, offset), typename Ker::Triangle_3(P<Ker>(a), P<Ker>(b), P<Ker>(c)));
}
bool box_plane(const double mn[3], const double mx[3], const double n[3], double offset) { return box_plane_k<K>(mn, mx, n, offset); }
bool plane_segment(const double n[3], double offset, const double p[3], const double q[3]) { return plane_segment_k<K>(n, offset, p, q); }
bool plane_triangle(const double n[3], double offset, const double a[3], const double b[3], const double c[3]) {
    return plane_triangle_k<K>(n, offset, a, b, c);
}
bool box_plane_epick(const double mn[3], const double mx[3], const double n[3], double offset) {
    return box_plane_k<KI>(mn, mx, n, offset);
}
bool plane_segment_epick(const double n[3], double offset, const double p[3], const double q[3]) {
    return plane_segment_k<KI>(n, offset, p, q);
}
bool plane_triangle_epick(const double n[3], double offset, const double a[3], const double b[3], const double c[3]) {
    return plane_triangle_k<KI>(n, offset, a, b, c);
}
bool box_segment(const double mn[3], const double mx[3], const double p[3], const double q[3]) {
    const K::Iso_cuboid_3 box(P(mn), P(mx));
    if (P(p) == P(q)) return !box.has_on_unbounded_side(P(p));
    return CGAL::do_intersect(K::Segment_3(P(p), P(q)), box);
}
// Not CGAL's do_intersect(Line_3, Iso_cuboid_3): in CGAL 5.5 (bbox_line_do_intersect_aux) a line
// parallel to a face and lying exactly in its plane loses a slab bound (0/0), and the test says
// yes for lines that miss the box. Here: the slab intervals in exact rationals, with quotients.
bool box_line(const double mn[3], const double mx[3], const double p[3], const double d[3]) {
    using FT = K::FT;
    bool have = false;
    FT lo = 0, hi = 0;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0) {
            if (p[i] < mn[i] || p[i] > mx[i]) return false;
            continue;
        }
        FT a = (FT(mn[i]) - FT(p[i])) / FT(d[i]), b = (FT(mx[i]) - FT(p[i])) / FT(d[i]);
        if (b < a) std::swap(a, b);
        if (!have || a > lo) lo = a;
        if (!have || b < hi) hi = b;
        have = true;
    }
    return !have || lo <= hi;
}
bool box_triangle(const double mn[3], const double mx[3], const double a[3], const double b[3], const double c[3]) {
    const K::Triangle_3 t(P(a), P(b), P(c));
    int flat = -1;
    for (int i = 0; i < 3; ++i)
        if (mn[i] == mx[i]) flat = i;
    if (flat < 0) return CGAL::do_intersect(t, K::Iso_cuboid_3(P(mn), P(mx)));
    // the rectangle (or segment, or point) in the plane x_flat = mn[flat]
    const int j = (flat + 1) % 3, l = (flat + 2) % 3;
    auto corner = [&](bool hj, bool hl) {
        double p[3];
        p[flat] = mn[flat], p[j] = hj ? mx[j] : mn[j], p[l] = hl ? mx[l] : mn[l];
        return P(p);
    };
    const K::Point_3 c00 = corner(false, false), c10 = corner(true, false), c11 = corner(true, true), c01 = corner(false, true);
    if (c00 == c11) return CGAL::do_intersect(t, c00);
    if (c00 == c10 || c00 == c01) return CGAL::do_intersect(t, K::Segment_3(c00, c11));
    return CGAL::do_intersect(t, K::Triangle_3(c00, c10, c11)) || CGAL::do_intersect(t, K::Triangle_3(c00, c11, c01));
}
bool ray_box(const double o[3], const double d[3], const double mn[3], const double mx[3]) {
    return CGAL::do_intersect(K::Ray_3(P(o), V(d)), K::Iso_cuboid_3(P(mn), P(mx)));
}
bool box_box(const double amn[3], const double amx[3], const double bmn[3], const double bmx[3]) {
    return CGAL::do_intersect(K::Iso_cuboid_3(P(amn), P(amx)), K::Iso_cuboid_3(P(bmn), P(bmx)));
}
bool point_in_box(const double p[3], const double mn[3], const double mx[3]) {
    return !K::Iso_cuboid_3(P(mn), P(mx)).has_on_unbounded_side(P(p));
}
bool box_contains_box(const double amn[3], const double amx[3], const double bmn[3], const double bmx[3]) {
    const K::Iso_cuboid_3 a(P(amn), P(amx));
    return !a.has_on_unbounded_side(P(bmn)) && !a.has_on_unbounded_side(P(bmx));
}
bool point_in_ball(const double p[3], const double c[3], double r) { return CGAL::squared_distance(P(p), P(c)) <= FT(r) * FT(r); }
bool ball_ball(const double c1[3], double r1, const double c2[3], double r2) {
    const FT s = FT(std::fabs(r1)) + FT(std::fabs(r2)); // a negative radius acts as |r|
    return CGAL::squared_distance(P(c1), P(c2)) <= s * s;
}
bool ball_contains_ball(const double c1[3], double r1, const double c2[3], double r2) {
    const FT s = FT(std::fabs(r1)) - FT(std::fabs(r2)); // a negative radius acts as |r|
    return s >= 0 && CGAL::squared_distance(P(c1), P(c2)) <= s * s;
}
bool ray_ball(const double o[3], const double d[3], const double c[3], double r) {
    return CGAL::squared_distance(K::Ray_3(P(o), V(d)), P(c)) <= FT(r) * FT(r);
}

namespace {
// t of the first contact along from + t dv, for an intersection that is a point or (coplanar)
// a segment, whose nearer end point is the first contact.
template <class Result>
bool first_contact_rounded(const Result& res, const K::Point_3& from, const K::Vector_3& dv, double t) {
    if (!res) return false;
    auto param = [&](const K::Point_3& x) { return FT(((x - from) * dv) / (dv * dv)); };
    if (const K::Point_3* x = boost::get<K::Point_3>(&*res)) return nearest(exact(param(*x)), t);
    const K::Segment_3* sg = boost::get<K::Segment_3>(&*res);
    if (!sg) return false;
    const FT t0 = param(sg->source()), t1 = param(sg->target());
    return nearest(exact(t0 < t1 ? t0 : t1), t);
}
} // namespace
bool is_rounded_ray_triangle_t(const double o[3], const double d[3], const double a[3], const double b[3], const double c[3], double t) {
    return first_contact_rounded(CGAL::intersection(K::Ray_3(P(o), V(d)), K::Triangle_3(P(a), P(b), P(c))), P(o), V(d), t);
}
bool is_rounded_segment_triangle_t(const double p[3], const double q[3], const double a[3], const double b[3], const double c[3],
                                   double t) {
    return first_contact_rounded(CGAL::intersection(K::Segment_3(P(p), P(q)), K::Triangle_3(P(a), P(b), P(c))), P(p), P(q) - P(p), t);
}
namespace {
FT point_box_sqdist(const double p[3], const double mn[3], const double mx[3], bool farthest) {
    FT s = 0;
    for (int i = 0; i < 3; ++i) {
        const FT pi(p[i]), lo(mn[i]), hi(mx[i]);
        FT g = 0;
        if (farthest) g = CGAL::max(CGAL::abs(pi - lo), CGAL::abs(hi - pi));
        else if (pi < lo) g = lo - pi;
        else if (pi > hi) g = pi - hi;
        s += g * g;
    }
    return s;
}
} // namespace
bool interval_contains_point_box_sqdist(const double p[3], const double mn[3], const double mx[3], bool farthest, double lo, double hi) {
    const FT s = point_box_sqdist(p, mn, mx, farthest);
    return FT(lo) <= s && s <= FT(hi);
}
bool is_rounded_point_box_sqdist(const double p[3], const double mn[3], const double mx[3], bool farthest, double x) {
    FT s = 0;
    for (int i = 0; i < 3; ++i) {
        const FT pi(p[i]), lo(mn[i]), hi(mx[i]);
        FT g = 0;
        if (farthest) g = CGAL::max(CGAL::abs(pi - lo), CGAL::abs(hi - pi));
        else if (pi < lo) g = lo - pi;
        else if (pi > hi) g = pi - hi;
        s += g * g;
    }
    return nearest(exact(s), x);
}
bool is_rounded_ray_box_t(const double o[3], const double d[3], const double mn[3], const double mx[3], double t_enter, double t_exit) {
    // Exact slab parameters in rationals, independently of the library.
    Q t0 = 0;
    bool bounded = false;
    Q t1 = 0;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) continue;
        Q a = (Q(mn[i]) - Q(o[i])) / Q(d[i]);
        Q b = (Q(mx[i]) - Q(o[i])) / Q(d[i]);
        if (b < a) std::swap(a, b);
        if (a > t0) t0 = a;
        if (!bounded || b < t1) t1 = b;
        bounded = true;
    }
    if (!nearest(t0, t_enter)) return false;
    if (!bounded) return t_exit == INFINITY;
    return nearest(t1, t_exit);
}
bool is_rounded_ray_ball_t(const double o[3], const double d[3], const double c[3], double r, double x) {
    // f(t) = a t^2 + 2 b t + c', first root t1; x is nearest iff t1 lies between the
    // midpoints m- = (prev + x)/2 and m+ = (x + next)/2 (ties: x even).
    Q a = 0, b = 0, cc = -Q(r) * Q(r);
    for (int i = 0; i < 3; ++i) {
        const Q m = Q(o[i]) - Q(c[i]);
        a += Q(d[i]) * Q(d[i]);
        b += m * Q(d[i]);
        cc += m * m;
    }
    if (cc <= 0) return x == 0.0;
    auto f = [&](const Q& t) { return Q(a * t * t + 2 * b * t + cc); }; // a value, not a gmpxx expression
    auto le = [&](const Q& y) { return a * y + b >= 0 || f(y) <= 0; };  // t1 <= y
    auto lt = [&](const Q& y) { return a * y + b > 0 || f(y) < 0; };    // t1 < y
    // Around the top of the range the midpoint above DBL_MAX is DBL_MAX + 2^970; beyond it t1
    // rounds to infinity.
    const Q top = Q(0x1.fffffffffffffp1023) + Q(0x1p970);
    if (std::isinf(x)) return x > 0 && !lt(top);
    if (std::isnan(x)) return false;
    const double up = std::nextafter(x, INFINITY), down = std::nextafter(x, -INFINITY);
    const Q mp = std::isinf(up) ? top : Q((Q(x) + Q(up)) / 2);
    const Q mm = std::isinf(down) ? Q(-top) : Q((Q(x) + Q(down)) / 2);
    std::uint64_t bits;
    std::memcpy(&bits, &x, 8);
    const bool even = (bits & 1u) == 0;
    const bool upper_ok = even ? le(mp) : lt(mp);
    const bool lower_ok = even ? !lt(mm) : !le(mm);
    return upper_ok && lower_ok;
}

bool is_rounded_min_sphere_sqradius(const double* xyz, unsigned long n, double x) {
    using KQ = CGAL::Cartesian<Q>;
    std::vector<KQ::Point_3> pts;
    for (unsigned long i = 0; i < n; ++i) pts.emplace_back(Q(xyz[3 * i]), Q(xyz[3 * i + 1]), Q(xyz[3 * i + 2]));
    CGAL::Min_sphere_d<CGAL::Min_sphere_annulus_d_traits_3<KQ>> ms(pts.begin(), pts.end());
    return nearest(Q(ms.squared_radius()), x);
}
namespace {
// The box { c + sum s_i a_i : |s_i| <= h_i } (axes = a0 a1 a2, 9 values) in exact rationals: each
// point's frame coordinates s = M^-1 (p - c) by Cramer's rule, M's columns the axes.
struct q_box {
    Q a[3][3];
    Q c[3], h[3], D;
    q_box(const double cc[3], const double axes[9], const double hh[3]) {
        for (int r = 0; r < 3; ++r)
            for (int col = 0; col < 3; ++col) a[r][col] = Q(axes[3 * col + r]);
        for (int i = 0; i < 3; ++i) c[i] = Q(cc[i]), h[i] = Q(hh[i]);
        D = det(a);
    }
    static Q det(const Q m[3][3]) { // a Q, not a gmpxx expression over temporaries
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }
    // the frame coordinate s_k of p (D != 0)
    Q coordinate(const Q p[3], int k) const {
        Q m[3][3];
        for (int r = 0; r < 3; ++r)
            for (int col = 0; col < 3; ++col) m[r][col] = col == k ? Q(p[r] - c[r]) : a[r][col];
        return det(m) / D;
    }
    bool holds(const Q p[3]) const {
        for (int k = 0; k < 3; ++k)
            if (qabs(coordinate(p, k)) > h[k]) return false;
        return true;
    }
    // corner m: c + sum +-h_i a_i (bit i of m: +)
    void corner(int m, Q x[3]) const {
        for (int k = 0; k < 3; ++k) x[k] = c[k];
        for (int i = 0; i < 3; ++i) {
            const Q f = (m >> i & 1) ? h[i] : Q(-h[i]);
            for (int k = 0; k < 3; ++k) x[k] += f * a[k][i];
        }
    }
};
} // namespace

bool all_in_box(const double* xyz, unsigned long n, const double c[3], const double axes[9], const double h[3]) {
    const q_box b(c, axes, h);
    if (b.D == 0) return false;
    for (unsigned long i = 0; i < n; ++i) {
        const Q p[3] = {Q(xyz[3 * i]), Q(xyz[3 * i + 1]), Q(xyz[3 * i + 2])};
        if (!b.holds(p)) return false;
    }
    return true;
}
bool box_in_box(const double c[3], const double axes[9], const double h[3], const double ic[3], const double iaxes[9], const double ih[3]) {
    const q_box out(c, axes, h), in(ic, iaxes, ih);
    if (out.D == 0) return false;
    for (int m = 0; m < 8; ++m) {
        Q x[3];
        in.corner(m, x);
        if (!out.holds(x)) return false;
    }
    return true;
}
bool ball_in_box(const double c[3], const double axes[9], const double h[3], const double center[3], double r) {
    const q_box b(c, axes, h);
    if (b.D == 0) return false; // precondition: independent axes
    const Q p[3] = {Q(center[0]), Q(center[1]), Q(center[2])};
    const Q rr = Q(r) * Q(r);
    for (int k = 0; k < 3; ++k) {
        // the distance from p to the faces s_k = +-h_k is (h_k - |s_k|) |D| / |a_i x a_j|
        const Q room = b.h[k] - qabs(b.coordinate(p, k));
        if (room < 0) return false;
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const Q n[3] = {b.a[1][i] * b.a[2][j] - b.a[2][i] * b.a[1][j], b.a[2][i] * b.a[0][j] - b.a[0][i] * b.a[2][j],
                        b.a[0][i] * b.a[1][j] - b.a[1][i] * b.a[0][j]};
        const Q nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if (room * room * b.D * b.D < rr * nn) return false;
    }
    return true;
}
bool box_in_ball(const double c[3], const double axes[9], const double h[3], const double center[3], double r) {
    const q_box b(c, axes, h);
    const Q rr = Q(r) * Q(r);
    for (int m = 0; m < 8; ++m) {
        Q x[3];
        b.corner(m, x);
        Q d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (x[k] - Q(center[k])) * (x[k] - Q(center[k]));
        if (d2 > rr) return false;
    }
    return true;
}
bool box_in_capsule(const double c[3], const double axes[9], const double h[3], const double a[3], const double b[3], double r) {
    const q_box box(c, axes, h);
    const Q rr = Q(r) * Q(r);
    Q d[3], dd = 0;
    for (int k = 0; k < 3; ++k) d[k] = Q(b[k]) - Q(a[k]), dd += d[k] * d[k];
    for (int m = 0; m < 8; ++m) {
        Q x[3], along = 0;
        box.corner(m, x);
        for (int k = 0; k < 3; ++k) along += (x[k] - Q(a[k])) * d[k];
        Q t = 0; // the nearest point's parameter, clamped to [0, 1]
        if (dd > 0 && along > 0) t = along >= dd ? Q(1) : Q(along / dd);
        Q d2 = 0;
        for (int k = 0; k < 3; ++k) {
            const Q e = x[k] - (Q(a[k]) + t * d[k]);
            d2 += e * e;
        }
        if (d2 > rr) return false;
    }
    return true;
}
namespace {
using q3 = std::array<Q, 3>;
q3 sub(const q3& a, const q3& b) { return {Q(a[0] - b[0]), Q(a[1] - b[1]), Q(a[2] - b[2])}; }
q3 crossq(const q3& a, const q3& b) { return {Q(a[1] * b[2] - a[2] * b[1]), Q(a[2] * b[0] - a[0] * b[2]), Q(a[0] * b[1] - a[1] * b[0])}; }
Q dotq(const q3& a, const q3& b) { return Q(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]); }
bool zero(const q3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
// p in the closed triangle (a, b, c), any of them possibly equal or collinear.
bool in_triangle(const q3& p, const q3& a, const q3& b, const q3& c) {
    const q3 n = crossq(sub(b, a), sub(c, a));
    if (!zero(n)) {
        if (dotq(n, sub(p, a)) != 0) return false;
        return dotq(n, crossq(sub(b, a), sub(p, a))) >= 0 && dotq(n, crossq(sub(c, b), sub(p, b))) >= 0 &&
               dotq(n, crossq(sub(a, c), sub(p, c))) >= 0;
    }
    const q3 v[3] = {a, b, c};
    int u = 0, w = 0;
    Q best = -1;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (const Q d = dotq(sub(v[j], v[i]), sub(v[j], v[i])); d > best) best = d, u = i, w = j;
    const q3 d = sub(v[w], v[u]), e = sub(p, v[u]);
    if (zero(d)) return zero(e); // one point
    if (!zero(crossq(d, e))) return false;
    const Q t = dotq(e, d);
    return t >= 0 && t <= dotq(d, d);
}
} // namespace
bool box_in_tetrahedron(const double c[3], const double axes[9], const double h[3], const double t[12]) {
    const q_box b(c, axes, h);
    q3 v[4];
    for (int i = 0; i < 4; ++i) v[i] = {Q(t[3 * i]), Q(t[3 * i + 1]), Q(t[3 * i + 2])};
    auto pt = [](const q3& x) { return K::Point_3(FT(x[0]), FT(x[1]), FT(x[2])); };
    const K::Tetrahedron_3 solid(pt(v[0]), pt(v[1]), pt(v[2]), pt(v[3]));
    const bool flat = solid.is_degenerate();
    for (int m = 0; m < 8; ++m) {
        q3 x;
        b.corner(m, x.data());
        if (!flat) {
            if (solid.has_on_unbounded_side(pt(x))) return false;
            continue;
        }
        const int faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
        bool in = false;
        for (const auto& f : faces) in = in || in_triangle(x, v[f[0]], v[f[1]], v[f[2]]);
        if (!in) return false;
    }
    return true;
}
bool ball_in_aabb(const double mn[3], const double mx[3], const double center[3], double r) {
    for (int k = 0; k < 3; ++k)
        if (Q(center[k]) - Q(r) < Q(mn[k]) || Q(center[k]) + Q(r) > Q(mx[k])) return false;
    return true;
}
bool ball_aabb(const double mn[3], const double mx[3], const double center[3], double r) {
    if (!(mn[0] <= mx[0] && mn[1] <= mx[1] && mn[2] <= mx[2])) return false;
    // CGAL's Sphere_3 / Iso_cuboid_3 test compares the centre's squared distance to the box with
    // r^2 (Intersections_3/internal/Iso_cuboid_3_Sphere_3_do_intersect.h): the ball's test.
    return CGAL::do_intersect(K::Sphere_3(P(center), FT(r) * FT(r)), K::Iso_cuboid_3(P(mn), P(mx)));
}
bool box_in_constraints(const double c[3], const double axes[9], const double h[3], const convex_set& s) {
    for (int m = 0; m < 8; ++m) {
        Q x[3] = {Q(c[0]), Q(c[1]), Q(c[2])};
        for (int i = 0; i < 3; ++i) {
            const Q f = (m >> i & 1) ? Q(h[i]) : Q(-h[i]);
            for (int k = 0; k < 3; ++k) x[k] += f * Q(axes[3 * i + k]);
        }
        auto along = [&](const std::array<double, 3>& n) -> Q { return Q(n[0]) * x[0] + Q(n[1]) * x[1] + Q(n[2]) * x[2]; };
        for (const auto& e : s.halfspaces)
            if (along(e.n) > Q(e.offset)) return false;
        for (const auto& e : s.slabs) {
            const Q t = along(e.n);
            if (t < Q(e.lo) || t > Q(e.hi)) return false;
        }
    }
    return true;
}
bool all_in_ball(const double* xyz, unsigned long n, const double c[3], double r) {
    const Q cx(c[0]), cy(c[1]), cz(c[2]), rr = Q(r) * Q(r);
    for (unsigned long i = 0; i < n; ++i) {
        const Q dx = Q(xyz[3 * i]) - cx, dy = Q(xyz[3 * i + 1]) - cy, dz = Q(xyz[3 * i + 2]) - cz;
        if (dx * dx + dy * dy + dz * dz > rr) return false;
    }
    return true;
}
double min_sphere_of_spheres_epick(const double* xyz, unsigned long n) {
    using Traits = CGAL::Min_sphere_of_spheres_d_traits_3<KI, double>;
    std::vector<Traits::Sphere> s;
    s.reserve(n);
    for (unsigned long i = 0; i < n; ++i) s.emplace_back(KI::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), 0.0);
    CGAL::Min_sphere_of_spheres_d<Traits> ms(s.begin(), s.end());
    return CGAL::to_double(ms.radius());
}
bool ray_triangle_epick(const double o[3], const double d[3], const double a[3], const double b[3], const double c[3]) {
    return CGAL::do_intersect(KI::Ray_3(P<KI>(o), V<KI>(d)), KI::Triangle_3(P<KI>(a), P<KI>(b), P<KI>(c)));
}
bool ray_box_epick(const double o[3], const double d[3], const double mn[3], const double mx[3]) {
    return CGAL::do_intersect(KI::Ray_3(P<KI>(o), V<KI>(d)), KI::Iso_cuboid_3(P<KI>(mn), P<KI>(mx)));
}
bool segment_triangle_epick(const double p[3], const double q[3], const double a[3], const double b[3], const double c[3]) {
    return CGAL::do_intersect(KI::Segment_3(P<KI>(p), P<KI>(q)), KI::Triangle_3(P<KI>(a), P<KI>(b), P<KI>(c)));
}
bool triangle_triangle_epick(const double a[3], const double b[3], const double c[3], const double d[3], const double e[3],
                             const double f[3]) {
    return CGAL::do_intersect(KI::Triangle_3(P<KI>(a), P<KI>(b), P<KI>(c)), KI::Triangle_3(P<KI>(d), P<KI>(e), P<KI>(f)));
}
bool box_segment_epick(const double mn[3], const double mx[3], const double p[3], const double q[3]) {
    const KI::Iso_cuboid_3 box(P<KI>(mn), P<KI>(mx));
    if (P<KI>(p) == P<KI>(q)) return !box.has_on_unbounded_side(P<KI>(p));
    return CGAL::do_intersect(KI::Segment_3(P<KI>(p), P<KI>(q)), box);
}
bool box_line_epick(const double mn[3], const double mx[3], const double p[3], const double d[3]) {
    return CGAL::do_intersect(KI::Line_3(P<KI>(p), V<KI>(d)), KI::Iso_cuboid_3(P<KI>(mn), P<KI>(mx)));
}
bool box_triangle_epick(const double mn[3], const double mx[3], const double a[3], const double b[3], const double c[3]) {
    return CGAL::do_intersect(KI::Triangle_3(P<KI>(a), P<KI>(b), P<KI>(c)), KI::Iso_cuboid_3(P<KI>(mn), P<KI>(mx)));
}
bool box_box_epick(const double amn[3], const double amx[3], const double bmn[3], const double bmx[3]) {
    return CGAL::do_intersect(KI::Iso_cuboid_3(P<KI>(amn), P<KI>(amx)), KI::Iso_cuboid_3(P<KI>(bmn), P<KI>(bmx)));
}
bool point_in_box_epick(const double p[3], const double mn[3], const double mx[3]) {
    return !KI::Iso_cuboid_3(P<KI>(mn), P<KI>(mx)).has_on_unbounded_side(P<KI>(p));
}
int orient3d_epick(const double a[3], const double b[3], const double c[3], const double d[3]) {
    return -sgn(CGAL::orientation(P<KI>(a), P<KI>(b), P<KI>(c), P<KI>(d)));
}
double capsule_point_distance_epick(const double a[3], const double b[3], double r, const double p[3]) {
    const KI::Point_3 x = P<KI>(p), u = P<KI>(a), w = P<KI>(b);
    const double d2 = u == w ? CGAL::squared_distance(x, u) : CGAL::squared_distance(x, KI::Segment_3(u, w));
    return std::sqrt(d2) - std::fabs(r);
}
double tetrahedron_point_distance_epick(const double t[12], const double p[3]) {
    const KI::Point_3 x = P<KI>(p), v[4] = {P<KI>(t), P<KI>(t + 3), P<KI>(t + 6), P<KI>(t + 9)};
    const KI::Tetrahedron_3 tet(v[0], v[1], v[2], v[3]);
    if (const double d2 = CGAL::squared_distance(x, tet); d2 > 0.0) return std::sqrt(d2);
    if (tet.is_degenerate() || !tet.has_on_bounded_side(x)) return 0.0;
    double d2 = CGAL::squared_distance(x, KI::Triangle_3(v[1], v[2], v[3]));
    for (int i = 0; i < 3; ++i) { // the faces opposite v[1], v[2], v[3]
        const KI::Triangle_3 f(v[0], v[(i + 2) % 3 + 1], v[(i + 1) % 3 + 1]);
        d2 = std::min(d2, CGAL::squared_distance(x, f));
    }
    return -std::sqrt(d2);
}

} // namespace oracle
