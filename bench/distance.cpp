// The signed distance from a point to a solid (distance/<family>), every tier, on the tests'
// generators at scale 1 (testkit/capsule_cases.hpp, ball_halfspace_cases.hpp, mesh_cases.hpp):
// random and near-degenerate sets (points on the boundary, at a face, an edge or a vertex, inside).
// The answer each loop checks: whether the point is outside or on the solid (d >= 0), against the
// exact value of the oracle (testkit/oracle/cgal_distance.cpp); the values themselves are checked in
// tests/query/distance/. Peers: CGAL Epick (the ball, the capsule, the tetrahedron) and FCL (the
// capsule, the oriented box), below.
#include "bench.hpp"
#include <cmath>
#include <optional>
#include <utility>

namespace bench {
namespace {

// d >= 0 in a tier's form: an interval's upper end for conservative, its lower end for aggressive.
template <class Tier, class D>
bool not_inside(const D& d) {
    if constexpr (std::is_same_v<D, double>) return d >= 0.0;
    else if constexpr (std::is_same_v<Tier, aggressive>) return d.lo >= 0.0;
    else return d.hi >= 0.0;
}

// A set, its answers (the oracle's), and the set's name's tail for the peers' rows.
template <class S>
struct distance_set {
    std::vector<std::pair<S, point3>> cases;
    std::vector<bool> truth;
    std::string tail;
};

template <class S, class Gen>
[[gnu::noinline]] distance_set<S> distance_tiers(const std::string& name, bool near, Gen gen,
                                                 oracle::distance_solid (*solid_of)(const S&)) {
    support::rng r = set_rng(near);
    distance_set<S> set;
    while (set.cases.size() < set_size)
        if (const auto c = gen(r, near)) set.cases.push_back(*c);
    auto truth = [solid_of](const std::pair<S, point3>& c) {
        const auto k = oracle::check_distance(solid_of(c.first), support::a3(c.second), false, 0.0, 0.0, 0.0, 0.0);
        return k.sign >= 0;
    };
    const std::string dist = near ? "near_degenerate" : "random";
    tiers(
        name, dist, set.cases, truth,
        [](auto tier, const std::pair<S, point3>& c) {
            return not_inside<decltype(tier)>(signed_distance<decltype(tier)>(c.first, c.second));
        },
        "distance");
    for (const auto& c : set.cases) set.truth.push_back(truth(c));
    set.tail = "/distance/" + name + "/" + dist;
    return set;
}

oracle::distance_solid ball_solid(const sphere3& s) {
    return {oracle::distance_solid::capsule, {s.center.x, s.center.y, s.center.z, s.center.x, s.center.y, s.center.z, s.radius}, {}};
}
oracle::distance_solid capsule_solid(const capsule3& c) {
    return {oracle::distance_solid::capsule, {c.a.x, c.a.y, c.a.z, c.b.x, c.b.y, c.b.z, c.radius}, {}};
}
template <class P>
oracle::distance_solid rows_solid(const P& a) {
    return {oracle::distance_solid::rows, {}, support::lp(a)};
}
oracle::distance_solid tetrahedron_solid(const tetrahedron3& t) {
    return {oracle::distance_solid::tetrahedron, {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z, t.d.x, t.d.y, t.d.z}, {}};
}
// The centre of ball_near / ball_random's ball as the point.
template <class P>
std::optional<std::pair<P, point3>> at_centre(support::rng& r, bool near) {
    const auto c = near ? support::ball_near<P>(r) : support::ball_random<P>(r);
    if (!c) return std::nullopt;
    return std::pair{c->first, c->second.center};
}

// Two points, segments, rays, lines or triangles (distance/<name>): the distance in every tier on the flat
// pairs' sets at scale 1 (random; near-degenerate: meeting, parallel and coplanar arrangements
// alternating with sets apart by a small dyadic offset, testkit/flat_cases.hpp). The answer each
// loop checks: whether the distance rounds to 0 (d = 0; an interval's lower end <= 0 for
// conservative, its upper end for aggressive), against the exact distance; the peer: CGAL Epick's
// sqrt(squared_distance) (not for the triangle's pairs).
template <class A, class B>
[[gnu::noinline]] void linear_distance_tiers(const std::string& name, bool near) {
    support::rng r = set_rng(near);
    std::vector<std::pair<A, B>> cs;
    while (cs.size() < set_size)
        cs.push_back(!near ? support::flat_random<A, B>(r, false)
                           : (cs.size() % 2 == 0 ? support::flat_near<A, B>(r, false) : support::flat_apart<A, B>(r, false)));
    // the distance rounds to 0 (they meet, or miss by less than half the least subnormal)
    const auto truth = [](const std::pair<A, B>& c) {
        return oracle::check_flat_distance(support::to_flat(c.first), support::to_flat(c.second), false, 0.0, 0.0, 0.0, 0.0).rounded;
    };
    const std::string dist = near ? "near_degenerate" : "random";
    tiers(
        name, dist, cs, truth,
        [](auto tier, const std::pair<A, B>& c) {
            const auto d = distance<decltype(tier)>(c.first, c.second);
            if constexpr (std::is_same_v<decltype(d), const double>) return d == 0.0;
            else if constexpr (std::is_same_v<decltype(tier), conservative>) return d.lo <= 0.0;
            else return d.hi <= 0.0;
        },
        "distance");
    if constexpr (std::is_same_v<B, triangle3>) return; // no peer row (oracle::flat_distance_epick)
    std::vector<bool> t;
    for (const auto& c : cs) t.push_back(truth(c));
    reg("cgal_epick/distance/" + name + "/" + dist, cs, t, check::approximate,
        [](const std::pair<A, B>& c) { return oracle::flat_distance_epick(support::to_flat(c.first), support::to_flat(c.second)) == 0.0; });
}

} // namespace

// The peers: CGAL Epick's squared distances as its users write a signed distance
// (testkit/oracle/cgal_oracle.cpp), and FCL's distance between a ball of radius 0 and the solid
// (bench/fcl_peer.cpp: apart, or on or in, for which FCL gives no distance).
void register_distance(bool near) {
    {
        const auto set = distance_tiers<sphere3>(
            "point_sphere", near,
            [](support::rng& r, bool n) -> std::optional<std::pair<sphere3, point3>> {
                const auto c = n ? support::capsule_near<point3>(r) : support::capsule_random<point3>(r);
                if (!c) return std::nullopt;
                return std::pair{sphere3{c->first.a, c->first.radius}, c->second};
            },
            ball_solid);
        reg("cgal_epick" + set.tail, set.cases, set.truth, check::approximate, [](const std::pair<sphere3, point3>& c) {
            double o[3], p[3];
            arr(c.first.center, o), arr(c.second, p);
            return oracle::capsule_point_distance_epick(o, o, c.first.radius, p) >= 0.0;
        });
    }
    {
        const auto set = distance_tiers<capsule3>(
            "capsule_point", near,
            [](support::rng& r, bool n) { return n ? support::capsule_near<point3>(r) : support::capsule_random<point3>(r); },
            capsule_solid);
        reg("cgal_epick" + set.tail, set.cases, set.truth, check::approximate, [](const std::pair<capsule3, point3>& c) {
            double a[3], b[3], p[3];
            arr(c.first.a, a), arr(c.first.b, b), arr(c.second, p);
            return oracle::capsule_point_distance_epick(a, b, c.first.radius, p) >= 0.0;
        });
        reg("fcl" + set.tail, set.cases, set.truth, check::approximate, [](const std::pair<capsule3, point3>& c) {
            double a[3], b[3], p[3];
            arr(c.first.a, a), arr(c.first.b, b), arr(c.second, p);
            return fcl_peer::point_apart_capsule(p, a, b, std::fabs(c.first.radius));
        });
    }
    distance_tiers<convex_polyhedron3>("convex_polyhedron_point", near, at_centre<convex_polyhedron3>, rows_solid<convex_polyhedron3>);
    distance_tiers<frustum3>("frustum_point", near, at_centre<frustum3>, rows_solid<frustum3>);
    distance_tiers<kdop<6>>("kdop_point_6", near, at_centre<kdop<6>>, rows_solid<kdop<6>>);
    distance_tiers<kdop<14>>("kdop_point_14", near, at_centre<kdop<14>>, rows_solid<kdop<14>>);
    distance_tiers<kdop<26>>("kdop_point_26", near, at_centre<kdop<26>>, rows_solid<kdop<26>>);
    {
        const auto set = distance_tiers<tetrahedron3>("point_tetrahedron", near, at_centre<tetrahedron3>, tetrahedron_solid);
        reg("cgal_epick" + set.tail, set.cases, set.truth, check::approximate, [](const std::pair<tetrahedron3, point3>& c) {
            double t[12], p[3];
            arr(c.first.a, t), arr(c.first.b, t + 3), arr(c.first.c, t + 6), arr(c.first.d, t + 9), arr(c.second, p);
            return oracle::tetrahedron_point_distance_epick(t, p) >= 0.0;
        });
    }
    {
        const auto set = distance_tiers<obb3>("obb_point", near, at_centre<obb3>, rows_solid<obb3>);
        reg("fcl" + set.tail, set.cases, set.truth, check::approximate, [](const std::pair<obb3, point3>& c) {
            double cb[3], ab[9], hb[3], p[3];
            obb_arrays(c.first, cb, ab, hb);
            arr(c.second, p);
            return fcl_peer::point_apart_obb(p, cb, ab, hb);
        });
    }
    linear_distance_tiers<line3, line3>("line_line", near);
    linear_distance_tiers<line3, point3>("line_point", near);
    linear_distance_tiers<line3, ray3>("line_ray", near);
    linear_distance_tiers<line3, segment3>("line_segment", near);
    linear_distance_tiers<point3, point3>("point_point", near);
    linear_distance_tiers<point3, ray3>("point_ray", near);
    linear_distance_tiers<point3, segment3>("point_segment", near);
    linear_distance_tiers<ray3, ray3>("ray_ray", near);
    linear_distance_tiers<ray3, segment3>("ray_segment", near);
    linear_distance_tiers<segment3, segment3>("segment_segment", near);
    linear_distance_tiers<line3, triangle3>("line_triangle", near);
    linear_distance_tiers<point3, triangle3>("point_triangle", near);
    linear_distance_tiers<ray3, triangle3>("ray_triangle", near);
    linear_distance_tiers<segment3, triangle3>("segment_triangle", near);
    linear_distance_tiers<triangle3, triangle3>("triangle_triangle", near);
    {
        // a mesh: the store outlives the view each case holds
        struct mesh_case {
            support::mesh_store m;
            point3 p;
        };
        support::rng r = set_rng(near);
        std::vector<mesh_case> cs;
        while (cs.size() < set_size / 8) { // 48 to 96 triangles each
            mesh_case c;
            if (near) c.p = support::segment_in_mesh_near(r, c.m).a;
            else c.p = support::random_mesh_and_box_points(r, c.m)();
            if (is_finite(c.p)) cs.push_back(std::move(c));
        }
        auto truth = [](const mesh_case& c) {
            const oracle::mesh_data data = support::mesh_data_of(c.m.view());
            oracle::distance_solid s{oracle::distance_solid::mesh, {}, {}};
            s.mesh_ptr = &data;
            return oracle::check_distance(s, support::a3(c.p), false, 0.0, 0.0, 0.0, 0.0).sign >= 0;
        };
        tiers(
            "mesh_point", near ? "near_degenerate" : "random", cs, truth,
            [](auto tier, const mesh_case& c) { return not_inside<decltype(tier)>(signed_distance<decltype(tier)>(c.m.view(), c.p)); },
            "distance");
    }
}

} // namespace bench
