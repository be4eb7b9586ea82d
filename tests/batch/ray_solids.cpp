// batch::intersects(ray, boxes or balls) and batch::intersects(rays, box or ball): on every SIMD
// target this processor has, each lane's answer equals the scalar intersects<Tier>(ray, box or
// ball) in all four tiers, for the array and the structure-of-arrays entry points: on rays and
// shapes that touch exactly (a ray through a box's corner, edge or face point, or lying in a face
// plane; a ray tangent to a ball, from integer vectors of integer length), a few ulps off, at
// scales 2^-500..2^500, and on special values (NaN, infinities, zero directions, inverted boxes,
// negative radii). The exact lanes are checked against the CGAL Epeck oracle.
// And batch::intersection(ray, boxes or balls), the first hit: its index against brute force over
// the scalar exact hits ordered by an independent computation of their entries (Boost
// multiprecision: a box's as an exact rational, a ball's root in 1,200-bit floats), on random
// shapes, on grids of boxes that the ray crosses at shared edges and corners, on balls whose
// entries tie exactly (Pythagorean directions), on rays that start inside, and on special values.
#include <catch2/catch_test_macros.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
#include "testkit/testing.hpp"
#include "testkit/simd_targets.hpp"
#include "testkit/sphere_points.hpp"
#include "testkit/batch_packets.hpp"
#include "testkit/generators.hpp"

