// The floor of a correctly rounded value (floor/intersection/<pair>/random and, where the processor
// has it, floor_fma/...): the answer in plain double, then, for a hit, every value the exact
// tier returns (t_enter, t_exit and the point; for a triangle t, the point, the barycentrics and
// the normal) evaluated once to double-double precision by error-free transforms (Dekker and
// Knuth; Muller et al., Handbook of Floating-Point Arithmetic, 2018, chapter 14), with no error
// bound and no rounding test. Rounding to the nearest double needs more than double's 53 bits of
// the value, so any method by a more precise evaluation spends at least this; the exact tier's
// cost beside it is its proof. floor_fma takes the products from the processor's fused
// multiply-add (2 operations where Dekker's product takes 17), the cheapest such evaluation this
// machine can do; the library cannot use it at compile time or in a build for every x86-64.
#pragma once
#include <cmath>
#include <type_traits>

namespace bench::value_floor {

// The library's error-free transforms (arith's eft: Knuth's two_sum, Dekker's fast_two_sum and
// two_product); the operations below add no error bound.
using dd = incidence::arith::two_double;
struct dekker {
    [[gnu::always_inline]] static dd product(double a, double b) { return incidence::arith::two_product(a, b); }
};
struct fused {
    [[gnu::always_inline]] static dd product(double a, double b) {
        const double p = a * b;
        return {p, __builtin_fma(a, b, -p)};
    }
};

using incidence::arith::fast_two_sum;
using incidence::arith::two_sum;
[[gnu::always_inline]] inline dd operator+(dd a, dd b) {
    const dd s = two_sum(a.hi, b.hi);
    return fast_two_sum(s.hi, s.lo + a.lo + b.lo);
}
[[gnu::always_inline]] inline dd operator-(dd a) { return {-a.hi, -a.lo}; }
[[gnu::always_inline]] inline dd operator-(dd a, dd b) { return a + (-b); }
[[gnu::always_inline]] inline dd exact(double a) { return {a, 0.0}; }
[[gnu::always_inline]] inline dd difference(double a, double b) { return incidence::arith::two_diff(a, b); }
template <class M>
[[gnu::always_inline]] inline dd mul(dd a, dd b) {
    const dd p = M::product(a.hi, b.hi);
    return fast_two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}
template <class M>
[[gnu::always_inline]] inline dd mul(dd a, double b) {
    const dd p = M::product(a.hi, b);
    return fast_two_sum(p.hi, p.lo + a.lo * b);
}
template <class M>
[[gnu::always_inline]] inline dd div(dd a, dd b) {
    const double q1 = a.hi / b.hi;
    const dd r = a - mul<M>(b, q1);
    return fast_two_sum(q1, r.hi / b.hi);
}
template <class M>
[[gnu::always_inline]] inline dd root(dd a) {
    if (!(a.hi > 0.0)) return {0.0, 0.0};
    const double x = std::sqrt(a.hi);
    const dd r = a - M::product(x, x);
    return fast_two_sum(x, r.hi / (2.0 * x));
}
[[gnu::always_inline]] inline double value(dd a) { return a.hi + a.lo; }

struct dd3 {
    dd x, y, z;
};
[[gnu::always_inline]] inline dd3 differences(incidence::point3 a, incidence::point3 b) {
    return {difference(a.x, b.x), difference(a.y, b.y), difference(a.z, b.z)};
}
template <class M>
[[gnu::always_inline]] inline dd dot(dd3 a, incidence::vec3 b) {
    return mul<M>(a.x, b.x) + mul<M>(a.y, b.y) + mul<M>(a.z, b.z);
}
template <class M>
[[gnu::always_inline]] inline dd dot(dd3 a, dd3 b) {
    return mul<M>(a.x, b.x) + mul<M>(a.y, b.y) + mul<M>(a.z, b.z);
}
template <class M>
[[gnu::always_inline]] inline dd3 cross(dd3 a, dd3 b) {
    return {mul<M>(a.y, b.z) - mul<M>(a.z, b.y), mul<M>(a.z, b.x) - mul<M>(a.x, b.z), mul<M>(a.x, b.y) - mul<M>(a.y, b.x)};
}
[[gnu::always_inline]] inline dd3 lifted(incidence::vec3 v) { return {exact(v.x), exact(v.y), exact(v.z)}; }
// o + t d, each coordinate to double-double, rounded once.
template <class M>
[[gnu::always_inline]] inline incidence::point3 point_at(incidence::point3 o, dd t, incidence::vec3 d) {
    return {value(exact(o.x) + mul<M>(t, d.x)), value(exact(o.y) + mul<M>(t, d.y)), value(exact(o.z) + mul<M>(t, d.z))};
}

// What the floor returns: enough that nothing is optimised away.
struct hit {
    bool exists = false;
    double t_enter = 0.0, t_exit = 0.0;
    incidence::point3 point{};
    double u = 0.0, v = 0.0, w = 0.0;
    incidence::vec3 normal{};
    explicit operator bool() const { return exists; }
};

// A plane against a ray or a line: t = (offset - n . o) / (n . d).
template <class M, class X>
[[gnu::always_inline]] inline hit plane_floor(const incidence::plane3& p, const X& x) {
    const incidence::vec3 n = p.normal, d = x.direction;
    const incidence::point3 o = x.origin;
    const double s = n.x * d.x + n.y * d.y + n.z * d.z;
    const double a = p.offset - (n.x * o.x + n.y * o.y + n.z * o.z);
    if (s == 0.0) { // parallel: in the plane (the whole range, no value to compute) or apart
        if (a != 0.0) return {};
        constexpr bool line = std::is_same_v<X, incidence::line3>;
        return {true, line ? -INFINITY : 0.0, INFINITY, o};
    }
    if constexpr (std::is_same_v<X, incidence::ray3>)
        if ((a > 0.0) != (s > 0.0) && a != 0.0) return {};
    const dd3 nn = lifted(n);
    const dd sd = dot<M>(nn, d);
    const dd ad = exact(p.offset) - dot<M>(nn, incidence::vec3{o.x, o.y, o.z});
    const dd t = div<M>(ad, sd);
    hit h{true, value(t), value(t), point_at<M>(o, t, d)};
    return h;
}

// A box against a ray: the slabs in double choose the entry and exit faces; each parameter
// (bound - o_i) / d_i and the point's two other coordinates to double-double.
template <class M>
[[gnu::always_inline]] inline hit box_floor(const incidence::aabb3& b, const incidence::ray3& r) {
    const double o[3] = {r.origin.x, r.origin.y, r.origin.z}, d[3] = {r.direction.x, r.direction.y, r.direction.z};
    const double lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
    double t0 = 0.0, t1 = INFINITY;
    int enter = -1, exit = -1;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (o[i] < lo[i] || o[i] > hi[i]) return {};
            continue;
        }
        const double inv = 1.0 / d[i];
        const double near = ((d[i] > 0.0 ? lo[i] : hi[i]) - o[i]) * inv, far = ((d[i] > 0.0 ? hi[i] : lo[i]) - o[i]) * inv;
        if (near > t0) t0 = near, enter = i;
        if (far < t1) t1 = far, exit = i;
    }
    if (t0 > t1) return {};
    auto parameter = [&](int i, bool entering) {
        const double bound = (d[i] > 0.0) == entering ? lo[i] : hi[i];
        return div<M>(difference(bound, o[i]), exact(d[i]));
    };
    hit h{true, 0.0, INFINITY, r.origin};
    if (exit >= 0) h.t_exit = value(parameter(exit, false));
    if (enter >= 0) {
        const dd t = parameter(enter, true);
        h.t_enter = value(t);
        h.point = point_at<M>(r.origin, t, r.direction);
    }
    return h;
}

