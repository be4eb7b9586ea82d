// batch::intersects(frustum, boxes) and (boxes, frustum), boxes axis-aligned or oriented: on every
// SIMD target this processor has,
// each lane's answer equals the scalar intersects<Tier>(frustum, boxes[i]) in all four tiers, for
// the array and the structure-of-arrays entry points in both argument orders, on camera frustums
// (frustum3::from_camera) with random boxes, on integer frustums (corners integers) with boxes
// whose corner lies on a frustum corner, edge or face (touching, crossing, or beyond it) and a few
// ulps off, at scales 2^-500..2^500, and on special values (NaN, infinities, inverted boxes,
// non-finite planes); oriented boxes the same way (random rotations around a camera's view; exact
// frames whose corner, edge or face point is on the integer frustum's boundary; special numbers
// and negative extents); balls the same way (around a camera's view; tangent to a small-integer
// frustum's corners, edges and faces, exactly or within ulps; special numbers and negative radii).
// The near-degenerate lanes are counted: those whose filter verdict is
// uncertain (the batch must leave them to the scalar query).
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/generators.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/simd_targets.hpp"
#include "testkit/batch_packets.hpp"
#include "testkit/ball_halfspace_cases.hpp"

namespace test_batch_culling { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::batch_fields;
using support::packet;

namespace {

// The number of shapes in a set: 1 to `most`, or 1 to 16 where the cases are scaled down (the
// sanitizer build, whose scalar exact queries on the open lanes are slow at -O0).
int set_size(support::rng& r, int most) { return r.integer(1, static_cast<int>(std::max(16L, support::cases(100L * most) / 100))); }

template <class Box = aabb3>
struct culling_set {
    frustum3 frustum;
    std::vector<Box> boxes;
};

// A perspective camera anywhere in [-100, 100]^3, and the box around its corners (lo, hi).
frustum3 camera(support::rng& r, point3& lo, point3& hi) {
    frustum3 f;
    for (;;) {
        const point3 eye{r.uniform(-100, 100), r.uniform(-100, 100), r.uniform(-100, 100)};
        const vec3 forward{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}, up{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
        const double near = r.uniform(0.1, 5);
        const auto made = frustum3::from_camera(eye, forward, up, r.uniform(0.2, 2.5), r.uniform(0.5, 2), near, near + r.uniform(5, 200));
        if (!made.has_value()) continue;
        f = made.value();
        break;
    }
    point3 corner[8];
    REQUIRE(detail::frustum_corners(f, corner));
    lo = corner[0], hi = corner[0];
    for (const point3& c : corner)
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)},
        hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    return f;
}

// A camera and boxes around what it sees.
culling_set<> camera_set(support::rng& r) {
    culling_set s;
    point3 lo, hi;
    s.frustum = camera(r, lo, hi);
    const double size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const int n = set_size(r, 200);
    for (int i = 0; i < n; ++i) {
        double a[3], e[3];
        const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
        for (int k = 0; k < 3; ++k) a[k] = r.uniform(l[k] - 0.2 * size, h[k] + 0.2 * size), e[k] = r.uniform(0, 0.1 * size);
        s.boxes.push_back(aabb3{{a[0], a[1], a[2]}, {a[0] + e[0], a[1] + e[1], a[2] + e[2]}});
    }
    return s;
}

// A camera and oriented boxes around what it sees (random rotations, extents up to a tenth of the
// view's size).
culling_set<obb3> camera_obb_set(support::rng& r) {
    culling_set<obb3> s;
    point3 lo, hi;
    s.frustum = camera(r, lo, hi);
    const double size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const int n = set_size(r, 200);
    for (int i = 0; i < n; ++i) {
        const point3 c{r.uniform(lo.x - 0.2 * size, hi.x + 0.2 * size), r.uniform(lo.y - 0.2 * size, hi.y + 0.2 * size),
                       r.uniform(lo.z - 0.2 * size, hi.z + 0.2 * size)};
        s.boxes.push_back(
            obb3{c, support::random_frame(r), {r.uniform(0, 0.05 * size), r.uniform(0, 0.05 * size), r.uniform(0, 0.05 * size)}});
    }
    return s;
}

// A point of the integer frustum's boundary: one of its corners, an edge's midpoint or a face's
// centre (exact: integers over 1, 2 or 4).
point3 frustum_boundary_point(support::rng& r, const point3* corner) {
    // corners on plane P: bit P / 2 of the corner index equal to P % 2
    const int plane = r.integer(0, 5), bit = plane / 2, value = plane % 2, take = 1 << r.integer(0, 2);
    int on[4], count = 0;
    for (int m = 0; m < 8; ++m)
        if (((m >> bit) & 1) == value) on[count++] = m;
    const int first = r.integer(0, 3);
    vec3 sum{0, 0, 0};
    for (int j = 0; j < take; ++j) sum = sum + (corner[on[(first + j) % 4]] - point3{0, 0, 0});
    return point3{0, 0, 0} + sum * (1.0 / take);
}

// An integer frustum (audit::touching_frustum: integer corners) and boxes with a corner at one of
// its corners, edge midpoints or face centres, reaching any way by integer extents (so touching
// it, crossing it or beyond it), a quarter of them a few ulps off; then the whole set at 2^k. At
// most 64 boxes: most of them go to the scalar query's linear program, slow in the sanitizer build.
culling_set<> touching_set(support::rng& r) {
    culling_set s;
    s.frustum = audit::touching_frustum(r).shape;
    point3 corner[8];
    REQUIRE(detail::frustum_corners(s.frustum, corner));
    const int n = set_size(r, 64);
    for (int i = 0; i < n; ++i) {
        const point3 p = frustum_boundary_point(r, corner);
        double a[3] = {p.x, p.y, p.z}, b[3] = {p.x, p.y, p.z};
        for (int k = 0; k < 3; ++k) {
            const double e = r.integer(0, 3) == 0 ? 0.0 : r.integer(1, 40);
            if (r.coin()) b[k] += e;
            else a[k] -= e;
        }
        aabb3 box{{a[0], a[1], a[2]}, {b[0], b[1], b[2]}};
        if (r.integer(0, 3) == 0)
            box = aabb3{{support::nudge(box.min.x, r.integer(-3, 3)), support::nudge(box.min.y, r.integer(-3, 3)), box.min.z},
                        {box.max.x, support::nudge(box.max.y, r.integer(-3, 3)), support::nudge(box.max.z, r.integer(-3, 3))}};
        s.boxes.push_back(box);
    }
    if (r.integer(0, 2) == 0) { // scale 2^k: planes by their offsets, boxes by their bounds
        const int k = r.integer(-500, 500);
        s.frustum = audit::scaled(s.frustum, k);
        for (aabb3& b : s.boxes)
            b = aabb3{{std::ldexp(b.min.x, k), std::ldexp(b.min.y, k), std::ldexp(b.min.z, k)},
                      {std::ldexp(b.max.x, k), std::ldexp(b.max.y, k), std::ldexp(b.max.z, k)}};
    }
    return s;
}

// The integer frustum and oriented boxes (support::near_obb: signed-permutation, dyadic
// near-rotation or small-integer skew axes, dyadic extents, some zero) whose corner, edge or face
// point lies on one of its corners, edge midpoints or face centres (a third of them rotated by a
// random rotation instead, so that the point is there up to rounding), a quarter of them with the
// centre a few ulps off; then the whole set at 2^k.
culling_set<obb3> touching_obb_set(support::rng& r) {
    culling_set<obb3> s;
    s.frustum = audit::touching_frustum(r).shape;
    point3 corner[8];
    REQUIRE(detail::frustum_corners(s.frustum, corner));
    const int n = set_size(r, 64);
    for (int i = 0; i < n; ++i) {
        const point3 p = frustum_boundary_point(r, corner);
        obb3 b = support::near_obb(r);
        for (double& h : b.half_extents) h *= 8;
        if (r.integer(0, 2) == 0) b.axes = support::random_frame(r); // a rotation: the point below is at p only to rounding
        b.center = p + (b.center - support::boundary_point(r, b));   // else exact: dyadics of small size
        if (r.integer(0, 3) == 0)
            b.center = {support::nudge(b.center.x, r.integer(-3, 3)), support::nudge(b.center.y, r.integer(-3, 3)), b.center.z};
        s.boxes.push_back(b);
    }
    if (r.integer(0, 2) == 0) {
        const int k = r.integer(-500, 500);
        s.frustum = audit::scaled(s.frustum, k);
        for (obb3& b : s.boxes) b = audit::scaled(b, k);
    }
    return s;
}

// Six planes with integer normals (no zero component) and the boxes beyond the line where planes 0
// and 1 meet (through an integer point X): a corner at X, reaching along the signs of
// g = |n_1[a]| n_0 + |n_0[a]| n_1 (n_0[a] and n_1[a] of opposite signs), so the plane the two imply
// touches the box at X (the batch's third stage, halfspaces::edge_planes); the other planes pass X
// or leave room. A third of the boxes are a few ulps off, some boxes random around X.
culling_set<> edge_set(support::rng& r) {
    auto nonzero = [&] { return (r.coin() ? 1.0 : -1.0) * r.integer(1, 3); };
    const point3 X = audit::int_point(r, 400);
    const int a = r.integer(0, 2);
    culling_set s;
    for (unsigned i = 0; i < 6; ++i) {
        vec3 n{nonzero(), nonzero(), nonzero()};
        if (i == 1) { // opposite to plane 0 on axis a
            const double v = (a == 0 ? s.frustum.planes[0].normal.x : a == 1 ? s.frustum.planes[0].normal.y : s.frustum.planes[0].normal.z);
            const double w = -std::copysign(r.integer(1, 3), v);
            n = a == 0 ? vec3{w, n.y, n.z} : a == 1 ? vec3{n.x, w, n.z} : vec3{n.x, n.y, w};
        }
        s.frustum.planes[i] = plane3{n, dot(n, X - point3{0, 0, 0}) + (i < 2 ? 0.0 : r.integer(0, 3) * 40.0)};
    }
    const vec3 n0 = s.frustum.planes[0].normal, n1 = s.frustum.planes[1].normal;
    const double alpha = std::abs(a == 0 ? n1.x : a == 1 ? n1.y : n1.z), beta = std::abs(a == 0 ? n0.x : a == 1 ? n0.y : n0.z);
    const vec3 g = n0 * alpha + n1 * beta; // exact: small integers
    const int n = set_size(r, 64);
    for (int i = 0; i < n; ++i) {
        const double gv[3] = {g.x, g.y, g.z}, x[3] = {X.x, X.y, X.z};
        double lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            const double e = r.integer(0, 40), sign = gv[k] != 0 ? std::copysign(1.0, gv[k]) : (r.coin() ? 1.0 : -1.0);
            const double y = r.integer(0, 5) == 0 ? x[k] + r.integer(-60, 60) : x[k];
            lo[k] = sign > 0 ? y : y - e, hi[k] = sign > 0 ? y + e : y;
        }
        aabb3 box{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
        if (r.integer(0, 2) == 0)
            box = aabb3{{support::nudge(box.min.x, r.integer(-3, 3)), support::nudge(box.min.y, r.integer(-3, 3)),
                         support::nudge(box.min.z, r.integer(-3, 3))},
                        {support::nudge(box.max.x, r.integer(-3, 3)), support::nudge(box.max.y, r.integer(-3, 3)),
                         support::nudge(box.max.z, r.integer(-3, 3))}};
        s.boxes.push_back(box);
    }
    return s;
}

// edge_set's boxes as oriented boxes: centre and half extents rounded from the bounds, the unit
// axes in a random signed order (the same box up to that rounding, beyond an implied plane or
// touching it, so that stage 2's corners lie within rounding of a plane).
culling_set<obb3> edge_obb_set(support::rng& r) {
    const culling_set<> boxes = edge_set(r);
    culling_set<obb3> s{boxes.frustum, {}};
    for (const aabb3& b : boxes.boxes) {
        std::array<vec3, 3> axes{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
        std::array<double, 3> h{0.5 * (b.max.x - b.min.x), 0.5 * (b.max.y - b.min.y), 0.5 * (b.max.z - b.min.z)};
        const int first = r.integer(0, 2);
        std::rotate(axes.begin(), axes.begin() + first, axes.end());
        std::rotate(h.begin(), h.begin() + first, h.end());
        for (vec3& a : axes)
            if (r.coin()) a = a * -1.0;
        s.boxes.push_back(obb3{{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y), 0.5 * (b.min.z + b.max.z)}, axes, h});
    }
    return s;
}

culling_set<> special_set(support::rng& r) {
    auto pick = [&] { return support::special_or_uniform(r); };
    auto point = [&] { return point3{pick(), pick(), pick()}; };
    culling_set s = r.coin() ? camera_set(r) : touching_set(r);
    if (r.integer(0, 3) == 0) s.frustum.planes[static_cast<unsigned>(r.integer(0, 5))] = plane3{vec3{pick(), pick(), pick()}, pick()};
    for (aabb3& b : s.boxes)
        if (r.coin()) b = r.coin() ? aabb3{point(), point()} : aabb3{b.max, b.min};
    return s;
}
// Oriented boxes with special numbers (NaN, infinities, huge, subnormal) or a negative extent.
culling_set<obb3> special_obb_set(support::rng& r) {
    auto pick = [&] { return support::special_or_uniform(r); };
    culling_set<obb3> s = r.coin() ? camera_obb_set(r) : touching_obb_set(r);
    if (r.integer(0, 3) == 0) s.frustum.planes[static_cast<unsigned>(r.integer(0, 5))] = plane3{vec3{pick(), pick(), pick()}, pick()};
    for (obb3& b : s.boxes) {
        if (!r.coin()) continue;
        double v[15];
        batch_fields(b, v);
        v[r.integer(0, 14)] = pick();
        if (r.integer(0, 3) == 0) v[12 + r.integer(0, 2)] = -r.uniform(0, 1);
        b = support::obb_of_fields(v);
    }
    return s;
}

// A camera and balls around what it sees (radii up to a tenth of the view's size).
culling_set<sphere3> camera_ball_set(support::rng& r) {
    culling_set<sphere3> s;
    point3 lo, hi;
    s.frustum = camera(r, lo, hi);
    const double size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const int n = set_size(r, 200);
    for (int i = 0; i < n; ++i)
        s.boxes.push_back(sphere3{{r.uniform(lo.x - 0.2 * size, hi.x + 0.2 * size), r.uniform(lo.y - 0.2 * size, hi.y + 0.2 * size),
                                   r.uniform(lo.z - 0.2 * size, hi.z + 0.2 * size)},
                                  r.uniform(0, 0.1 * size)});
    return s;
}
// A small-integer frustum (testkit/ball_halfspace_cases.hpp) and balls tangent at its corners,
// edges and faces, exactly (Pythagorean) or within ulps, inside or apart, moved by one transform.
culling_set<sphere3> touching_ball_set(support::rng& r) {
    const support::proto_rows p = support::near_rows<frustum3>(r);
    std::vector<sphere3> balls;
    for (int i = set_size(r, 100); i > 0; --i) balls.push_back(support::ball_touching(r, p));
    support::transform tr = support::random_transform(r, true, true);
    for (;;) {
        const auto f = support::realise_rows<frustum3>(p, tr);
        if (!f) {
            tr = support::random_transform(r, true, false);
            continue;
        }
        culling_set<sphere3> s{*f, {}};
        for (const sphere3& b : balls) s.boxes.push_back(sphere3{support::moved(b.center, tr), tr.scale_only(b.radius)});
        return s;
    }
}
// Camera or touching sets with special numbers in some balls (NaN, infinities, huge, subnormal,
// negative radii).
culling_set<sphere3> special_ball_set(support::rng& r) {
    culling_set<sphere3> s = r.coin() ? camera_ball_set(r) : touching_ball_set(r);
    for (sphere3& b : s.boxes)
        if (r.integer(0, 3) == 0) {
            double v[4] = {b.center.x, b.center.y, b.center.z, b.radius};
            v[r.integer(0, 3)] = support::special_or_uniform(r);
            if (r.coin()) v[3] = -v[3];
            b = sphere3{{v[0], v[1], v[2]}, v[3]};
        }
    return s;
}

struct counts {
    long lanes = 0, wrong = 0, uncertain = 0, met = 0;
};

template <class Tier, class Box>
void compare(const culling_set<Box>& s, counts& c, const std::string& where) {
    const std::size_t n = s.boxes.size();
    std::vector<std::uint8_t> out[4];
    for (auto& o : out) o.assign(n, 7);
    const packet<Box> copy(s.boxes);
    const auto soa = copy.view();
    const std::span<const Box> boxes(s.boxes);
    const result<std::size_t> r[4] = {batch::intersects<Tier>(s.frustum, boxes, out[0]), batch::intersects<Tier>(s.frustum, soa, out[1]),
                                      batch::intersects<Tier>(boxes, s.frustum, out[2]), batch::intersects<Tier>(soa, s.frustum, out[3])};
    std::size_t met = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t scalar = intersects<Tier>(s.frustum, s.boxes[i]) ? 1 : 0;
        met += scalar;
        ++c.lanes;
        if (std::is_same_v<Tier, exact>) c.uncertain += classify(s.frustum, s.boxes[i]) == certainty::uncertain;
        if (out[0][i] != scalar || out[1][i] != scalar || out[2][i] != scalar || out[3][i] != scalar) {
            if (++c.wrong <= 5) {
                std::printf("  %s lane %zu: scalar %d, batch %d %d %d %d\n", where.c_str(), i, scalar, out[0][i], out[1][i], out[2][i],
                            out[3][i]);
                for (auto& p : s.frustum.planes) std::printf("    plane %a %a %a %a\n", p.normal.x, p.normal.y, p.normal.z, p.offset);
                double v[15];
                batch_fields(s.boxes[i], v);
                std::printf("    box");
                for (std::size_t k = 0; k < packet<Box>::fields; ++k) std::printf(" %a", v[k]);
                std::printf("\n");
            }
        }
    }
    c.met += static_cast<long>(met);
    for (const auto& x : r) {
        REQUIRE(x.has_value());
        if (x.value() != met) ++c.wrong;
    }
}