namespace test_batch_ray_solids { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {

// One ray, box and ball, and many of each: the many rays aimed at the one box and ball, the many
// boxes and balls placed on the one ray.
struct ray_solid_set {
    ray3 ray;
    aabb3 box;
    sphere3 ball;
    std::vector<ray3> rays;
    std::vector<aabb3> boxes;
    std::vector<sphere3> balls;
};

ray_solid_set make_set(support::rng& r) {
    // an exact frame: axes permuted, scale 2^k, translation by a multiple of 2^k; nudges come after
    const int perm = r.integer(0, 2), k = r.integer(0, 3) == 0 ? r.integer(-500, 500) : 0;
    const double t[3] = {std::ldexp(r.integer(-64, 64), k), std::ldexp(r.integer(-64, 64), k), std::ldexp(r.integer(-64, 64), k)};
    auto axes = [perm](double x, double y, double z) {
        return perm == 0 ? std::array<double, 3>{x, y, z} : (perm == 1 ? std::array<double, 3>{z, x, y} : std::array<double, 3>{y, z, x});
    };
    auto at = [&](double x, double y, double z) {
        const auto q = axes(x, y, z);
        return point3{std::ldexp(q[0], k) + t[0], std::ldexp(q[1], k) + t[1], std::ldexp(q[2], k) + t[2]};
    };
    auto along = [&](double x, double y, double z) {
        const auto q = axes(x, y, z);
        return vec3{std::ldexp(q[0], k), std::ldexp(q[1], k), std::ldexp(q[2], k)};
    };
    auto length = [&](double x) { return std::ldexp(x, k); };
    auto nudged = [&](point3 p) {
        return point3{support::nudge(p.x, r.integer(-2, 2)), support::nudge(p.y, r.integer(-2, 2)), support::nudge(p.z, r.integer(-2, 2))};
    };
    ray_solid_set s;
    // The one box [-4, 5] x [-3, 6] x [-2, 7]; the one ball centre 0, radius w of a quadruple.
    const double lo[3] = {-4, -3, -2}, hi[3] = {5, 6, 7};
    s.box = aabb3{at(lo[0], lo[1], lo[2]), at(hi[0], hi[1], hi[2])};
    const support::quad q0 = support::pythagorean(r);
    s.ball = sphere3{at(0, 0, 0), length(q0.w)};
    // The one ray: direction (a, b, 0) of a quadruple (a, b, c) so that w = (-b, a, c) is
    // orthogonal to it with integer length; a zero or axis-parallel direction now and then.
    const support::quad q = support::pythagorean(r);
    double dir[3] = {q.x, q.y, 0};
    if (r.integer(0, 7) == 0) dir[1] = 0;
    if (r.integer(0, 31) == 0) dir[0] = dir[1] = 0;
    const double o[3] = {static_cast<double>(r.integer(-8, 8)), static_cast<double>(r.integer(-8, 8)),
                         static_cast<double>(r.integer(-8, 8))};
    s.ray = ray3{at(o[0], o[1], o[2]), along(dir[0], dir[1], dir[2])};
    const int n = 2 * r.integer(20, 60) + 1;
    for (int i = 0; i < n; ++i) {
        // a box with a corner, edge or face point at o + j dir (j may be negative: behind the origin)
        const int j = r.integer(-2, 4);
        const double p[3] = {o[0] + j * dir[0], o[1] + j * dir[1], o[2] + j * dir[2]};
        double bmin[3], bmax[3];
        for (int a = 0; a < 3; ++a) {
            const int side = r.integer(0, 2); // p on the lower face, the upper face, or inside on this axis
            const double e = r.integer(0, 3);
            bmin[a] = side == 0 ? p[a] : p[a] - e - (side == 2 ? 1 : 0);
            bmax[a] = side == 1 ? p[a] : p[a] + e + (side == 2 ? 1 : 0);
        }
        aabb3 b{at(bmin[0], bmin[1], bmin[2]), at(bmax[0], bmax[1], bmax[2])};
        // a ball tangent to the ray's line at o + j dir: centre p + m w, radius m |w|
        const int m = r.integer(1, 2);
        const double w[3] = {-dir[1], dir[0], q.z};
        const double wl = dir[0] == q.x && dir[1] == q.y ? q.w : -1; // the length is known for (a, b, 0)
        sphere3 ball{at(p[0] + m * w[0], p[1] + m * w[1], p[2] + m * w[2]), wl > 0 ? length(m * wl) : length(r.integer(1, 4))};
        // a ray at a point of the box's boundary (a corner, an edge or a face point), or lying in a
        // face plane; or tangent to the ball at an integer point x of it, along x times an axis
        ray3 ray;
        if (r.coin()) {
            double target[3];
            for (int a = 0; a < 3; ++a)
                target[a] = r.coin() ? (r.coin() ? lo[a] : hi[a]) : r.integer(static_cast<int>(lo[a]), static_cast<int>(hi[a]));
            double from[3] = {static_cast<double>(r.integer(-12, 12)), static_cast<double>(r.integer(-12, 12)),
                              static_cast<double>(r.integer(-12, 12))};
            if (r.integer(0, 3) == 0) from[0] = target[0] = r.coin() ? lo[0] : hi[0]; // in a face plane
            ray = ray3{at(from[0], from[1], from[2]), along(target[0] - from[0], target[1] - from[1], target[2] - from[2])};
        } else {
            const double x[3] = {q0.x, q0.y, q0.z};
            const int axis = r.integer(0, 2);
            double e[3] = {0, 0, 0};
            e[axis] = 1;
            const double u[3] = {x[1] * e[2] - x[2] * e[1], x[2] * e[0] - x[0] * e[2], x[0] * e[1] - x[1] * e[0]};
            const int back = r.integer(-1, 3);
            ray = ray3{at(x[0] - back * u[0], x[1] - back * u[1], x[2] - back * u[2]), along(u[0], u[1], u[2])};
        }
        if (r.integer(0, 5) == 0) b = aabb3{nudged(b.min), nudged(b.max)};
        if (r.integer(0, 5) == 0) ball = sphere3{nudged(ball.center), support::nudge(ball.radius, r.integer(-2, 2))};
        if (r.integer(0, 5) == 0) ray.origin = nudged(ray.origin);
        s.boxes.push_back(b);
        s.balls.push_back(ball);
        s.rays.push_back(ray);
    }
    return s;
}

ray_solid_set special_set(support::rng& r) {
    auto pick = [&] { return support::special_or_uniform(r); };
    auto point = [&] { return point3{pick(), pick(), pick()}; };
    ray_solid_set s;
    s.ray = r.coin() ? ray3{point(), vec3{pick(), pick(), pick()}} : ray3{{0, 0, 0}, {1, 1, 1}};
    s.box = r.coin() ? aabb3{point(), point()} : aabb3{{-1, -1, -1}, {1, 1, 1}};
    s.ball = r.coin() ? sphere3{point(), pick()} : sphere3{{0, 0, 0}, 1};
    for (int i = 0; i < 37; ++i) {
        s.rays.push_back(ray3{point(), vec3{pick(), pick(), pick()}});
        s.boxes.push_back(aabb3{point(), point()});
        s.balls.push_back(sphere3{point(), pick()});
    }
    return s;
}

struct counts {
    long lanes = 0, wrong = 0;
};

std::vector<double> fields(const std::vector<ray3>& v, int k) {
    std::vector<double> out;
    for (const ray3& x : v) {
        const double f[6] = {x.origin.x, x.origin.y, x.origin.z, x.direction.x, x.direction.y, x.direction.z};
        out.push_back(f[k]);
    }
    return out;
}
std::vector<double> fields(const std::vector<aabb3>& v, int k) {
    std::vector<double> out;
    for (const aabb3& x : v) {
        const double f[6] = {x.min.x, x.min.y, x.min.z, x.max.x, x.max.y, x.max.z};
        out.push_back(f[k]);
    }
    return out;
}
std::vector<double> fields(const std::vector<sphere3>& v, int k) {
    std::vector<double> out;
    for (const sphere3& x : v) {
        const double f[4] = {x.center.x, x.center.y, x.center.z, x.radius};
        out.push_back(f[k]);
    }
    return out;
}

// The many's structure-of-arrays view over f (the fields' copies).
auto soa_view(const std::vector<ray3>&, const std::vector<double>* f) { return batch::rays_soa{f[0], f[1], f[2], f[3], f[4], f[5]}; }
auto soa_view(const std::vector<aabb3>&, const std::vector<double>* f) { return batch::boxes_soa{f[0], f[1], f[2], f[3], f[4], f[5]}; }
auto soa_view(const std::vector<sphere3>&, const std::vector<double>* f) { return batch::spheres_soa{f[0], f[1], f[2], f[3]}; }

// `one` against `many` in both entry points, every lane against the scalar query (ray first).
template <class Tier, class One, class Many>
void compare(const One& one, const std::vector<Many>& many, counts& c, const std::string& where) {
    const std::size_t n = many.size();
    std::vector<std::uint8_t> aos(n, 7), soa(n, 7);
    std::vector<double> f[6];
    for (int k = 0; k < (std::is_same_v<Many, sphere3> ? 4 : 6); ++k) f[k] = fields(many, k);
    auto call = [&](const auto& m, std::span<std::uint8_t> out) {
        if constexpr (std::is_same_v<One, ray3>) return batch::intersects<Tier>(one, m, out);
        else return batch::intersects<Tier>(m, one, out);
    };
    const auto ra = call(std::span<const Many>(many), aos);
    const auto rs = call(soa_view(many, f), soa);
    REQUIRE(ra.has_value());
    REQUIRE(rs.has_value());
    std::size_t met = 0;
    for (std::size_t i = 0; i < n; ++i) {
        std::uint8_t scalar;
        if constexpr (std::is_same_v<One, ray3>) scalar = intersects<Tier>(one, many[i]) ? 1 : 0;
        else scalar = intersects<Tier>(many[i], one) ? 1 : 0;
        met += scalar;
        ++c.lanes;
        if ((aos[i] != scalar || soa[i] != scalar) && ++c.wrong <= 5)
            std::printf("  %s lane %zu: scalar %d, batch %d (array) %d (soa)\n", where.c_str(), i, scalar, aos[i], soa[i]);
    }
    if (ra.value() != met || rs.value() != met) ++c.wrong;
}

template <class One, class Many>
void every_tier(const One& one, const std::vector<Many>& many, counts* c, const std::string& where) {
    compare<exact>(one, many, c[0], where + ", exact");
    compare<conservative>(one, many, c[1], where + ", conservative");
    compare<aggressive>(one, many, c[2], where + ", aggressive");
    compare<approximate>(one, many, c[3], where + ", approximate");
}

template <class Make>
void every_pair_on_every_target(const char* name, long sets, Make make) {
    counts pairs[4][4]; // ray-boxes, ray-balls, rays-box, rays-ball; per tier
    const int targets = support::on_every_target(name, [&](support::rng& r, const std::string& where, const char*) {
        for (long k = 0; k < sets; ++k) {
            const ray_solid_set s = make(r);
            every_tier(s.ray, s.boxes, pairs[0], where + ", ray against boxes");
            every_tier(s.ray, s.balls, pairs[1], where + ", ray against balls");
            every_tier(s.box, s.rays, pairs[2], where + ", rays against a box");
            every_tier(s.ball, s.rays, pairs[3], where + ", rays against a ball");
        }
    });
    const char* names[4] = {"ray-boxes", "ray-balls", "rays-box", "rays-ball"};
    for (int p = 0; p < 4; ++p)
        std::printf("[cases] batch ray_solids %s, %s: %d SIMD targets, %ld lanes per tier; lanes unlike the scalar answer %ld %ld %ld %ld "
                    "(exact, conservative, aggressive, approximate)\n",
                    name, names[p], targets, pairs[p][0].lanes, pairs[p][0].wrong, pairs[p][1].wrong, pairs[p][2].wrong, pairs[p][3].wrong);
    CHECK(targets >= 2);
    for (int p = 0; p < 4; ++p)
        for (int t = 0; t < 4; ++t) CHECK(pairs[p][t].wrong == 0);
}

// --- the first hit -------------------------------------------------------------------------------

namespace mp = boost::multiprecision;
using rational = mp::cpp_rational;
using wide = mp::number<mp::cpp_bin_float<1200, mp::digit_base_2>>;

// The exact entry of a ray into a box it meets, max(0, (near_k - o_k) / d_k), as a rational; and
// into a ball it meets, max(0, t1), t1 = c / (-b + sqrt(b^2 - a c)) when c > 0 and b < 0 (the form
// without cancellation), from exact coefficients, in 1,200-bit floats.
wide entry_of(const ray3& r, const aabb3& b) {
    const double o[3] = {r.origin.x, r.origin.y, r.origin.z}, d[3] = {r.direction.x, r.direction.y, r.direction.z};
    const double lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
    rational best = 0;
    for (int k = 0; k < 3; ++k)
        if (d[k] != 0) best = std::max(best, (rational(d[k] > 0 ? lo[k] : hi[k]) - rational(o[k])) / rational(d[k]));
    return wide(mp::numerator(best)) / wide(mp::denominator(best));
}
wide entry_of(const ray3& r, const sphere3& s) {
    const rational m[3] = {rational(r.origin.x) - rational(s.center.x), rational(r.origin.y) - rational(s.center.y),
                           rational(r.origin.z) - rational(s.center.z)};
    const rational D[3] = {rational(r.direction.x), rational(r.direction.y), rational(r.direction.z)};
    const rational a = D[0] * D[0] + D[1] * D[1] + D[2] * D[2], b = m[0] * D[0] + m[1] * D[1] + m[2] * D[2];
    const rational c = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] - rational(s.radius) * rational(s.radius);
    if (!(c > 0 && b < 0)) return 0;
    auto to_wide = [](const rational& x) { return wide(mp::numerator(x)) / wide(mp::denominator(x)); };
    return to_wide(c) / (to_wide(-b) + mp::sqrt(to_wide(b * b - a * c)));
}
// Two entries are the same where they agree to 2^-1000 relative (their float error is below
// 2^-1150; distinct entries of double inputs lie much further apart).
bool same_entry(const wide& t, const wide& u) { return mp::abs(t - u) <= mp::ldexp(mp::abs(t) + mp::abs(u), -1000); }
// The index of the first hit by brute force: the scalar exact hits, least entry, ties to the least
// index; -1 for none.
template <class Solid>
long first_by_brute_force(const ray3& r, const std::vector<Solid>& many) {
    long best = -1;
    wide t_best = 0;
    for (std::size_t i = 0; i < many.size(); ++i) {
        if (!intersects<exact>(r, many[i])) continue;
        const wide t = entry_of(r, many[i]);
        if (best < 0 || (t < t_best && !same_entry(t, t_best))) best = static_cast<long>(i), t_best = t;
    }
    return best;
}

struct first_set {
    ray3 ray;
    std::vector<aabb3> boxes;
    std::vector<sphere3> balls;
};
// kind 0: random boxes and balls (some large, around the origin); 1: a grid of unit boxes in a
// random order, the ray from an integer point along an integer direction (it crosses the boxes at
// shared faces, edges and corners: ties), and balls on the ray's line, centred at o + t_c d with
// radius rho |d| (|d| from a Pythagorean quadruple), so the entry is t_c - rho exactly and several
// tie; balls repeated, concentric, and around the origin (entry 0); a third of the balls' radii and
// a fifth of the boxes' lower corners a few ulps off (entries apart by less than the enclosures'
// width, which the exact comparison orders). All at 2^k.
first_set make_first_set(support::rng& r, int kind) {
    first_set s;
    if (kind == 0) {
        s.ray = ray3{{r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-2, 2)}, {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}};
        const int n = r.integer(1, 200);
        for (int i = 0; i < n; ++i) {
            const point3 c = r.integer(0, 19) == 0 ? s.ray.origin : point3{r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-2, 2)};
            const double e = r.uniform(0, r.integer(0, 9) == 0 ? 2.0 : 0.5);
            s.boxes.push_back(aabb3{{c.x - e, c.y - r.uniform(0, e), c.z - e}, {c.x + r.uniform(0, e), c.y + e, c.z + e}});
            s.balls.push_back(sphere3{c, e});
        }
    } else {
        const auto q = support::pythagorean(r);
        const point3 o{double(r.integer(-2, 6)), double(r.integer(-2, 6)), double(r.integer(-2, 6))};
        s.ray = ray3{o, vec3{q.x, q.y, q.z}};
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j)
                for (int k = 0; k < 5; ++k) s.boxes.push_back(aabb3{{double(i), double(j), double(k)}, {i + 1.0, j + 1.0, k + 1.0}});
        for (std::size_t i = s.boxes.size(); i > 1; --i)
            std::swap(s.boxes[i - 1], s.boxes[static_cast<std::size_t>(r.integer(0, static_cast<int>(i) - 1))]);
        s.boxes.resize(static_cast<std::size_t>(r.integer(1, 125)));
        const int n = r.integer(1, 60);
        const bool inside = r.integer(0, 3) == 0; // a quarter of the sets: balls around the origin too
        for (int i = 0; i < n; ++i) {
            int how = r.integer(0, 5);
            if (how == 1 && !inside) how = 2;
            if (how == 0 && !s.balls.empty()) { // a repeat
                s.balls.push_back(s.balls[static_cast<std::size_t>(r.integer(0, static_cast<int>(s.balls.size()) - 1))]);
            } else if (how == 1) { // around the origin: entered at 0
                s.balls.push_back(sphere3{{o.x + r.integer(-1, 1), o.y + r.integer(-1, 1), o.z}, q.w * r.integer(1, 3) + 2.0});
            } else { // on the line: centre o + t_c d, radius rho |d|, entry t_c - rho
                const double tc = r.integer(2, 12), rho = r.integer(1, 2) * (r.coin() ? 1.0 : 0.5);
                s.balls.push_back(sphere3{{o.x + tc * q.x, o.y + tc * q.y, o.z + tc * q.z}, rho * q.w});
            }
            if (r.integer(0, 2) == 0) // a few ulps larger or smaller: entries apart by less than the enclosures' width
                s.balls.back().radius = support::nudge(s.balls.back().radius, r.coin() ? r.integer(1, 3) : -r.integer(1, 3));
        }
        for (aabb3& b : s.boxes)
            if (r.integer(0, 4) == 0)
                b.min = {support::nudge(b.min.x, r.integer(-2, 2)), support::nudge(b.min.y, r.integer(-2, 2)), b.min.z};
    }
    if (r.integer(0, 2) == 0) {
        const int k = r.integer(-400, 400);
        s.ray = ray3{{std::ldexp(s.ray.origin.x, k), std::ldexp(s.ray.origin.y, k), std::ldexp(s.ray.origin.z, k)}, s.ray.direction};
        for (aabb3& b : s.boxes) b = audit::scaled(b, k);
        for (sphere3& b : s.balls)
            b = sphere3{{std::ldexp(b.center.x, k), std::ldexp(b.center.y, k), std::ldexp(b.center.z, k)}, std::ldexp(b.radius, k)};
    }
    return s;
}
first_set special_first_set(support::rng& r) {
    first_set s = make_first_set(r, r.integer(0, 1));
    auto pick = [&] { return support::special_or_uniform(r); };
    if (r.integer(0, 3) == 0) s.ray = ray3{{pick(), pick(), pick()}, {pick(), pick(), pick()}};
    for (aabb3& b : s.boxes)
        if (r.integer(0, 3) == 0) b = r.coin() ? aabb3{{pick(), pick(), pick()}, {pick(), pick(), pick()}} : aabb3{b.max, b.min};
    for (sphere3& b : s.balls)
        if (r.integer(0, 3) == 0) b = sphere3{{pick(), b.center.y, pick()}, r.coin() ? pick() : -b.radius};
    return s;
}

