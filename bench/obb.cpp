// Benchmarks: the OBB pairs (tests/support/obb_cases.hpp) against the LP, with the Gottschalk SAT and FCL beside obb_obb.
#include "bench.hpp"

namespace bench {
void register_obb(bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    {
        const auto cs = obb_tiers<obb3, obb3>("obb_obb", near);
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(oracle::lp_intersect(support::lp(c.first), support::lp(c.second)));
        reg("gottschalk/intersects/obb_obb/" + dist, cs, t, check::approximate,
            [](const std::pair<obb3, obb3>& c) { return method::obb_obb_gottschalk(c.first, c.second); });
        reg("fcl/intersects/obb_obb/" + dist, cs, t, check::approximate, [](const std::pair<obb3, obb3>& c) {
            double ca[3], aa[9], ha[3], cb[3], ab[9], hb[3];
            obb_arrays(c.first, ca, aa, ha), obb_arrays(c.second, cb, ab, hb);
            return fcl_peer::obb_obb(ca, aa, ha, cb, ab, hb);
        });
        (void)obb_tiers<aabb3, obb3>("aabb_obb", near);
        (void)obb_tiers<obb3, point3>("obb_point", near);
        (void)obb_tiers<obb3, segment3>("obb_segment", near);
        (void)obb_tiers<obb3, ray3>("obb_ray", near);
        (void)obb_tiers<line3, obb3>("line_obb", near);
        (void)obb_tiers<obb3, triangle3>("obb_triangle", near);
        (void)obb_tiers<obb3, plane3>("obb_plane", near);
        (void)obb_tiers<obb3, tetrahedron3>("obb_tetrahedron", near);
        mesh_tiers<obb3>("mesh_obb", near);
    }
}
} // namespace bench
