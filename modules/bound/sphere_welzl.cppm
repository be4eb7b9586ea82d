// sphere_welzl: the exact minimum enclosing ball of a point set, by Welzl's move-to-front
// algorithm (expected linear time after a random shuffle). Every "is the point outside the
// current ball" decision is exact: the ball of a support set (1 to 4 affinely independent
// points on its boundary, centre in their affine hull) is computed in exact rationals, and a
// rigorous double filter (rounded centre, a proven bound on its distance to the exact centre,
// proven bounds on the radius) settles all but the nearly cospherical points. The returned
// centre is the exact centre rounded to nearest; the radius is then rounded outward against
// exact tests, so every input point is provably inside. `squared_radius` is the exact minimum
// squared radius, correctly rounded.
// Source: Welzl, "Smallest enclosing disks (balls and ellipsoids)", LNCS 555 (1991); move-to-
// front and the support-set ball as in Gaertner, "Fast and robust smallest enclosing balls",
// ESA 1999, sections 2-3. Exact rationals: Boost.Multiprecision cpp_rational (heap-allocating:
// a construction, not a scalar query).
module;
#include <array>
#include <bit>
#include <boost/multiprecision/cpp_int.hpp>
#include <cstdint>
#include <random>
#include <span>
#include <vector>
export module incidence.bound:sphere_welzl;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :outward;