struct first_counts {
    long sets = 0, hits = 0, ties = 0, wrong = 0, approximate_elsewhere = 0;
};

template <class Solid>
void check_first(const ray3& ray, const std::vector<Solid>& many, first_counts& c, const std::string& where) {
    const long truth = first_by_brute_force(ray, many);
    const support::packet<Solid> copy(many);
    ++c.sets;
    c.hits += truth >= 0;
    if (truth >= 0) { // a tie: another hit at the same entry
        const wide t = entry_of(ray, many[static_cast<std::size_t>(truth)]);
        for (std::size_t i = static_cast<std::size_t>(truth) + 1; i < many.size(); ++i)
            if (intersects<exact>(ray, many[i]) && same_entry(entry_of(ray, many[i]), t)) {
                ++c.ties;
                break;
            }
    }
    auto report = [&](const char* tier, long got) {
        if (++c.wrong <= 5) std::printf("  %s, %s: first hit %ld, brute force %ld\n", where.c_str(), tier, got, truth);
    };
    auto index_of = [](const auto& h) { return h ? static_cast<long>(h->index) : -1L; };
    const auto e = batch::intersection<exact>(ray, std::span<const Solid>(many));
    const auto ep = batch::intersection<exact>(ray, copy.view());
    REQUIRE((e.has_value() && ep.has_value()));
    if (index_of(e.value()) != truth || index_of(ep.value()) != truth) report("exact", index_of(e.value()));
    if (truth >= 0 && e.value()) {
        const auto scalar = intersection<exact>(ray, many[static_cast<std::size_t>(truth)]);
        const auto& h = *e.value();
        if (!scalar || h.t_enter != scalar->t_enter || h.t_exit != scalar->t_exit || !(h.point == scalar->point) ||
            h.exists != certainty::yes)
            report("exact values", index_of(e.value()));
    }
    auto enclosed = [&](const auto& h) {
        const auto& x = *e.value();
        return h.t_enter.contains(x.t_enter) && h.t_exit.contains(x.t_exit) && h.exists == certainty::yes;
    };
    const auto cv = batch::intersection<conservative>(ray, std::span<const Solid>(many));
    const auto ag = batch::intersection<aggressive>(ray, copy.view());
    REQUIRE((cv.has_value() && ag.has_value()));
    if (index_of(cv.value()) != truth || (cv.value() && !enclosed(*cv.value()))) report("conservative", index_of(cv.value()));
    if (index_of(ag.value()) != truth || (ag.value() && !enclosed(*ag.value()))) report("aggressive", index_of(ag.value()));
    // approximate: the least plain-double entry among the plain-double hits, ties to the least index
    long plain = -1;
    double t_plain = 0;
    for (std::size_t i = 0; i < many.size(); ++i)
        if (intersects<approximate>(ray, many[i]))
            if (const auto h = intersection<approximate>(ray, many[i]); h && (plain < 0 || h->t_enter < t_plain))
                plain = static_cast<long>(i), t_plain = h->t_enter;
    const auto ap = batch::intersection<approximate>(ray, std::span<const Solid>(many));
    REQUIRE(ap.has_value());
    if (index_of(ap.value()) != plain || (ap.value() && ap.value()->exists != certainty::uncertain))
        report("approximate", index_of(ap.value()));
    c.approximate_elsewhere += plain != truth;
}