template <class Make>
void every_tier_on_every_target(const char* name, long sets, Make make) {
    counts c[4];
    const int targets = support::on_every_target(name, [&](support::rng& r, const std::string& where, const char*) {
        for (long k = 0; k < sets; ++k) {
            const auto s = make(r, k);
            compare<exact>(s, c[0], where + ", exact");
            compare<conservative>(s, c[1], where + ", conservative");
            compare<aggressive>(s, c[2], where + ", aggressive");
            compare<approximate>(s, c[3], where + ", approximate");
        }
    });
    std::printf("[cases] batch culling %s: %d SIMD targets, %ld lanes per tier (%ld met, %ld uncertain for the filter); lanes unlike the "
                "scalar answer %ld %ld %ld %ld (exact, conservative, aggressive, approximate)\n",
                name, targets, c[0].lanes, c[0].met, c[0].uncertain, c[0].wrong, c[1].wrong, c[2].wrong, c[3].wrong);
    CHECK(targets >= 2);
    for (const counts& x : c) CHECK(x.wrong == 0);
}

// The same for near-degenerate sets, after checking on 30 of them that the filter leaves at least
// a tenth of their lanes uncertain (the batch must leave those to the scalar query).
template <class Box>
void near_sets_on_every_target(const char* name, long sets, culling_set<Box> (*make)(support::rng&)) {
    long uncertain = 0, lanes = 0;
    support::rng r(support::seed());
    for (int k = 0; k < 30; ++k) {
        const culling_set<Box> s = make(r);
        for (const Box& b : s.boxes) uncertain += classify(s.frustum, b) == certainty::uncertain, ++lanes;
    }
    std::printf("[cases] batch culling %s: %ld of %ld lanes of 30 sets are uncertain for the filter\n", name, uncertain, lanes);
    CHECK(uncertain * 10 > lanes);
    every_tier_on_every_target(name, sets, [make](support::rng& g, long) { return make(g); });
}

} // namespace

