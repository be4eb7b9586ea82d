// Outward rounding shared by the constructions: the smallest radius (up to a few ulps) whose
// ball around a given centre provably contains every point, decided by the exact sign of
// r^2 - |p - c|^2 (filter first, exact fallback: see incidence.arith), and doubles just below
// or above an exact dyadic value.
module;
#include <span>
export module incidence.bound:outward;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::bound {

// Is p in the closed ball (c, r)? Exact.
[[nodiscard]] constexpr bool in_ball(point3 c, double r, point3 p) {
    bool valid = true;
    const sign s = arith::exact_sign(
        [=](auto L) {
            const auto d = arith::lift(L, p) - arith::lift(L, c);
            return L(r) * L(r) - arith::dot(d, d);
        },
        valid);
    return valid && s != sign::negative;
}

// |v| in double without overflow or underflow of the squares (about 2 ulps).
[[nodiscard]] constexpr double length(vec3 v) {
    const double ax = v.x < 0 ? -v.x : v.x, ay = v.y < 0 ? -v.y : v.y, az = v.z < 0 ? -v.z : v.z;
    const double m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
    if (m == 0.0 || !is_finite(m)) return m;
    if (m > 0x1p-500 && m < 0x1p500) return arith::sqrt(dot(v, v)); // squares stay normal and finite
    const int e = arith::exponent_of(m);                            // scale by a power of two: exact, no 1/m overflow for subnormal m
    const vec3 u{arith::scale_by_power_of_two(v.x, -e), arith::scale_by_power_of_two(v.y, -e), arith::scale_by_power_of_two(v.z, -e)};
    return arith::scale_by_power_of_two(arith::sqrt(dot(u, u)), e);
}

// The ball around c with radius >= `guess` that contains every point, its radius within a few
// ulps of the least such double. Errors: a radius beyond binary64, non-finite input.
[[nodiscard]] constexpr result<double> enclosing_radius(point3 c, std::span<const point3> points, double guess = 0.0) {
    if (!is_finite(c)) return error{errc::not_finite};
    double r = guess > 0.0 ? guess : 0.0;
    for (const point3& p : points) { // start just below the farthest point: few exact steps after
        if (!is_finite(p)) return error{errc::not_finite};
        const double l = length(p - c) * (1.0 - 0x1p-50);
        if (l > r) r = l;
    }
    if (!is_finite(r)) return error{errc::out_of_range};
    for (const point3& p : points) {
        if (in_ball(c, r, p)) continue;
        const double approx = length(p - c);
        double t = approx > r ? approx : arith::next_up(r);
        while (!in_ball(c, t, p)) {
            t = t < 0x1p-1000 ? (t * 2.0 > 0x1p-1074 ? t * 2.0 : 0x1p-1074) : t * (1.0 + 0x1p-50);
            if (!is_finite(t)) return error{errc::out_of_range};
        }
        // Tighten: bisect between the last radius that failed and t (t contains p).
        double lo = r;
        for (int i = 0; i < 80 && arith::next_up(lo) < t; ++i) {
            const double mid = lo + (t - lo) * 0.5;
            if (mid <= lo || mid >= t) break;
            if (in_ball(c, mid, p)) t = mid;
            else lo = mid;
        }
        r = t;
    }
    if (!is_finite(r)) return error{errc::out_of_range};
    return r;
}

// The largest double <= x and the smallest double >= x (x exact; may give an infinity).
[[nodiscard]] constexpr double round_down(const arith::dyadic& x) {
    double r = arith::to_double(x);
    if (is_finite(r) && arith::sign_of(arith::to_dyadic(r) - x) > 0) r = arith::next_down(r);
    return r;
}
[[nodiscard]] constexpr double round_up(const arith::dyadic& x) {
    double r = arith::to_double(x);
    if (is_finite(r) && arith::sign_of(arith::to_dyadic(r) - x) < 0) r = arith::next_up(r);
    return r;
}

} // namespace incidence::bound