template <class Make>
void first_hits_on_every_target(const char* name, long sets, Make make) {
    first_counts boxes, balls;
    const int targets = support::on_every_target(name, [&](support::rng& r, const std::string& where, const char*) {
        for (long k = 0; k < sets; ++k) {
            const first_set s = make(r, static_cast<int>(k % 2));
            check_first(s.ray, s.boxes, boxes, where + ", boxes");
            check_first(s.ray, s.balls, balls, where + ", balls");
        }
    });
    for (const auto& [what, c] : {std::pair{"boxes", boxes}, std::pair{"balls", balls}})
        std::printf("[cases] batch first hit %s, %s: %d SIMD targets, %ld rays, %ld with a hit, %ld of them tied at the first entry; "
                    "unlike brute force: %ld; approximate elsewhere than exact: %ld\n",
                    name, what, targets, c.sets, c.hits, c.ties, c.wrong, c.approximate_elsewhere);
    CHECK(targets >= 2);
    CHECK(boxes.wrong == 0);
    CHECK(balls.wrong == 0);
    return;
}

} // namespace

TEST_CASE("batch ray_solids: the first hit among boxes and balls is brute force's, random, grids and ties, every target", "[batch]") {
    first_hits_on_every_target("random and tied", support::cases(100), make_first_set);
}