// A ball against a ray: the roots of a t^2 + 2 b t + c, written so that nothing cancels.
template <class M>
[[gnu::always_inline]] inline hit ball_floor(const incidence::sphere3& s, const incidence::ray3& r) {
    const incidence::vec3 d = r.direction;
    const incidence::vec3 m{r.origin.x - s.center.x, r.origin.y - s.center.y, r.origin.z - s.center.z};
    const double a = d.x * d.x + d.y * d.y + d.z * d.z;
    const double b = m.x * d.x + m.y * d.y + m.z * d.z;
    const double c = m.x * m.x + m.y * m.y + m.z * m.z - s.radius * s.radius;
    if (a == 0.0 || b * b - a * c < 0.0 || (c > 0.0 && b > 0.0)) return {};
    const dd3 md = differences(r.origin, s.center);
    const dd ad = dot<M>(lifted(d), d), bd = dot<M>(md, d);
    const dd cd = dot<M>(md, md) - M::product(s.radius, s.radius);
    const dd sq = root<M>(mul<M>(bd, bd) - mul<M>(ad, cd));
    const dd q = bd.hi < 0.0 ? sq - bd : -(bd + sq); // -b + sign(-b) sqrt(disc)
    dd t1 = div<M>(q, ad), t2 = div<M>(cd, q);
    if (t2.hi < t1.hi) std::swap(t1, t2);
    hit h{true, 0.0, value(t2), r.origin};
    if (t1.hi > 0.0) {
        h.t_enter = value(t1);
        h.point = point_at<M>(r.origin, t1, d);
    }
    return h;
}

