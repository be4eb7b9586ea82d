// Benchmarks: the k-DOP pairs and the half-space pairs (convex_polyhedron3, frustum3; against a box
// or an oriented box also the frustum culling test (box only), the separating-axis and the
// decomposition tests in double), the LP as truth; a ball against them (frustum_sphere with the
// classic plane-by-plane culling test beside it), the exact QP as truth.
#include "bench.hpp"

namespace bench {
void register_halfspace(bool near) {
    kdop_tiers<14, point3>("kdop_point", near);
    kdop_tiers<14, segment3>("kdop_segment", near);
    kdop_tiers<14, ray3>("kdop_ray", near);
    kdop_tiers<14, line3>("kdop_line", near);
    kdop_tiers<26, ray3>("kdop_ray", near);
    kdop_tiers<14, kdop<14>>("kdop_kdop", near);
    kdop_tiers<26, kdop<26>>("kdop_kdop", near);
    kdop_tiers<14, aabb3>("aabb_kdop", near);
    kdop_tiers<14, plane3>("kdop_plane", near);
    kdop_tiers<14, triangle3>("kdop_triangle", near);
    kdop_tiers<26, triangle3>("kdop_triangle", near);
    kdop_tiers<14, tetrahedron3>("kdop_tetrahedron", near);
    kdop_tiers<26, tetrahedron3>("kdop_tetrahedron", near);
    kdop_tiers<26, plane3>("kdop_plane", near);
    kdop_tiers<14, obb3>("kdop_obb", near);
    kdop_tiers<26, obb3>("kdop_obb", near);
    halfspace_tiers<convex_polyhedron3, point3>("convex_polyhedron_point", near);
    halfspace_tiers<convex_polyhedron3, segment3>("convex_polyhedron_segment", near);
    halfspace_tiers<convex_polyhedron3, ray3>("convex_polyhedron_ray", near);
    halfspace_tiers<convex_polyhedron3, line3>("convex_polyhedron_line", near);
    halfspace_tiers<frustum3, point3>("frustum_point", near);
    halfspace_tiers<frustum3, segment3>("frustum_segment", near);
    halfspace_tiers<frustum3, ray3>("frustum_ray", near);
    halfspace_tiers<frustum3, line3>("frustum_line", near);
    halfspace_tiers<convex_polyhedron3, plane3>("convex_polyhedron_plane", near);
    halfspace_tiers<frustum3, plane3>("frustum_plane", near);
    halfspace_tiers<convex_polyhedron3, convex_polyhedron3>("convex_polyhedron_convex_polyhedron", near);
    halfspace_tiers<frustum3, convex_polyhedron3>("convex_polyhedron_frustum", near);
    halfspace_tiers<frustum3, frustum3>("frustum_frustum", near);
    halfspace_tiers<convex_polyhedron3, triangle3>("convex_polyhedron_triangle", near);
    halfspace_tiers<frustum3, triangle3>("frustum_triangle", near);
    halfspace_tiers<convex_polyhedron3, tetrahedron3>("convex_polyhedron_tetrahedron", near);
    halfspace_tiers<frustum3, tetrahedron3>("frustum_tetrahedron", near);
    halfspace_tiers<convex_polyhedron3, kdop<14>>("convex_polyhedron_kdop_14", near);
    halfspace_tiers<convex_polyhedron3, kdop<26>>("convex_polyhedron_kdop_26", near);
    halfspace_tiers<frustum3, kdop<14>>("frustum_kdop_14", near);
    halfspace_tiers<frustum3, kdop<26>>("frustum_kdop_26", near);
    halfspace_tiers<convex_polyhedron3, aabb3>("aabb_convex_polyhedron", near);
    halfspace_tiers<convex_polyhedron3, obb3>("convex_polyhedron_obb", near);
    ball_tiers<convex_polyhedron3>("convex_polyhedron_sphere", near);
    ball_tiers<kdop<14>>("kdop_sphere_14", near);
    ball_tiers<kdop<26>>("kdop_sphere_26", near);
    ball_flat_tiers<segment3>("segment_sphere", near);
    ball_flat_tiers<line3>("line_sphere", near);
    ball_flat_tiers<plane3>("plane_sphere", near);
    ball_flat_tiers<triangle3>("sphere_triangle", near);
    ball_flat_tiers<tetrahedron3>("sphere_tetrahedron", near);
    capsule_tiers<point3>("capsule_point", near);
    capsule_tiers<segment3>("capsule_segment", near);
    capsule_tiers<ray3>("capsule_ray", near);
    capsule_tiers<line3>("capsule_line", near);
    capsule_tiers<plane3>("capsule_plane", near);
    capsule_tiers<triangle3>("capsule_triangle", near);
    capsule_tiers<tetrahedron3>("capsule_tetrahedron", near);
    // FCL's capsule tests beside the exact tier (bench/fcl_peer.cpp), on the same cases
    const std::string dist = near ? "near_degenerate" : "random";
    {
        const auto set = capsule_tiers<sphere3>("capsule_sphere", near);
        reg("fcl/intersects/capsule_sphere/" + dist, set.cases, set.truth, check::approximate, [](const std::pair<capsule3, sphere3>& c) {
            double a[3], b[3], s[3];
            arr(c.first.a, a), arr(c.first.b, b), arr(c.second.center, s);
            return fcl_peer::capsule_sphere(a, b, std::fabs(c.first.radius), s, std::fabs(c.second.radius));
        });
    }
    {
        const auto set = capsule_tiers<capsule3>("capsule_capsule", near);
        reg("fcl/intersects/capsule_capsule/" + dist, set.cases, set.truth, check::approximate, [](const std::pair<capsule3, capsule3>& c) {
            double a1[3], b1[3], a2[3], b2[3];
            arr(c.first.a, a1), arr(c.first.b, b1), arr(c.second.a, a2), arr(c.second.b, b2);
            return fcl_peer::capsule_capsule(a1, b1, std::fabs(c.first.radius), a2, b2, std::fabs(c.second.radius));
        });
    }
    {
        const auto set = capsule_tiers<aabb3>("aabb_capsule", near);
        reg("fcl/intersects/aabb_capsule/" + dist, set.cases, set.truth, check::approximate, [](const std::pair<capsule3, aabb3>& c) {
            double a[3], b[3];
            arr(c.first.a, a), arr(c.first.b, b);
            const aabb3& x = c.second;
            const double cb[3] = {0.5 * x.min.x + 0.5 * x.max.x, 0.5 * x.min.y + 0.5 * x.max.y, 0.5 * x.min.z + 0.5 * x.max.z};
            const double hb[3] = {0.5 * x.max.x - 0.5 * x.min.x, 0.5 * x.max.y - 0.5 * x.min.y, 0.5 * x.max.z - 0.5 * x.min.z};
            static constexpr double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
            return fcl_peer::capsule_obb(a, b, std::fabs(c.first.radius), cb, identity, hb);
        });
    }
    {
        const auto set = capsule_tiers<obb3>("capsule_obb", near);
        reg("fcl/intersects/capsule_obb/" + dist, set.cases, set.truth, check::approximate, [](const std::pair<capsule3, obb3>& c) {
            double a[3], b[3], cb[3], ab[9], hb[3];
            arr(c.first.a, a), arr(c.first.b, b);
            obb_arrays(c.second, cb, ab, hb);
            return fcl_peer::capsule_obb(a, b, std::fabs(c.first.radius), cb, ab, hb);
        });
    }
    capsule_tiers<convex_polyhedron3>("capsule_convex_polyhedron", near);
    capsule_tiers<frustum3>("capsule_frustum", near);
    capsule_tiers<kdop<14>>("capsule_kdop_14", near);
    {
        const auto cs = ball_tiers<obb3>("obb_sphere", near);
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(intersects(c.first, c.second)); // the exact tier, checked against the QP above
        reg("closest_point/intersects/obb_sphere/" + dist, cs, t, check::approximate,
            [](const std::pair<obb3, sphere3>& c) { return method::obb_sphere_closest_point(c.first, c.second); });
        reg("fcl/intersects/obb_sphere/" + dist, cs, t, check::approximate, [](const std::pair<obb3, sphere3>& c) {
            double cb[3], ab[9], hb[3], cc[3];
            obb_arrays(c.first, cb, ab, hb);
            arr(c.second.center, cc);
            return fcl_peer::sphere_obb(cc, c.second.radius, cb, ab, hb);
        });
    }
    {
        const auto cs = ball_tiers<frustum3>("frustum_sphere", near);
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(intersects(c.first, c.second)); // the exact tier, checked against the QP above
        reg(std::string("plane_culling/intersects/frustum_sphere/") + (near ? "near_degenerate" : "random"), cs, t, check::approximate,
            [](const std::pair<frustum3, sphere3>& c) { return method::frustum_sphere_planes(c.first, c.second); });
    }
    {
        const auto cs = halfspace_tiers<frustum3, obb3>("frustum_obb", near);
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(oracle::lp_intersect(support::lp(c.first), support::lp(c.second)));
        reg(std::string("sat/intersects/frustum_obb/") + (near ? "near_degenerate" : "random"), cs, t, check::approximate,
            [](const std::pair<frustum3, obb3>& c) { return method::frustum_obb_sat(c.first, c.second); });
        reg(std::string("decomposition/intersects/frustum_obb/") + (near ? "near_degenerate" : "random"), cs, t, check::approximate,
            [](const std::pair<frustum3, obb3>& c) { return method::frustum_obb_decomposition(c.first, c.second); });
    }
    {
        const auto cs = halfspace_tiers<frustum3, aabb3>("aabb_frustum", near);
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(oracle::lp_intersect(support::lp(c.first), support::lp(c.second)));
        reg(std::string("culling/intersects/aabb_frustum/") + (near ? "near_degenerate" : "random"), cs, t, check::approximate,
            [](const std::pair<frustum3, aabb3>& c) { return method::aabb_frustum_culling(c.second, c.first); });
        reg(std::string("sat/intersects/aabb_frustum/") + (near ? "near_degenerate" : "random"), cs, t, check::approximate,
            [](const std::pair<frustum3, aabb3>& c) { return method::aabb_frustum_sat(c.second, c.first); });
        reg(std::string("decomposition/intersects/aabb_frustum/") + (near ? "near_degenerate" : "random"), cs, t, check::approximate,
            [](const std::pair<frustum3, aabb3>& c) { return method::aabb_frustum_decomposition(c.second, c.first); });
    }
}
} // namespace bench
