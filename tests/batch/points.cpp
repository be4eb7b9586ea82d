// batch::intersects(solid, points) for a box, a sphere and a tetrahedron: on every SIMD target this
// processor has, each lane's answer equals the scalar intersects<Tier> in all four tiers, for the
// array and the structure-of-arrays entry points, on random points, on points exactly on the
// boundary and a few ulps off it (box faces, edges and corners; points of the sphere with integer
// coordinates, from Pythagorean quadruples; tetrahedron faces, edges and vertices in eighths, flat
// tetrahedra among them), at scales 2^-500..2^500, and on special values. The
// exact lanes on the boundary are checked against the known truth (on the boundary: inside).
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>
import incidence;
#include "testkit/testing.hpp"
#include "testkit/simd_targets.hpp"

namespace test_batch_points { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {

struct point_set {
    aabb3 box;
    sphere3 ball;
    tetrahedron3 tet;
    std::vector<point3> points;
    std::vector<int> on_boundary; // 1: exactly on the box's boundary, 2: on the sphere, 3: on the tetrahedron's, 0: none known
};

// Integer points of the sphere of radius 9 around the origin: (1, 4, 8), (4, 4, 7), (0, 0, 9)
// and their sign changes and permutations (x^2 + y^2 + z^2 = 81).
std::vector<std::array<double, 3>> sphere_points() {
    std::vector<std::array<double, 3>> out;
    const int base[3][3] = {{1, 4, 8}, {4, 4, 7}, {0, 0, 9}};
    const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& b : base)
        for (const auto& p : perm)
            for (int s = 0; s < 8; ++s)
                out.push_back({(s & 1 ? -1.0 : 1.0) * b[p[0]], (s & 2 ? -1.0 : 1.0) * b[p[1]], (s & 4 ? -1.0 : 1.0) * b[p[2]]});
    return out;
}

point_set make_set(support::rng& r, int kind) {
    point_set s;
    // scale 2^k and an exact translation by a multiple of 2^k, so boundary points stay exact
    const int k = r.integer(0, 3) == 0 ? r.integer(-500, 500) : 0;
    const double t[3] = {std::ldexp(r.integer(-64, 64), k), std::ldexp(r.integer(-64, 64), k), std::ldexp(r.integer(-64, 64), k)};
    auto at = [&](double x, double y, double z) {
        return point3{std::ldexp(x, k) + t[0], std::ldexp(y, k) + t[1], std::ldexp(z, k) + t[2]};
    };
    s.box = aabb3{at(-4, -3, -2), at(5, 6, 7)};
    s.ball = sphere3{at(0, 0, 0), std::ldexp(9.0, k)};
    // vertices in quarters, either orientation; flat (four coplanar vertices) once in eight
    const bool flat = r.integer(0, 7) == 0; // the fourth vertex (a + 2 b + c) / 4, in the plane of the others
    const double tv[4][3] = {{-4, -3, -2}, {6, -1, 0}, {-1, 7, 1}, {flat ? 1.75 : 0.0, flat ? 0.5 : 1.0, flat ? -0.25 : 8.0}};
    const int swap = r.integer(0, 1);
    s.tet = tetrahedron3{at(tv[0][0], tv[0][1], tv[0][2]), at(tv[1 + swap][0], tv[1 + swap][1], tv[1 + swap][2]),
                         at(tv[2 - swap][0], tv[2 - swap][1], tv[2 - swap][2]), at(tv[3][0], tv[3][1], tv[3][2])};
    const auto on_sphere = sphere_points();
    const int n = 2 * r.integer(20, 80) + 1;
    for (int i = 0; i < n; ++i) {
        int known = 0;
        point3 p;
        if (kind == 0) { // random around both
            p = at(r.uniform(-12, 12), r.uniform(-12, 12), r.uniform(-12, 12));
        } else if (kind == 1) { // on the box's boundary: a face, an edge or a corner
            double c[3] = {r.uniform(-4, 5), r.uniform(-3, 6), r.uniform(-2, 7)};
            const double lo[3] = {-4, -3, -2}, hi[3] = {5, 6, 7};
            for (int a = 0; a < 3; ++a)
                if (a == 0 || r.coin()) c[a] = r.coin() ? lo[a] : hi[a];
            p = at(c[0], c[1], c[2]);
            known = 1;
        } else if (kind == 3) { // on the tetrahedron's boundary: weights in eighths on a face, an edge or a vertex
            int w[4] = {r.integer(0, 8), 0, 0, 0};
            w[1] = r.integer(0, 8 - w[0]);
            w[2] = 8 - w[0] - w[1];
            const int skip = r.integer(0, 3); // the vertex the face leaves out
            double c[3] = {};
            for (int a = 0; a < 3; ++a)
                for (int j = 0; j < 3; ++j) c[a] += w[j] * tv[(skip + 1 + j) % 4][a] / 8.0;
            p = at(c[0], c[1], c[2]);
            known = 3;
        } else { // on the sphere
            const auto& q = on_sphere[static_cast<std::size_t>(r.integer(0, static_cast<int>(on_sphere.size()) - 1))];
            p = at(q[0], q[1], q[2]);
            known = 2;
        }
        if (r.integer(0, 3) == 0) { // a few ulps off
            p = {support::nudge(p.x, r.integer(-3, 3)), support::nudge(p.y, r.integer(-3, 3)), support::nudge(p.z, r.integer(-3, 3))};
            known = 0;
        }
        s.points.push_back(p);
        s.on_boundary.push_back(known);
    }
    return s;
}

point_set special_set(support::rng& r) {
    auto pick = [&] { return support::special_or_uniform(r); };
    auto point = [&] { return point3{pick(), pick(), pick()}; };
    point_set s;
    s.box = aabb3{point(), point()};
    s.ball = sphere3{point(), pick()};
    s.tet = tetrahedron3{point(), point(), point(), point()};
    if (r.coin()) s.tet = tetrahedron3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 37; ++i) s.points.push_back(point()), s.on_boundary.push_back(0);
    return s;
}