// A triangle against a ray (Moeller and Trumbore, J. Graphics Tools 2(1), 1997): t, u, v, w as
// ratios of triple products, the point and the normal, each to double-double.
template <class M>
[[gnu::always_inline]] inline hit triangle_floor(const incidence::triangle3& tr, const incidence::ray3& r) {
    const incidence::vec3 d = r.direction;
    const incidence::vec3 e1{tr.b.x - tr.a.x, tr.b.y - tr.a.y, tr.b.z - tr.a.z}, e2{tr.c.x - tr.a.x, tr.c.y - tr.a.y, tr.c.z - tr.a.z};
    const incidence::vec3 tv{r.origin.x - tr.a.x, r.origin.y - tr.a.y, r.origin.z - tr.a.z};
    const incidence::vec3 p{d.y * e2.z - d.z * e2.y, d.z * e2.x - d.x * e2.z, d.x * e2.y - d.y * e2.x};
    const double det = e1.x * p.x + e1.y * p.y + e1.z * p.z;
    if (det == 0.0) return {}; // in the triangle's plane: not covered (wrong_pct counts these cases)
    const double u = (tv.x * p.x + tv.y * p.y + tv.z * p.z) / det;
    const incidence::vec3 q{tv.y * e1.z - tv.z * e1.y, tv.z * e1.x - tv.x * e1.z, tv.x * e1.y - tv.y * e1.x};
    const double v = (d.x * q.x + d.y * q.y + d.z * q.z) / det;
    const double t = (e2.x * q.x + e2.y * q.y + e2.z * q.z) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0 || t < 0.0) return {};
    const dd3 E1 = differences(tr.b, tr.a), E2 = differences(tr.c, tr.a), T = differences(r.origin, tr.a);
    const dd3 P = cross<M>(lifted(d), E2), Q = cross<M>(T, E1);
    const dd D = dot<M>(E1, P);
    const dd un = dot<M>(T, P), vn = dot<M>(Q, d), tn = dot<M>(E2, Q);
    const dd td = div<M>(tn, D);
    const dd3 n = cross<M>(E1, E2);
    hit h{true, value(td), value(td), point_at<M>(r.origin, td, d)};
    h.v = value(div<M>(un, D));
    h.w = value(div<M>(vn, D));
    h.u = value(div<M>(D - un - vn, D));
    h.normal = {value(n.x), value(n.y), value(n.z)};
    return h;
}

// The pairs with a floor: a plane against a ray or a line, a box, a ball and a triangle against a ray.
template <class S, class X>
inline constexpr bool has_floor =
    std::is_same_v<X, incidence::ray3> ? (std::is_same_v<S, incidence::plane3> || std::is_same_v<S, incidence::aabb3> ||
                                          std::is_same_v<S, incidence::sphere3> || std::is_same_v<S, incidence::triangle3>)
                                       : std::is_same_v<X, incidence::line3> && std::is_same_v<S, incidence::plane3>;
template <class M, class S, class X>
[[gnu::always_inline]] inline hit of(const S& s, const X& x) {
    if constexpr (std::is_same_v<S, incidence::plane3>) return plane_floor<M>(s, x);
    else if constexpr (std::is_same_v<S, incidence::aabb3>) return box_floor<M>(s, x);
    else if constexpr (std::is_same_v<S, incidence::sphere3>) return ball_floor<M>(s, x);
    else return triangle_floor<M>(s, x);
}

template <class S, class X>
hit with_dekker(const S& s, const X& x) {
    return of<dekker>(s, x);
}
template <class S, class X>
[[gnu::target("fma")]] hit with_fma(const S& s, const X& x) {
    return of<fused>(s, x);
}

} // namespace bench::value_floor
