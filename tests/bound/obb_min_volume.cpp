// obb_min_volume: every point inside the returned box (CGAL exact rationals, and the library's exact test),
// axes orthonormal within 1e-6 (obb3::make accepts the box), on generated, degenerate and real
// point sets; the volume against CGAL's oriented_bounding_box on the real meshes (printed).
#include <catch2/catch_test_macros.hpp>
#include <span>
#include "../oracle/cgal_oracle.hpp"
import incidence;
#include "../support/testing.hpp"
#include "../support/point_sets.hpp"
#include "../support/box_checks.hpp"

using namespace incidence;

TEST_CASE("obb_min_volume: every generated and real set", "[bound][obb_min_volume]") {
    support::rng r(support::seed());
    auto sets = support::point_sets(r, support::cases(1000));
    auto meshes = support::real_meshes();
    if (support::meshes_required()) REQUIRE(meshes.size() == 5);
    for (auto& m : meshes) sets.push_back(std::move(m));
    for (const auto& s : sets) {
        INFO(s.name);
        const std::span<const point3> pts(s.points);
        const auto b = bound::obb_min_volume(pts);
        if (!b) { // only overflow may refuse: coordinates near 1e300 whose box extents overflow
            CHECK(b.error().code == errc::out_of_range);
            std::printf("[cases] obb_min_volume %s: %s\n", s.name.c_str(), b.error().message());
            continue;
        }
        const obb3 box = b.value();
        CHECK(obb3::make(box.center, box.axes, box.half_extents));
        CHECK(support::all_inside(pts, box));
        bool all = true;
        for (const point3& p : s.points) all = all && bound::contains(box, p);
        CHECK(all);
        std::vector<double> xyz;
        for (const auto& p : s.points) xyz.insert(xyz.end(), {p.x, p.y, p.z});
        double hv = 0, ha = 0, ms = 0;
        oracle::hull_volume_area(xyz.data(), s.points.size(), hv, ha);
        if (hv > 0 && s.points.size() > 1000) {
            const double cgal = oracle::obb_volume_cgal(xyz.data(), s.points.size(), ms);
            std::printf("[cases] obb_min_volume %s: volume / hull %.4f, / CGAL oriented_bounding_box %.4f\n", s.name.c_str(),
                        bound::volume(box) / hv, bound::volume(box) / cgal);
        }
    }
    CHECK(bound::obb_min_volume(std::span<const point3>()).error().code == errc::empty_input);
    const point3 nan_pt[] = {{0, 0, 0}, {__builtin_nan(""), 0, 0}};
    CHECK(bound::obb_min_volume(std::span<const point3>(nan_pt)).error().code == errc::not_finite);
}
