// sphere_welzl: the implementation of modules/bound/sphere_welzl.cppm (Welzl's algorithm with exact
// support-set balls in Boost.Multiprecision cpp_int; see the interface's comment for the method
// and its sources).
module;
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <boost/multiprecision/cpp_int.hpp>
#include <cstdint>
#include <random>
#include <span>
#include <vector>
module incidence.bound;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :outward;

namespace incidence::bound {

namespace welzl_detail {
// Exact integers: every input coordinate times 2^shift is an integer (one shift for the set), so
// centres are N / D with integer N, D and squared radii R / D^2: no rational normalisation.
using I = boost::multiprecision::cpp_int;
struct iv {
    I x, y, z;
};
inline iv operator-(const iv& a, const iv& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline iv operator+(const iv& a, const iv& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline iv operator*(const iv& a, const I& s) { return {a.x * s, a.y * s, a.z * s}; }
inline I dot(const iv& a, const iv& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline iv cross(const iv& a, const iv& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// x = m * 2^e with an integer m (|m| < 2^53), for finite x.
inline I mantissa(double x, int& e) {
    if (x == 0.0) {
        e = 0;
        return I(0);
    }
    int ex = 0;
    const double f = std::frexp(x, &ex);
    e = ex - 53;
    return I(static_cast<long long>(std::ldexp(f, 53)));
}
inline I shifted(I v, int k) { return k >= 0 ? I(v << k) : I(v >> -k); } // exact when the low bits are zero
inline I to_int(double x, int shift) {
    int e = 0;
    const I m = mantissa(x, e);
    return shifted(m, e + shift);
}
inline iv to_iv(point3 p, int shift) { return {to_int(p.x, shift), to_int(p.y, shift), to_int(p.z, shift)}; }

// n / (d 2^s) in double, relative error below 2^-51 unless it over- or underflows (d > 0).
inline double ratio(const I& n, const I& d, int s) {
    if (n == 0) return 0.0;
    const I an = n < 0 ? I(-n) : n;
    const int bn = int(boost::multiprecision::msb(an)), bd = int(boost::multiprecision::msb(d));
    const int kn = bn > 62 ? bn - 62 : 0, kd = bd > 62 ? bd - 62 : 0;
    const double q = I(an >> kn).convert_to<double>() / I(d >> kd).convert_to<double>();
    const double r = std::ldexp(q, kn - kd - s);
    return n < 0 ? -r : r;
}
// sign(n / (d 2^s) - x) for a double x (d > 0), exactly.
inline int compare(const I& n, const I& d, int s, double x) {
    int e = 0;
    const I m = mantissa(x, e); // x = m 2^e: compare n vs m d 2^(e + s)
    const int k = e + s;
    const I lhs = k >= 0 ? n : I(n << -k), rhs = k >= 0 ? I((m * d) << k) : I(m * d);
    return lhs < rhs ? -1 : (lhs > rhs ? 1 : 0);
}
// The midpoint of two adjacent finite doubles, as m 2^e.
inline I midpoint(double a, double b, int& e) {
    int ea = 0, eb = 0;
    I ma = mantissa(a, ea), mb = mantissa(b, eb);
    if (a == 0.0) ea = eb;
    if (b == 0.0) eb = ea;
    const int lo = ea < eb ? ea : eb;
    e = lo - 1; // (a + b) / 2 = (ma 2^(ea - lo) + mb 2^(eb - lo)) 2^(lo - 1)
    return I(ma << (ea - lo)) + I(mb << (eb - lo));
}
inline int compare_mid(const I& n, const I& d, int s, double a, double b) {
    int e = 0;
    const I m = midpoint(a, b, e);
    const int k = e + s;
    const I lhs = k >= 0 ? n : I(n << -k), rhs = k >= 0 ? I((m * d) << k) : I(m * d);
    return lhs < rhs ? -1 : (lhs > rhs ? 1 : 0);
}
// n / (d 2^s) rounded to nearest, ties to even (d > 0).
inline double nearest(const I& n, const I& d, int s) {
    double r = ratio(n, d, s);
    if (!is_finite(r)) return r;
    for (int i = 0; i < 8; ++i) {
        const double up = arith::next_up(r), dn = arith::next_down(r);
        const int cu = is_finite(up) ? compare_mid(n, d, s, r, up) : -1;
        const int cd = is_finite(dn) ? compare_mid(n, d, s, dn, r) : 1;
        if (cu > 0) {
            r = up;
            continue;
        }
        if (cd < 0) {
            r = dn;
            continue;
        }
        if ((cu == 0 || cd == 0) && (std::bit_cast<std::uint64_t>(r) & 1u)) r = cu == 0 ? up : dn;
        break;
    }
    return r;
}

struct ball {
    iv N; // centre = N / (D 2^shift)
    I D;  // > 0
    I R;  // squared radius = R / (D 2^shift)^2
    // Filter data, all proven: |c - cd| <= delta, r_lo <= radius <= r_hi.
    point3 cd{};
    double delta = 0, r_lo = 0, r_hi = 0;
    bool filter = false;
    // The same filter on squared distances: |p - cd|^2 below in_sq: inside; above out_sq: outside.
    double in_sq = -1, out_sq = __builtin_huge_val();
    double near_sq = -1; // |p - cd|^2 below it: |p - c| < r_lo - 2 delta (the final radius pass skips p)
};

// The smallest ball with the support points on its boundary (affinely independent, 1..4).
inline ball through(const std::array<point3, 4>& s, int n, int shift) {
    ball b;
    const iv A = to_iv(s[0], shift);
    if (n == 1) {
        b.N = A, b.D = 1;
    } else if (n == 2) {
        b.N = A + to_iv(s[1], shift), b.D = 2;
    } else if (n == 3) {
        const iv u = to_iv(s[1], shift) - A, v = to_iv(s[2], shift) - A, w = cross(u, v);
        b.D = 2 * dot(w, w);
        b.N = A * b.D + cross(v, w) * dot(u, u) + cross(w, u) * dot(v, v);
    } else {
        const iv u = to_iv(s[1], shift) - A, v = to_iv(s[2], shift) - A, w = to_iv(s[3], shift) - A;
        b.D = 2 * dot(u, cross(v, w));
        b.N = A * b.D + cross(v, w) * dot(u, u) + cross(w, u) * dot(v, v) + cross(u, v) * dot(w, w);
        if (b.D < 0) b.D = -b.D, b.N = {-b.N.x, -b.N.y, -b.N.z};
    }
    const iv e = A * b.D - b.N;
    b.R = dot(e, e);
    // within 2^-51 relative (ratio): the filter's centre; the result's centre is rounded to nearest
    b.cd = {ratio(b.N.x, b.D, shift), ratio(b.N.y, b.D, shift), ratio(b.N.z, b.D, shift)};
    const double m = std::max({std::abs(b.cd.x), std::abs(b.cd.y), std::abs(b.cd.z)});
    // radius = sqrt(R) / (D 2^shift), computed as sqrt(R / (D^2 2^(2 shift + 2k))) 2^k with k chosen
    // so the ratio is near 1: its square never over- or underflows (r^2 is out of range long before r).
    double r = 0.0;
    if (b.R != 0) {
        const int t = int(boost::multiprecision::msb(b.R)) - 2 * int(boost::multiprecision::msb(b.D)) - 2 * shift;
        const int k = t >= 0 ? t / 2 : -((-t + 1) / 2);
        r = std::ldexp(std::sqrt(ratio(b.R, b.D * b.D, 2 * shift + 2 * k)), k);
    }
    if (!is_finite(m) || !is_finite(r) || m > 0x1p900 || (r != 0 && (r < 0x1p-900 || r > 0x1p900))) return b;
    b.delta = m * 0x1p-48 + 0x1p-1000;
    b.r_lo = r * (1 - 0x1p-44), b.r_hi = r * (1 + 0x1p-44) + 0x1p-1000;
    b.filter = true;
    if (b.r_hi + b.delta < 0x1p400 && b.r_lo - b.delta > 0x1p-400) {
        const double lo = (b.r_lo - b.delta) * (1 - 0x1p-50), hi = (b.r_hi + b.delta) * (1 + 0x1p-50);
        b.in_sq = lo * lo * (1 - 0x1p-50), b.out_sq = hi * hi * (1 + 0x1p-50);
        const double lo3 = (b.r_lo - 3 * b.delta) * (1 - 0x1p-50);
        b.near_sq = lo3 > 0 ? lo3 * lo3 * (1 - 0x1p-50) : -1;
    }
    return b;
}

// Is p strictly outside the exact ball?
// Is |p - cd| < r_lo - k delta proven (so |p - c| < r_lo - (k - 1) delta: p is strictly inside
// the exact ball)? k = 1 or 3. Double only.
inline bool surely_inside(const ball& b, point3 p, int k = 1) {
    if (b.in_sq > 0) {
        // each difference within 1 ulp, the sum of squares within 3 ulps more: |d2 - |p - cd|^2| is
        // below 2^-49 d2 (plus 2^-1070 if it underflows).
        const vec3 q = p - b.cd;
        const double d2 = q.x * q.x + q.y * q.y + q.z * q.z;
        return d2 * (1 + 0x1p-45) + 0x1p-1070 < (k == 1 ? b.in_sq : b.near_sq);
    }
    if (!b.filter) return false;
    const double d = length(p - b.cd); // within 3 ulps of |p - cd| (no over/underflow of squares)
    return is_finite(d) && d > 0x1p-900 && d < 0x1p900 && d * (1 + 0x1p-45) + k * b.delta < b.r_lo;
}
// Is p strictly outside the exact ball?
inline bool outside(const ball& b, point3 p, int shift) {
    if (surely_inside(b, p)) return false;
    if (b.in_sq > 0) { // an infinite d2 means a huge distance
        const vec3 q = p - b.cd;
        if ((q.x * q.x + q.y * q.y + q.z * q.z) * (1 - 0x1p-45) > b.out_sq) return true;
    } else if (b.filter) {
        const double d = length(p - b.cd);
        if (is_finite(d) && d > 0x1p-900 && d < 0x1p900 && d * (1 - 0x1p-45) - b.delta > b.r_hi) return true;
    }
    const iv e = to_iv(p, shift) * b.D - b.N;
    return dot(e, e) > b.R;
}

struct solver {
    std::span<const point3> pts;
    int shift = 0;
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
            if (!have || outside(current, pts[i], shift)) {
                support[static_cast<unsigned>(n)] = pts[i], support_index[static_cast<unsigned>(n)] = i, ++n;
                current = through(support, n, shift);
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
// The exact minimum ball of a few points (at most `pivot_cap`), by move-to-front; `ids` are
// their indices in `points`. With `last_on_boundary`, the last point is known to be on the
// boundary (it lay outside the minimum ball of the others) and is kept as a support point from
// the start. Leaves the ball in `out`, the points exactly on its boundary in `boundary`, and the
// support set that defines it in `basis`.
inline void small_ball(std::span<const point3> points, std::span<const std::uint32_t> ids, int shift, bool last_on_boundary, ball& out,
                       std::vector<std::uint32_t>& boundary, std::vector<std::uint32_t>& basis) {
    std::array<point3, pivot_cap + 1> sub{};
    for (std::size_t k = 0; k < ids.size(); ++k) sub[k] = points[ids[k]];
    solver s;
    s.pts = std::span<const point3>(sub.data(), ids.size());
    s.shift = shift;
    const auto m = static_cast<std::uint32_t>(ids.size());
    const std::uint32_t listed = last_on_boundary ? m - 1 : m;
    s.next.resize(m), s.prev.resize(m);
    for (std::uint32_t k = 0; k < listed; ++k) s.next[k] = k + 1 < listed ? k + 1 : solver::none, s.prev[k] = k > 0 ? k - 1 : solver::none;
    if (last_on_boundary) {
        s.support[0] = sub[m - 1], s.support_index[0] = m - 1, s.n = 1;
        s.current = through(s.support, 1, shift), s.have = true;
        s.best_support = {m - 1};
    }
    if (listed > 0) {
        s.head = 0;
        s.mtf(solver::none);
    }
    out = s.current;
    boundary.clear();
    for (std::uint32_t k = 0; k < m; ++k) {
        const iv e = to_iv(sub[k], shift) * out.D - out.N;
        if (dot(e, e) == out.R) boundary.push_back(ids[k]);
    }
    basis.clear();
    for (std::uint32_t k : s.best_support) basis.push_back(ids[k]);
}
} // namespace welzl_detail

// Exact minimum enclosing sphere. `seed` fixes the shuffle of the fallback (the result does not
// depend on it). Main loop: Gaertner's pivoting (ESA 1999, section 3): keep the exact minimum ball
// of a small set S of points on its boundary; the point farthest outside it joins S, the ball of
// S is recomputed exactly and S shrinks to the points on its boundary. The radius grows strictly
// each round, so the loop ends, and the ball of S then contains every point: it is the minimum
// ball of all. Each round is one filtered pass over the points. Sets with many exactly cospherical
// points (S would outgrow `pivot_cap`) fall back to move-to-front over all points.
// `cap` (at most pivot_cap) bounds S; the tests use a small one to run the fallback.
namespace welzl_detail {
result<min_sphere> solve(std::span<const point3> points, std::uint64_t seed, std::size_t cap) {
    if (points.empty()) return error{errc::empty_input};
    for (const point3& p : points)
        if (!is_finite(p)) return error{errc::not_finite};
    const auto n = static_cast<std::uint32_t>(points.size());
    int emin = 1 << 20;
    for (const point3& p : points)
        for (double x : {p.x, p.y, p.z})
            if (x != 0.0) { // x = m 2^e with an integer m < 2^53: e = exponent - 52 (or -1074)
                const int e = std::max(arith::exponent_of(x) - 52, -1074);
                emin = e < emin ? e : emin;
            }
    const int shift = emin == (1 << 20) ? 0 : -emin; // every coordinate times 2^shift is an integer
    ball b;
    std::vector<std::uint32_t> S{0}, boundary, basis{0};
    std::vector<point3> near; // the points of the last pass not surely inside
    {                         // start from point 0 and the point farthest from it (the ranking only needs to be rough)
        std::uint32_t far = 0;
        double best = -1.0;
        for (std::uint32_t i = 0; i < n; ++i) {
            const vec3 q = points[i] - points[0];
            const double d = q.x * q.x + q.y * q.y + q.z * q.z;
            if (d > best) best = d, far = i;
        }
        if (far != 0) S.push_back(far);
        small_ball(points, S, shift, false, b, boundary, basis);
        S = boundary;
    }
    // Pivot rounds over every stride-th point (a sample: few exact balls, cheap passes), then over
    // all points (stride 1), which usually needs one or two rounds more.
    bool done = false, overflow = false;
    for (std::uint32_t stride : {n / 256 + 1, 1u}) {
        done = false;
        while (!done) {
            // the point farthest outside the ball (exact outside test; distance in double to rank)
            std::uint32_t pivot = solver::none;
            double far = -1.0;
            near.clear();
            overflow = false;
            for (std::uint32_t i = 0; i < n; i += stride) {
                if (surely_inside(b, points[i], 3)) continue;
                if (near.size() < 4096) near.push_back(points[i]);
                else overflow = true;
                if (surely_inside(b, points[i])) continue;
                if (!outside(b, points[i], shift)) continue;
                const vec3 q = points[i] - b.cd;
                const double d = q.x * q.x + q.y * q.y + q.z * q.z; // ranks the candidates only
                if (d > far || pivot == solver::none) far = d, pivot = i;
            }
            if (pivot == solver::none) {
                done = true;
                break;
            }
            S.push_back(pivot);
            if (S.size() > cap) break;
            small_ball(points, S, shift, true, b, boundary, basis);
            S = boundary;
        }
        if (!done) break;
    }
    if (done && overflow) near.assign(points.begin(), points.end());
    if (!done) { // many cospherical points: move-to-front over everything
        solver s;
        s.pts = points;
        s.shift = shift;
        s.next.resize(n), s.prev.resize(n);
        std::vector<std::uint32_t> order(n);
        for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
        std::mt19937_64 g(seed);
        for (std::uint32_t i = n - 1; i > 0; --i) std::swap(order[i], order[std::uniform_int_distribution<std::uint32_t>(0, i)(g)]);
        for (std::uint32_t k = 0; k < n; ++k) {
            s.next[order[k]] = k + 1 < n ? order[k + 1] : solver::none;
            s.prev[order[k]] = k > 0 ? order[k - 1] : solver::none;
        }
        s.head = order[0];
        s.mtf(solver::none);
        b = s.current;
        basis = s.best_support;
        near.assign(points.begin(), points.end());
    }
    // The support of the final ball: the points exactly on its boundary among its basis.
    std::vector<std::uint32_t> support;
    for (std::uint32_t i : basis) {
        const auto e = to_iv(points[i], shift) * b.D - b.N;
        if (dot(e, e) == b.R) support.push_back(i);
    }
    const point3 c{nearest(b.N.x, b.D, shift), nearest(b.N.y, b.D, shift), nearest(b.N.z, b.D, shift)};
    if (!is_finite(c)) return error{errc::out_of_range};
    const double r2 = nearest(b.R, b.D * b.D, shift * 2);
    // A point left out of `near` is within r_lo - 2 delta of the exact centre, so within r_lo - delta
    // of c (|c - exact centre| < delta); a support point is at least r_lo - delta from c, so the
    // radius enclosing `near` (support points included) encloses the others.
    const auto r = enclosing_radius(c, near);
    if (!r) return r.error();
    return min_sphere{sphere3{c, r.value()}, r2, support};
}

} // namespace welzl_detail

} // namespace incidence::bound