TEST_CASE("batch ray_solids: the first hit among boxes and balls, special values, every target", "[batch]") {
    first_hits_on_every_target("special", support::cases(100), [](support::rng& r, int) { return special_first_set(r); });
}

TEST_CASE("batch ray_solids: every lane is the scalar answer, touching rays, boxes and balls, every target", "[batch]") {
    every_pair_on_every_target("touching", support::cases(300), make_set);
}

TEST_CASE("batch ray_solids: every lane is the scalar answer, special values, every target", "[batch]") {
    every_pair_on_every_target("special", support::cases(300), special_set);
}

TEST_CASE("batch ray_solids: the exact lanes against the CGAL Epeck oracle", "[batch]") {
    support::rng r(support::seed());
    long lanes[2] = {}, wrong[2] = {}, met[2] = {}, skipped = 0;
    for (long k = 0; k < support::cases(600); ++k) {
        const ray_solid_set s = make_set(r);
        std::vector<std::uint8_t> boxes(s.boxes.size()), balls(s.balls.size()), by_box(s.rays.size()), by_ball(s.rays.size());
        REQUIRE(batch::intersects<exact>(s.ray, std::span<const aabb3>(s.boxes), boxes).has_value());
        REQUIRE(batch::intersects<exact>(s.ray, std::span<const sphere3>(s.balls), balls).has_value());
        REQUIRE(batch::intersects<exact>(std::span<const ray3>(s.rays), s.box, by_box).has_value());
        REQUIRE(batch::intersects<exact>(std::span<const ray3>(s.rays), s.ball, by_ball).has_value());
        auto check = [&](int kind, const ray3& ray, const auto& solid, std::uint8_t answer) {
            double o[3], d[3];
            support::arr(ray.origin, o);
            support::arr(ray.direction, d);
            if (ray.direction == vec3{0, 0, 0}) { // the oracle's ray needs a direction
                ++skipped;
                return;
            }
            bool truth;
            if constexpr (std::is_same_v<std::decay_t<decltype(solid)>, aabb3>) {
                double mn[3], mx[3];
                support::arr(solid.min, mn);
                support::arr(solid.max, mx);
                // a nudge can invert a flat box: an empty set here (CGAL's Iso_cuboid_3 would reorder it)
                const bool inverted = mn[0] > mx[0] || mn[1] > mx[1] || mn[2] > mx[2];
                truth = !inverted && oracle::ray_box(o, d, mn, mx);
            } else {
                double c[3];
                support::arr(solid.center, c);
                truth = oracle::ray_ball(o, d, c, solid.radius);
            }
            ++lanes[kind];
            met[kind] += answer;
            if ((answer == 1) != truth) ++wrong[kind];
        };
        for (std::size_t i = 0; i < s.boxes.size(); ++i) check(0, s.ray, s.boxes[i], boxes[i]);
        for (std::size_t i = 0; i < s.balls.size(); ++i) check(1, s.ray, s.balls[i], balls[i]);
        for (std::size_t i = 0; i < s.rays.size(); ++i) check(0, s.rays[i], s.box, by_box[i]);
        for (std::size_t i = 0; i < s.rays.size(); ++i) check(1, s.rays[i], s.ball, by_ball[i]);
    }
    std::printf("[cases] batch ray_solids exact against the oracle: boxes %ld lanes (%ld met), %ld wrong; balls %ld lanes (%ld met), %ld "
                "wrong; %ld lanes with a zero direction left to the scalar tests\n",
                lanes[0], met[0], wrong[0], lanes[1], met[1], wrong[1], skipped);
    CHECK(wrong[0] == 0);
    CHECK(wrong[1] == 0);
    CHECK((met[0] * 5 > lanes[0] && met[1] * 5 > lanes[1])); // the sets are mostly touching, not missing
}