TEST_CASE("batch culling: every lane is the scalar answer, camera frustums and random boxes, every target", "[batch]") {
    every_tier_on_every_target("camera", support::cases(150), [](support::rng& r, long) { return camera_set(r); });
}

TEST_CASE("batch culling: every lane is the scalar answer, boxes at an integer frustum's boundary, every target", "[batch]") {
    near_sets_on_every_target("touching", support::cases(150), touching_set);
}

TEST_CASE("batch culling: every lane is the scalar answer, boxes beyond an edge of six integer planes, every target", "[batch]") {
    every_tier_on_every_target("edge", support::cases(150), [](support::rng& r, long) { return edge_set(r); });
}

TEST_CASE("batch culling: every lane is the scalar answer, special values, every target", "[batch]") {
    every_tier_on_every_target("special", support::cases(100), [](support::rng& r, long) { return special_set(r); });
}

TEST_CASE("batch culling: every lane is the scalar answer, oriented boxes, camera frustums, every target", "[batch]") {
    every_tier_on_every_target("obb camera", support::cases(150), [](support::rng& r, long) { return camera_obb_set(r); });
}

TEST_CASE("batch culling: every lane is the scalar answer, oriented boxes at an integer frustum's boundary, every target", "[batch]") {
    near_sets_on_every_target("obb touching", support::cases(100), touching_obb_set);
}