struct counts {
    long lanes = 0, wrong = 0, boundary_wrong = 0;
};

template <class Tier, class Solid>
void compare(const Solid& solid, const point_set& s, int boundary_kind, counts& c, const std::string& where) {
    const std::size_t n = s.points.size();
    std::vector<std::uint8_t> aos(n, 7), soa(n, 7);
    std::vector<double> x, y, z;
    for (const point3& p : s.points) x.push_back(p.x), y.push_back(p.y), z.push_back(p.z);
    const auto ra = batch::intersects<Tier>(solid, std::span<const point3>(s.points), aos);
    const auto rs = batch::intersects<Tier>(solid, batch::points_soa{x, y, z}, soa);
    REQUIRE(ra.has_value());
    REQUIRE(rs.has_value());
    std::size_t met = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t scalar = intersects<Tier>(solid, s.points[i]) ? 1 : 0;
        met += scalar;
        ++c.lanes;
        if (aos[i] != scalar || soa[i] != scalar) {
            if (++c.wrong <= 5)
                std::printf("  %s lane %zu: scalar %d, batch %d (array) %d (soa)\n", where.c_str(), i, scalar, aos[i], soa[i]);
        }
        if (std::is_same_v<Tier, exact> && s.on_boundary[i] == boundary_kind && aos[i] != 1) ++c.boundary_wrong;
    }
    if (ra.value() != met || rs.value() != met) ++c.wrong;
}

template <class Make>
void every_tier_on_every_target(const char* name, long sets, Make make) {
    counts box[4], ball[4], tet[4];
    const int targets = support::on_every_target(name, [&](support::rng& r, const std::string& where, const char*) {
        for (long k = 0; k < sets; ++k) {
            const point_set s = make(r, static_cast<int>(k % 4));
            compare<exact>(s.box, s, 1, box[0], where + ", box, exact");
            compare<conservative>(s.box, s, 1, box[1], where + ", box, conservative");
            compare<aggressive>(s.box, s, 1, box[2], where + ", box, aggressive");
            compare<approximate>(s.box, s, 1, box[3], where + ", box, approximate");
            compare<exact>(s.ball, s, 2, ball[0], where + ", ball, exact");
            compare<conservative>(s.ball, s, 2, ball[1], where + ", ball, conservative");
            compare<aggressive>(s.ball, s, 2, ball[2], where + ", ball, aggressive");
            compare<approximate>(s.ball, s, 2, ball[3], where + ", ball, approximate");
            compare<exact>(s.tet, s, 3, tet[0], where + ", tetrahedron, exact");
            compare<conservative>(s.tet, s, 3, tet[1], where + ", tetrahedron, conservative");
            compare<aggressive>(s.tet, s, 3, tet[2], where + ", tetrahedron, aggressive");
            compare<approximate>(s.tet, s, 3, tet[3], where + ", tetrahedron, approximate");
        }
    });
    std::printf(
        "[cases] batch points %s: %d SIMD targets, %ld lanes per tier and solid; lanes unlike the scalar answer: box %ld %ld %ld %ld, "
        "ball %ld %ld %ld %ld, tetrahedron %ld %ld %ld %ld (exact, conservative, aggressive, approximate); exact lanes on the "
        "boundary not inside: box %ld, ball %ld, tetrahedron %ld\n",
        name, targets, box[0].lanes, box[0].wrong, box[1].wrong, box[2].wrong, box[3].wrong, ball[0].wrong, ball[1].wrong, ball[2].wrong,
        ball[3].wrong, tet[0].wrong, tet[1].wrong, tet[2].wrong, tet[3].wrong, box[0].boundary_wrong, ball[0].boundary_wrong,
        tet[0].boundary_wrong);
    CHECK(targets >= 2);
    for (int t = 0; t < 4; ++t) CHECK((box[t].wrong == 0 && ball[t].wrong == 0 && tet[t].wrong == 0));
    CHECK(box[0].boundary_wrong == 0);
    CHECK(ball[0].boundary_wrong == 0);
    CHECK(tet[0].boundary_wrong == 0);
}

} // namespace

TEST_CASE("batch points: every lane is the scalar answer, random and boundary points, every target", "[batch]") {
    every_tier_on_every_target("random and boundary", support::cases(600), make_set);
}

TEST_CASE("batch points: every lane is the scalar answer, special values, every target", "[batch]") {
    every_tier_on_every_target("special", support::cases(300), [](support::rng& r, int) { return special_set(r); });
}

TEST_CASE("batch points: sizes", "[batch]") {
    const std::vector<point3> ps(3, point3{0, 0, 0});
    std::vector<std::uint8_t> out(2);
    const aabb3 box{{-1, -1, -1}, {1, 1, 1}};
    const auto refused = batch::intersects<exact>(box, std::span<const point3>(ps), out);
    REQUIRE(refused.has_error());
    CHECK(refused.error().code == errc::size_mismatch);
    out.resize(3);
    const auto all = batch::intersects<exact>(sphere3{{0, 0, 0}, 1}, std::span<const point3>(ps), out);
    REQUIRE(all.has_value());
    CHECK(all.value() == 3);
    const std::vector<double> x{0.0, 1.0}, y{0.0};
    const auto bad = batch::intersects<exact>(box, batch::points_soa{x, x, y}, std::span<std::uint8_t>(out.data(), 2));
    REQUIRE(bad.has_error());
    CHECK(bad.error().code == errc::size_mismatch);
}

} // namespace test_batch_points