TEST_CASE("batch ray_solids: sizes", "[batch]") {
    const ray3 ray{{0, 0, -5}, {0, 0, 1}};
    const std::vector<aabb3> boxes(3, aabb3{{-1, -1, -1}, {1, 1, 1}});
    const std::vector<ray3> rays(3, ray);
    std::vector<std::uint8_t> out(2);
    const auto refused = batch::intersects<exact>(ray, std::span<const aabb3>(boxes), out);
    REQUIRE(refused.has_error());
    CHECK(refused.error().code == errc::size_mismatch);
    const auto refused_rays = batch::intersects<exact>(std::span<const ray3>(rays), sphere3{{0, 0, 0}, 1}, out);
    REQUIRE(refused_rays.has_error());
    out.resize(3);
    const auto all = batch::intersects<exact>(std::span<const ray3>(rays), boxes[0], out);
    REQUIRE(all.has_value());
    CHECK(all.value() == 3);
    const std::vector<double> x{0.0, 1.0}, y{1.0};
    const auto bad = batch::intersection<exact>(ray, batch::spheres_soa{x, x, x, y});
    REQUIRE(bad.has_error());
    CHECK(bad.error().code == errc::size_mismatch);
    const auto first = batch::intersection<exact>(ray, std::span<const aabb3>(boxes)); // three equal boxes: the first
    REQUIRE((first.has_value() && first.value().has_value()));
    CHECK(first.value()->index == 0);
    CHECK(first.value()->t_enter == 4.0);
    const auto none = batch::intersection<exact>(ray3{{5, 5, 5}, {1, 0, 0}}, std::span<const aabb3>(boxes));
    REQUIRE(none.has_value());
    CHECK(!none.value().has_value());
}

} // namespace test_batch_ray_solids