TEST_CASE("batch culling: every lane is the scalar answer, oriented boxes beyond an edge of six integer planes, every target", "[batch]") {
    every_tier_on_every_target("obb edge", support::cases(100), [](support::rng& r, long) { return edge_obb_set(r); });
}

TEST_CASE("batch culling: every lane is the scalar answer, oriented boxes of special values, every target", "[batch]") {
    every_tier_on_every_target("obb special", support::cases(100), [](support::rng& r, long) { return special_obb_set(r); });
}

TEST_CASE("batch culling: every lane is the scalar answer, balls, camera frustums, every target", "[batch]") {
    every_tier_on_every_target("ball camera", support::cases(150), [](support::rng& r, long) { return camera_ball_set(r); });
}
TEST_CASE("batch culling: every lane is the scalar answer, balls touching an integer frustum, every target", "[batch]") {
    near_sets_on_every_target("ball touching", support::cases(100), touching_ball_set);
}
TEST_CASE("batch culling: every lane is the scalar answer, balls of special values, every target", "[batch]") {
    every_tier_on_every_target("ball special", support::cases(100), [](support::rng& r, long) { return special_ball_set(r); });
}
TEST_CASE("batch culling: sizes", "[batch]") {
    const frustum3 f = frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1.0, 1.0, 1.0, 10.0).value();
    const std::vector<aabb3> boxes{aabb3{{-1, -1, -5}, {1, 1, -4}}, aabb3{{-1, -1, 1}, {1, 1, 2}}, aabb3{{50, 50, -5}, {51, 51, -4}}};
    std::vector<std::uint8_t> out(2);
    const auto refused = batch::intersects<exact>(f, std::span<const aabb3>(boxes), out);
    REQUIRE(refused.has_error());
    CHECK(refused.error().code == errc::size_mismatch);
    out.resize(3);
    const auto met = batch::intersects<exact>(std::span<const aabb3>(boxes), f, out);
    REQUIRE(met.has_value());
    CHECK(met.value() == 1);
    CHECK(out == std::vector<std::uint8_t>{1, 0, 0});
    const std::vector<double> x{0.0, 1.0}, y{0.0};
    const auto bad = batch::intersects<exact>(f, batch::boxes_soa{x, x, x, x, x, y}, std::span<std::uint8_t>(out.data(), 2));
    REQUIRE(bad.has_error());
    CHECK(bad.error().code == errc::size_mismatch);
    const std::vector<obb3> obbs{obb3{{0, 0, -5}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}},
                                 obb3{{0, 0, 5}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}}};
    out.assign(2, 7);
    const auto oriented = batch::intersects<exact>(f, std::span<const obb3>(obbs), out);
    REQUIRE(oriented.has_value());
    CHECK(oriented.value() == 1);
    CHECK(out == std::vector<std::uint8_t>{1, 0});
    const auto short_obbs = batch::intersects<exact>(std::span<const obb3>(obbs), f, std::span<std::uint8_t>(out.data(), 1));
    REQUIRE(short_obbs.has_error());
    const auto uneven =
        batch::intersects<exact>(batch::obbs_soa{x, x, x, x, x, x, x, x, x, x, x, x, x, x, y}, f, std::span<std::uint8_t>(out.data(), 2));
    REQUIRE(uneven.has_error());
}

} // namespace test_batch_culling