export namespace incidence::bound {

struct min_sphere {
    sphere3 sphere;                // contains every input point (outward rounded)
    double squared_radius;         // exact minimum squared radius, correctly rounded (inf beyond binary64)
    std::vector<std::uint32_t> support; // indices of the points on the exact minimum sphere's boundary (1..4)
};

namespace welzl_detail {
using Q = boost::multiprecision::cpp_rational;
struct qv {
    Q x, y, z;
};
inline qv q(point3 p) { return {Q(p.x), Q(p.y), Q(p.z)}; }
inline qv operator-(const qv& a, const qv& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline qv operator+(const qv& a, const qv& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline qv operator*(const qv& a, const Q& s) { return {a.x * s, a.y * s, a.z * s}; }
inline Q dot(const qv& a, const qv& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline qv cross(const qv& a, const qv& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The nearest double to an exact rational (ties to even), by exact midpoint comparisons.
inline double nearest(const Q& x) {
    double r = x.convert_to<double>();
    for (int i = 0; i < 8 && is_finite(r); ++i) {
        const double up = arith::next_up(r), dn = arith::next_down(r);
        if (is_finite(up) && x > (Q(r) + Q(up)) / 2) { r = up; continue; }
        if (is_finite(dn) && x < (Q(r) + Q(dn)) / 2) { r = dn; continue; }
        if (is_finite(up) && x == (Q(r) + Q(up)) / 2 && (std::bit_cast<std::uint64_t>(r) & 1u)) r = up;
        if (is_finite(dn) && x == (Q(r) + Q(dn)) / 2 && (std::bit_cast<std::uint64_t>(r) & 1u)) r = dn;
        break;
    }
    return r;
}

struct ball {
    qv c;     // exact centre
    Q r2;     // exact squared radius
    // Filter data, all proven: |c - cd| <= delta, r_lo <= sqrt(r2) <= r_hi.
    point3 cd{};
    double delta = 0, r_lo = 0, r_hi = 0;
    bool filter = false;
};

// The smallest ball with the support points on its boundary (affinely independent, 1..4).
inline ball through(const std::array<point3, 4>& s, int n) {
    ball b;
    const qv a = q(s[0]);
    if (n == 1) {
        b.c = a;
    } else if (n == 2) {
        b.c = (a + q(s[1])) * Q(1, 2);
    } else if (n == 3) {
        const qv u = q(s[1]) - a, v = q(s[2]) - a, w = cross(u, v);
        const Q den = 2 * dot(w, w);
        b.c = a + (cross(v, w) * dot(u, u) + cross(w, u) * dot(v, v)) * (1 / den);
    } else {
        const qv u = q(s[1]) - a, v = q(s[2]) - a, w = q(s[3]) - a;
        const Q den = 2 * dot(u, cross(v, w));
        b.c = a + (cross(v, w) * dot(u, u) + cross(w, u) * dot(v, v) + cross(u, v) * dot(w, w)) * (1 / den);
    }
    const qv d = a - b.c;
    b.r2 = dot(d, d);
    // Filter data, each bound checked exactly.
    b.cd = {nearest(b.c.x), nearest(b.c.y), nearest(b.c.z)};
    if (!is_finite(b.cd)) return b;
    const qv e = q(b.cd) - b.c;
    const Q e2 = dot(e, e);
    double delta = arith::sqrt(e2.convert_to<double>()) * (1 + 0x1p-40) + 0x1p-1060;
    while (is_finite(delta) && Q(delta) * Q(delta) < e2) delta *= 2;
    const double r = arith::sqrt(nearest(b.r2));
    if (!is_finite(r) || !is_finite(delta)) return b; // squares beyond binary64: exact tests only
    double lo = r * (1 - 0x1p-40), hi = r * (1 + 0x1p-40) + 0x1p-1060;
    while (lo > 0 && Q(lo) * Q(lo) > b.r2) lo *= 0.5;
    while (is_finite(hi) && Q(hi) * Q(hi) < b.r2) hi *= 2;
    if (!is_finite(delta) || !is_finite(hi) || !is_finite(r)) return b;
    b.delta = delta, b.r_lo = lo, b.r_hi = hi, b.filter = true;
    return b;
}

// Is p strictly outside the exact ball?
inline bool outside(const ball& b, point3 p) {
    if (b.filter) {
        const double d = length(p - b.cd); // within 3 ulps of |p - cd| (no over/underflow of squares)
        if (is_finite(d) && d > 0x1p-900 && d < 0x1p900) {
            if (d * (1 + 0x1p-45) + b.delta < b.r_lo) return false;
            if (d * (1 - 0x1p-45) - b.delta > b.r_hi) return true;
        }
    }
    const qv e = q(p) - b.c;
    return dot(e, e) > b.r2;
}

struct solver {
    std::span<const point3> pts;
    std::vector<std::uint32_t> next, prev; // the move-to-front list over point indices
    std::uint32_t head = 0;
    static constexpr std::uint32_t none = ~std::uint32_t{0};
    std::array<point3, 4> support{};
    std::array<std::uint32_t, 4> support_index{};
    int n = 0;
    ball current;
    bool have = false;
    std::vector<std::uint32_t> best_support;

    void move_to_front(std::uint32_t i) {
        if (i == head) return;
        next[prev[i]] = next[i];
        if (next[i] != none) prev[next[i]] = prev[i];
        next[i] = head, prev[i] = none, prev[head] = i, head = i;
    }
    // mb(points before `end` in the list, with the current support on the boundary)
    void mtf(std::uint32_t end) {
        if (n == 4) return;
        for (std::uint32_t i = head; i != end && i != none;) {
            const std::uint32_t nx = next[i];
            if (!have || outside(current, pts[i])) {
                support[static_cast<unsigned>(n)] = pts[i], support_index[static_cast<unsigned>(n)] = i, ++n;
                current = through(support, n);
                have = true;
                best_support.assign(support_index.begin(), support_index.begin() + n);
                mtf(i);
                --n;
                move_to_front(i);
            }
            i = nx;
        }
    }
};
} // namespace welzl_detail

// Exact minimum enclosing sphere. `seed` fixes the shuffle (the result does not depend on it).
[[nodiscard]] inline result<min_sphere> sphere_welzl(std::span<const point3> points, std::uint64_t seed = 1) {
    if (points.empty()) return error{errc::empty_input};
    for (const point3& p : points)
        if (!is_finite(p)) return error{errc::not_finite};
    const auto n = static_cast<std::uint32_t>(points.size());
    welzl_detail::solver s;
    s.pts = points;
    s.next.resize(n), s.prev.resize(n);
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
    std::mt19937_64 g(seed);
    for (std::uint32_t i = n - 1; i > 0; --i) std::swap(order[i], order[std::uniform_int_distribution<std::uint32_t>(0, i)(g)]);
    for (std::uint32_t k = 0; k < n; ++k) {
        s.next[order[k]] = k + 1 < n ? order[k + 1] : welzl_detail::solver::none;
        s.prev[order[k]] = k > 0 ? order[k - 1] : welzl_detail::solver::none;
    }
    s.head = order[0];
    s.mtf(welzl_detail::solver::none);
    const welzl_detail::ball& b = s.current;
    // The support of the final ball: the points exactly on its boundary among the last support.
    std::vector<std::uint32_t> support;
    for (std::uint32_t i : s.best_support) {
        const auto e = welzl_detail::q(points[i]) - b.c;
        if (welzl_detail::dot(e, e) == b.r2) support.push_back(i);
    }
    const point3 c = b.filter ? b.cd : point3{welzl_detail::nearest(b.c.x), welzl_detail::nearest(b.c.y), welzl_detail::nearest(b.c.z)};
    if (!is_finite(c)) return error{errc::out_of_range};
    const double r2 = welzl_detail::nearest(b.r2);
    const auto r = enclosing_radius(c, points);
    if (!r) return r.error();
    return min_sphere{sphere3{c, r.value()}, r2, support};
}

} // namespace incidence::bound
