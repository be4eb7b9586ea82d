// batch::intersects(one, many) for one and many among aabb3 and sphere3, and for oriented boxes
// against one box or one ball: on every SIMD target this processor has, each lane's answer equals the scalar
// intersects<Tier>(one, many[i]) in all four tiers, for the array and the structure-of-arrays entry
// points, on random shapes, on shapes that touch exactly (boxes sharing a face, an edge or a
// corner; balls touching a box's face, edge or corner, from Pythagorean triples and quadruples;
// tangent balls; oriented boxes through a point of the box's boundary or of the ball's sphere,
// flat ones among them) and a
// few ulps off, at scales 2^-500..2^500, and on special values (NaN, infinities, inverted boxes,
// negative radii and extents). The exact lanes that touch are checked against the known truth
// (touching meets).
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>
import incidence;
#include "testkit/testing.hpp"
#include "testkit/simd_targets.hpp"
#include "testkit/batch_packets.hpp"
#include "testkit/generators.hpp"
#include "testkit/obb_cases.hpp"

namespace test_batch_solids { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {

struct solid_set {
    aabb3 box;    // the one box: [-4, 5] x [-3, 6] x [-2, 7]
    sphere3 ball; // the one ball: centre 0, radius 9
    std::vector<aabb3> boxes;
    std::vector<sphere3> balls;
    std::vector<int> touching_box, touching_ball; // boxes[i] touches box, balls[i] touches box (1) or ball (2); 0: unknown
};

// Integer vectors of length 5 or 9 (Pythagorean triples and quadruples), signs and order mixed.
std::array<double, 4> integer_direction(support::rng& r) {
    const int base[4][4] = {{3, 4, 0, 5}, {1, 4, 8, 9}, {4, 4, 7, 9}, {2, 3, 6, 7}};
    const auto& b = base[r.integer(0, 3)];
    int perm[3] = {0, 1, 2};
    for (int i = 2; i > 0; --i) std::swap(perm[i], perm[r.integer(0, i)]);
    return {(r.coin() ? -1.0 : 1.0) * b[perm[0]], (r.coin() ? -1.0 : 1.0) * b[perm[1]], (r.coin() ? -1.0 : 1.0) * b[perm[2]],
            static_cast<double>(b[3])};
}

solid_set make_set(support::rng& r, int kind) {
    solid_set s;
    // scale 2^k and an exact translation by a multiple of 2^k, so touching stays exact
    const int k = r.integer(0, 3) == 0 ? r.integer(-500, 500) : 0;
    const double t[3] = {std::ldexp(r.integer(-64, 64), k), std::ldexp(r.integer(-64, 64), k), std::ldexp(r.integer(-64, 64), k)};
    auto at = [&](double x, double y, double z) {
        return point3{std::ldexp(x, k) + t[0], std::ldexp(y, k) + t[1], std::ldexp(z, k) + t[2]};
    };
    auto length = [&](double x) { return std::ldexp(x, k); };
    const double lo[3] = {-4, -3, -2}, hi[3] = {5, 6, 7};
    s.box = aabb3{at(lo[0], lo[1], lo[2]), at(hi[0], hi[1], hi[2])};
    s.ball = sphere3{at(0, 0, 0), length(9)};
    auto nudge = [&](point3 p) {
        return point3{support::nudge(p.x, r.integer(-3, 3)), support::nudge(p.y, r.integer(-3, 3)), support::nudge(p.z, r.integer(-3, 3))};
    };
    const int n = 2 * r.integer(20, 80) + 1;
    for (int i = 0; i < n; ++i) {
        int box_known = 0, ball_known = 0;
        aabb3 b;
        sphere3 ball;
        if (kind == 0) { // random around both
            double c[3], e[3];
            for (int a = 0; a < 3; ++a) c[a] = r.uniform(-16, 16), e[a] = r.uniform(0, 4);
            b = aabb3{at(c[0] - e[0], c[1] - e[1], c[2] - e[2]), at(c[0] + e[0], c[1] + e[1], c[2] + e[2])};
            ball = sphere3{at(r.uniform(-16, 16), r.uniform(-16, 16), r.uniform(-16, 16)), length(r.uniform(0, 6))};
        } else { // touching: a box on a face, edge or corner of the box; a ball on the box's or the ball's surface
            double corner[3];
            int face_axes = 0;
            for (int a = 0; a < 3; ++a) {
                if (a == 0 || r.coin()) {
                    const bool upper = r.coin();
                    corner[a] = upper ? hi[a] : lo[a];
                    face_axes |= (upper ? 2 : 1) << (2 * a);
                } else {
                    corner[a] = r.integer(static_cast<int>(lo[a]), static_cast<int>(hi[a]));
                }
            }
            // the box: from the touching point outwards on the face axes, any extent on the others
            double bmin[3], bmax[3];
            for (int a = 0; a < 3; ++a) {
                const int side = (face_axes >> (2 * a)) & 3;
                const double e = r.integer(1, 4);
                bmin[a] = side == 2 ? corner[a] : corner[a] - e;
                bmax[a] = side == 1 ? corner[a] : corner[a] + (side == 2 ? e : r.integer(0, 3));
            }
            b = aabb3{at(bmin[0], bmin[1], bmin[2]), at(bmax[0], bmax[1], bmax[2])};
            box_known = 1;
            if (kind == 1) { // a ball touching the box at `corner` from outside: centre along an outward integer direction
                const auto dir = integer_direction(r);
                double c[3];
                for (int a = 0; a < 3; ++a) {
                    const int side = (face_axes >> (2 * a)) & 3;
                    const double v = side == 0 ? 0.0 : (side == 2 ? std::abs(dir[a]) : -std::abs(dir[a]));
                    c[a] = corner[a] + v;
                }
                // only the face axes may carry the offset: the nearest point is then `corner`
                double rr = 0;
                for (int a = 0; a < 3; ++a) rr += (c[a] - corner[a]) * (c[a] - corner[a]);
                const double radius = std::sqrt(rr);
                ball = sphere3{at(c[0], c[1], c[2]), length(radius)};
                ball_known = radius == std::floor(radius) && radius * radius == rr ? 1 : 0; // an integer radius: exactly touching
            } else { // a ball tangent to the one ball from outside: centre at 9 + r' along an integer direction of length L
                const auto dir = integer_direction(r);
                const double rad = dir[3] * r.integer(2, 3) - 9; // centre at distance L m, radius L m - 9
                const double m = (rad + 9) / dir[3];
                ball = sphere3{at(dir[0] * m, dir[1] * m, dir[2] * m), length(rad)};
                ball_known = 2;
            }
        }
        if (r.integer(0, 3) == 0) { // a few ulps off
            b = aabb3{nudge(b.min), nudge(b.max)};
            box_known = 0;
        }
        if (r.integer(0, 3) == 0) {
            ball = sphere3{nudge(ball.center), support::nudge(ball.radius, r.integer(-3, 3))};
            ball_known = 0;
        }
        s.boxes.push_back(b);
        s.balls.push_back(ball);
        s.touching_box.push_back(box_known);
        s.touching_ball.push_back(ball_known);
    }
    return s;
}

solid_set special_set(support::rng& r) {
    auto pick = [&] { return support::special_or_uniform(r); };
    auto point = [&] { return point3{pick(), pick(), pick()}; };
    solid_set s;
    s.box = r.coin() ? aabb3{point(), point()} : aabb3{{-1, -1, -1}, {1, 1, 1}};
    s.ball = r.coin() ? sphere3{point(), pick()} : sphere3{{0, 0, 0}, 1};
    for (int i = 0; i < 37; ++i) {
        s.boxes.push_back(aabb3{point(), point()});
        s.balls.push_back(sphere3{point(), pick()});
        s.touching_box.push_back(0);
        s.touching_ball.push_back(0);
    }
    return s;
}

struct counts {
    long lanes = 0, wrong = 0, touching_wrong = 0, uncertain = 0;
};

// `one` against `many`, both entry points, lane by lane against the scalar query; known[i] == kind
// marks the lanes that touch (the exact tier must say 1).
template <class Tier, class One, class Many>
void compare(const One& one, const std::vector<Many>& many, const std::vector<int>& known, int kind, counts& c, const std::string& where) {
    const std::size_t n = many.size();
    std::vector<std::uint8_t> aos(n, 7), soa(n, 7);
    const support::packet<Many> copy(many);
    const auto ra = batch::intersects<Tier>(one, std::span<const Many>(many), aos);
    const auto rs = batch::intersects<Tier>(one, copy.view(), soa);
    REQUIRE(ra.has_value());
    REQUIRE(rs.has_value());
    std::size_t met = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t scalar = intersects<Tier>(one, many[i]) ? 1 : 0;
        met += scalar;
        ++c.lanes;
        if (aos[i] != scalar || soa[i] != scalar) {
            if (++c.wrong <= 5) {
                std::printf("  %s lane %zu: scalar %d, batch %d (array) %d (soa)\n", where.c_str(), i, scalar, aos[i], soa[i]);
                double v[15];
                support::batch_fields(many[i], v);
                std::printf("    shape");
                for (int k = 0; k < support::packet<Many>::fields; ++k) std::printf(" %a", v[k]);
                std::printf("\n");
            }
        }
        if constexpr (std::is_same_v<Many, obb3>)
            if (std::is_same_v<Tier, exact>) c.uncertain += classify(one, many[i]) == certainty::uncertain;
        if (std::is_same_v<Tier, exact> && known[i] == kind && aos[i] != 1) {
            if (++c.touching_wrong <= 3) {
                double v[15], w[15];
                support::batch_fields(one, w);
                support::batch_fields(many[i], v);
                std::printf("  %s lane %zu touches, not met:", where.c_str(), i);
                for (int k = 0; k < support::packet<One>::fields; ++k) std::printf(" %a", w[k]);
                std::printf(" /");
                for (int k = 0; k < support::packet<Many>::fields; ++k) std::printf(" %a", v[k]);
                std::printf("\n");
            }
        }
    }
    if (ra.value() != met || rs.value() != met) ++c.wrong;
}

template <class One, class Many>
void every_tier(const One& one, const std::vector<Many>& many, const std::vector<int>& known, int kind, counts* c,
                const std::string& where) {
    compare<exact>(one, many, known, kind, c[0], where + ", exact");
    compare<conservative>(one, many, known, kind, c[1], where + ", conservative");
    compare<aggressive>(one, many, known, kind, c[2], where + ", aggressive");
    compare<approximate>(one, many, known, kind, c[3], where + ", approximate");
}

template <class Make>
void every_pair_on_every_target(const char* name, long sets, Make make) {
    counts pairs[4][4]; // box-boxes, box-balls, ball-boxes, ball-balls; per tier
    const int targets = support::on_every_target(name, [&](support::rng& r, const std::string& where, const char*) {
        for (long k = 0; k < sets; ++k) {
            const solid_set s = make(r, static_cast<int>(k % 3));
            every_tier(s.box, s.boxes, s.touching_box, 1, pairs[0], where + ", box against boxes");
            every_tier(s.box, s.balls, s.touching_ball, 1, pairs[1], where + ", box against balls");
            every_tier(s.ball, s.boxes, s.touching_box, -1, pairs[2], where + ", ball against boxes");
            every_tier(s.ball, s.balls, s.touching_ball, 2, pairs[3], where + ", ball against balls");
        }
    });
    const char* names[4] = {"box-boxes", "box-balls", "ball-boxes", "ball-balls"};
    for (int p = 0; p < 4; ++p)
        std::printf("[cases] batch solids %s, %s: %d SIMD targets, %ld lanes per tier; lanes unlike the scalar answer %ld %ld %ld %ld "
                    "(exact, conservative, aggressive, approximate); exact touching lanes not met: %ld\n",
                    name, names[p], targets, pairs[p][0].lanes, pairs[p][0].wrong, pairs[p][1].wrong, pairs[p][2].wrong, pairs[p][3].wrong,
                    pairs[p][0].touching_wrong);
    CHECK(targets >= 2);
    for (int p = 0; p < 4; ++p) {
        for (int t = 0; t < 4; ++t) CHECK(pairs[p][t].wrong == 0);
        CHECK(pairs[p][0].touching_wrong == 0);
    }
}

// Oriented boxes against one box: the box [-4, 5] x [-3, 6] x [-2, 7] (flat on one axis in a
// fifth of the sets), and
// - random (kind 0): oriented boxes of random rotation (support::random_frame), centres in
//   [-16, 16]^3, extents in [0, 4], a tenth of them flat on an axis;
// - touching (kinds 1, 2): support::near_obb boxes (signed-permutation, dyadic near-rotation or
//   small-integer skew axes; dyadic extents, some zero) placed so that a corner, edge or face point
//   of theirs lies on a corner, edge point or face point of the box: they meet, exactly (known[i]
//   = 1), unless a third of them turned by a random rotation instead (the point is then there only
//   to rounding) or a quarter moved a few ulps;
// the whole set at 2^k for a third of the sets.
// A support::near_obb box with its extents doubled, a third of them turned by a random rotation
// (`turned`), moved so that a corner, edge or face point of it lies on `on`: exactly unless turned.
obb3 touching_box(support::rng& r, point3 on, bool& turned) {
    obb3 b = support::near_obb(r);
    for (double& h : b.half_extents) h *= 2;
    turned = r.integer(0, 2) == 0;
    if (turned) b.axes = support::random_frame(r);
    b.center = on + (b.center - support::boundary_point(r, b, true));
    return b;
}
// A quarter of the boxes moved a few ulps, then no longer known to touch.
void nudged_now_and_then(support::rng& r, obb3& b, int& known) {
    if (r.integer(0, 3) != 0) return;
    b.center = {support::nudge(b.center.x, r.integer(-3, 3)), support::nudge(b.center.y, r.integer(-3, 3)), b.center.z};
    known = 0;
}
struct obb_set {
    aabb3 box;
    std::vector<obb3> obbs;
    std::vector<int> touching;
};
obb_set make_obb_set(support::rng& r, int kind) {
    obb_set s;
    double lo[3] = {-4, -3, -2}, hi[3] = {5, 6, 7};
    if (r.integer(0, 4) == 0) {
        const int a = r.integer(0, 2);
        lo[a] = hi[a] = r.integer(static_cast<int>(lo[a]), static_cast<int>(hi[a]));
    }
    s.box = aabb3{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    // up to 150 boxes a set (16 where the cases are scaled down: the sanitizer build)
    const int n = r.integer(1, static_cast<int>(std::max(16L, support::cases(15000) / 100)));
    for (int i = 0; i < n; ++i) {
        obb3 b;
        int known = 0;
        if (kind == 0) {
            b = obb3{{r.uniform(-16, 16), r.uniform(-16, 16), r.uniform(-16, 16)},
                     support::random_frame(r),
                     {r.uniform(0, 4), r.uniform(0, 4), r.uniform(0, 4)}};
            if (r.integer(0, 9) == 0) b.half_extents[static_cast<unsigned>(r.integer(0, 2))] = 0;
        } else {
            double p[3];
            const int on = r.integer(0, 2); // an axis on which p is on a face
            for (int a = 0; a < 3; ++a)
                p[a] = a == on || r.coin() ? (r.coin() ? hi[a] : lo[a])
                                           : 0.5 * r.integer(static_cast<int>(2 * lo[a]), static_cast<int>(2 * hi[a]));
            bool turned = false;
            b = touching_box(r, point3{p[0], p[1], p[2]}, turned);
            known = turned ? 0 : 1;
            nudged_now_and_then(r, b, known);
        }
        s.obbs.push_back(b);
        s.touching.push_back(known);
    }
    if (r.integer(0, 2) == 0) {
        const int k = r.integer(-500, 500);
        s.box = audit::scaled(s.box, k);
        for (obb3& b : s.obbs) b = audit::scaled(b, k);
    }
    return s;
}
// The same sets with special numbers (NaN, infinities, huge, subnormal) in a field, a negative
// extent, or an inverted or special box.
obb_set special_obb_set(support::rng& r) {
    auto pick = [&] { return support::special_or_uniform(r); };
    obb_set s = make_obb_set(r, r.integer(0, 1));
    if (r.integer(0, 3) == 0) {
        s.box = r.coin() ? aabb3{{pick(), pick(), pick()}, {pick(), pick(), pick()}} : aabb3{s.box.max, s.box.min};
        for (int& t : s.touching) t = 0;
    }
    for (std::size_t i = 0; i < s.obbs.size(); ++i) {
        if (!r.coin()) continue;
        double v[15];
        support::batch_fields(s.obbs[i], v);
        v[r.integer(0, 14)] = pick();
        if (r.integer(0, 3) == 0) v[12 + r.integer(0, 2)] = -r.uniform(0, 1);
        s.obbs[i] = support::obb_of_fields(v);
        s.touching[i] = 0;
    }
    return s;
}

// Oriented boxes against one ball: the ball of centre 0 and radius 9 (moved by a few integers), and
// - random (kind 0): oriented boxes as make_obb_set's random ones;
// - touching (kinds 1, 2): support::near_obb boxes placed so that a corner, edge or face point of
//   theirs lies on a point s of the sphere with integer coordinates (|s| = 9: (1, 4, 8), (4, 4, 7),
//   (0, 0, 9) signed and permuted), turned through s where their centre would lie in the ball, so
//   that most of the box is outside: they meet, exactly (known[i] = 1), unless a third of them
//   turned by a random rotation instead or a quarter moved a few ulps;
// the whole set at 2^k for a third of the sets.
struct ball_obb_set {
    sphere3 ball;
    std::vector<obb3> obbs;
    std::vector<int> touching;
};
ball_obb_set make_ball_obb_set(support::rng& r, int kind) {
    ball_obb_set s;
    const point3 centre{double(r.integer(-3, 3)), double(r.integer(-3, 3)), double(r.integer(-3, 3))};
    s.ball = sphere3{centre, 9};
    const obb_set random = make_obb_set(r, 0);
    for (std::size_t i = 0; i < random.obbs.size(); ++i) {
        if (kind == 0) {
            s.obbs.push_back(random.obbs[i]);
            s.touching.push_back(0);
            continue;
        }
        const int base[3][3] = {{1, 4, 8}, {4, 4, 7}, {0, 0, 9}};
        const int* b = base[r.integer(0, 2)];
        int perm[3] = {0, 1, 2};
        for (int j = 2; j > 0; --j) std::swap(perm[j], perm[r.integer(0, j)]);
        const vec3 dir{(r.coin() ? -1.0 : 1.0) * b[perm[0]], (r.coin() ? -1.0 : 1.0) * b[perm[1]], (r.coin() ? -1.0 : 1.0) * b[perm[2]]};
        const point3 on = centre + dir;
        bool turned = false;
        obb3 box = touching_box(r, on, turned);
        const vec3 in = box.center - centre;
        if (dot(in, in) < 81) box.center = on + (on - box.center); // the box turned through s
        int known = turned ? 0 : 1;
        nudged_now_and_then(r, box, known);
        s.obbs.push_back(box);
        s.touching.push_back(known);
    }
    if (r.integer(0, 2) == 0) {
        const int k = r.integer(-500, 500);
        s.ball = audit::scaled(s.ball, k);
        for (obb3& b : s.obbs) b = audit::scaled(b, k);
    }
    return s;
}
// The same sets with special numbers in a field of the ball or of a box, or a negative extent.
ball_obb_set special_ball_obb_set(support::rng& r) {
    auto pick = [&] { return support::special_or_uniform(r); };
    ball_obb_set s = make_ball_obb_set(r, r.integer(0, 1));
    const obb_set special = special_obb_set(r);
    for (std::size_t i = 0; i < s.obbs.size() && i < special.obbs.size(); ++i)
        if (r.coin()) s.obbs[i] = special.obbs[i], s.touching[i] = 0;
    if (r.integer(0, 3) == 0) {
        s.ball = r.coin() ? sphere3{{pick(), pick(), pick()}, pick()} : sphere3{s.ball.center, -s.ball.radius};
        for (int& t : s.touching) t = 0;
    }
    return s;
}

// The one shape of a set of oriented boxes: a box or a ball.
const aabb3& one_of(const obb_set& s) { return s.box; }
const sphere3& one_of(const ball_obb_set& s) { return s.ball; }

// Sets from make (kinds 0, 1, 2 in turn) on every SIMD target; pair names the one shape and the
// many (box-obbs, ball-obbs), against says so in a failure's context.
template <class Make>
void obbs_on_every_target(const char* name, const char* pair, const char* against, long sets, Make make) {
    counts c[4];
    const int targets = support::on_every_target(name, [&](support::rng& r, const std::string& where, const char*) {
        for (long k = 0; k < sets; ++k) {
            const auto s = make(r, static_cast<int>(k % 3));
            every_tier(one_of(s), s.obbs, s.touching, 1, c, where + against);
        }
    });
    std::printf("[cases] batch solids %s, %s: %d SIMD targets, %ld lanes per tier (%ld uncertain to the scalar filter); lanes "
                "unlike the scalar answer %ld %ld %ld %ld (exact, conservative, aggressive, approximate); exact touching lanes not met: "
                "%ld\n",
                name, pair, targets, c[0].lanes, c[0].uncertain, c[0].wrong, c[1].wrong, c[2].wrong, c[3].wrong, c[0].touching_wrong);
    CHECK(targets >= 2);
    for (const counts& x : c) CHECK(x.wrong == 0);
    CHECK(c[0].touching_wrong == 0);
}
} // namespace

TEST_CASE("batch solids: every lane is the scalar answer, random and touching shapes, every target", "[batch]") {
    every_pair_on_every_target("random and touching", support::cases(400), make_set);
}

TEST_CASE("batch solids: every lane is the scalar answer, special values, every target", "[batch]") {
    every_pair_on_every_target("special", support::cases(300), [](support::rng& r, int) { return special_set(r); });
}

TEST_CASE("batch solids: oriented boxes, every lane is the scalar answer, random and touching, every target", "[batch]") {
    obbs_on_every_target("random and touching", "box-obbs", ", box against oriented boxes", support::cases(100), make_obb_set);
}

TEST_CASE("batch solids: oriented boxes, every lane is the scalar answer, special values, every target", "[batch]") {
    obbs_on_every_target("special", "box-obbs", ", box against oriented boxes", support::cases(100),
                         [](support::rng& r, int) { return special_obb_set(r); });
}

TEST_CASE("batch solids: oriented boxes against a ball, every lane is the scalar answer, random and touching, every target", "[batch]") {
    obbs_on_every_target("random and touching", "ball-obbs", ", ball against oriented boxes", support::cases(100), make_ball_obb_set);
}

TEST_CASE("batch solids: oriented boxes against a ball, every lane is the scalar answer, special values, every target", "[batch]") {
    obbs_on_every_target("special", "ball-obbs", ", ball against oriented boxes", support::cases(100),
                         [](support::rng& r, int) { return special_ball_obb_set(r); });
}

TEST_CASE("batch solids: touching lanes are counted", "[batch]") {
    // the touching cases are not vacuous: most lanes of a touching set are known to touch
    support::rng r(support::seed());
    long known = 0, lanes = 0;
    for (int k = 0; k < 20; ++k) {
        const solid_set s = make_set(r, 1 + k % 2);
        for (std::size_t i = 0; i < s.boxes.size(); ++i) known += (s.touching_box[i] != 0) + (s.touching_ball[i] != 0), lanes += 2;
    }
    std::printf("[cases] batch solids: %ld of %ld lanes of the touching sets touch exactly\n", known, lanes);
    CHECK(known * 2 > lanes);
    long obb_known = 0, obb_lanes = 0;
    for (int k = 0; k < 20; ++k) {
        const obb_set s = make_obb_set(r, 1);
        for (const int t : s.touching) obb_known += t, ++obb_lanes;
    }
    std::printf("[cases] batch solids: %ld of %ld oriented boxes of the touching sets meet the box exactly\n", obb_known, obb_lanes);
    CHECK(obb_known * 3 > obb_lanes);
    long ball_known = 0, ball_lanes = 0;
    for (int k = 0; k < 20; ++k) {
        const ball_obb_set s = make_ball_obb_set(r, 1);
        for (const int t : s.touching) ball_known += t, ++ball_lanes;
    }
    std::printf("[cases] batch solids: %ld of %ld oriented boxes of the touching sets meet the ball exactly\n", ball_known, ball_lanes);
    CHECK(ball_known * 3 > ball_lanes);
}

TEST_CASE("batch solids: sizes", "[batch]") {
    const std::vector<aabb3> boxes(3, aabb3{{0, 0, 0}, {1, 1, 1}});
    std::vector<std::uint8_t> out(2);
    const auto refused = batch::intersects<exact>(sphere3{{0, 0, 0}, 1}, std::span<const aabb3>(boxes), out);
    REQUIRE(refused.has_error());
    CHECK(refused.error().code == errc::size_mismatch);
    out.resize(3);
    const auto all = batch::intersects<exact>(aabb3{{1, 1, 1}, {2, 2, 2}}, std::span<const aabb3>(boxes), out);
    REQUIRE(all.has_value());
    CHECK(all.value() == 3);
    const std::vector<double> x{0.0, 1.0}, y{0.0};
    const auto bad =
        batch::intersects<exact>(aabb3{{1, 1, 1}, {2, 2, 2}}, batch::spheres_soa{x, x, x, y}, std::span<std::uint8_t>(out.data(), 2));
    REQUIRE(bad.has_error());
    CHECK(bad.error().code == errc::size_mismatch);
    const std::vector<obb3> obbs(3, obb3{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}});
    const auto oriented = batch::intersects<exact>(aabb3{{1, 1, 1}, {2, 2, 2}}, std::span<const obb3>(obbs), out);
    REQUIRE(oriented.has_value());
    CHECK(oriented.value() == 3);
    const auto short_out =
        batch::intersects<exact>(aabb3{{1, 1, 1}, {2, 2, 2}}, std::span<const obb3>(obbs), std::span<std::uint8_t>(out.data(), 2));
    REQUIRE(short_out.has_error());
    CHECK(short_out.error().code == errc::size_mismatch);
    const auto bad_obbs = batch::intersects<exact>(
        aabb3{{1, 1, 1}, {2, 2, 2}}, batch::obbs_soa{x, x, x, x, x, x, x, x, x, x, x, x, x, x, y}, std::span<std::uint8_t>(out.data(), 2));
    REQUIRE(bad_obbs.has_error());
    CHECK(bad_obbs.error().code == errc::size_mismatch);
    const auto ball_obbs = batch::intersects<exact>(sphere3{{2, 0, 0}, 1}, std::span<const obb3>(obbs), out);
    REQUIRE(ball_obbs.has_value());
    CHECK(ball_obbs.value() == 3); // touching the face x = 1
    const auto bad_ball_obbs = batch::intersects<exact>(sphere3{{2, 0, 0}, 1}, batch::obbs_soa{x, x, x, x, x, x, x, x, x, x, x, x, x, x, y},
                                                        std::span<std::uint8_t>(out.data(), 2));
    REQUIRE(bad_ball_obbs.has_error());
    CHECK(bad_ball_obbs.error().code == errc::size_mismatch);
}

} // namespace test_batch_solids
