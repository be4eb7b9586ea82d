// Containment of a point set in an obb3 (and the shared OBB construction test), checked with CGAL's exact rationals (independent of the
// library's predicates). Include after the oracle header, `import incidence;` and testing.hpp.
#pragma once
#include <span>
#include <vector>

namespace support {
inline bool all_inside(std::span<const incidence::point3> pts, const incidence::obb3& b) {
    std::vector<double> v;
    for (const auto& p : pts) v.insert(v.end(), {p.x, p.y, p.z});
    const double c[3] = {b.center.x, b.center.y, b.center.z};
    const double a[9] = {b.axes[0].x, b.axes[0].y, b.axes[0].z, b.axes[1].x, b.axes[1].y,
                         b.axes[1].z, b.axes[2].x, b.axes[2].y, b.axes[2].z};
    return oracle::all_in_box(v.data(), pts.size(), c, a, b.half_extents.data());
}
// One OBB construction (`build(points)` -> result<obb3>) on every generated and real set: every
// point inside (CGAL rationals and the library's exact test), axes accepted by obb3::make,
// volume against CGAL's oriented_bounding_box printed, clear errors for empty and NaN input.
// Include point_sets.hpp and Catch2 first.
// `refusal` is the one other error allowed (a construction's size limit), besides overflow.
template <class Build>
void check_obb_construction(const char* name, Build build, incidence::errc refusal = incidence::errc::out_of_range) {
    using namespace incidence;
    support::rng r(support::seed());
    auto sets = support::point_sets(r, support::cases(1000));
    auto meshes = support::real_meshes();
    if (support::meshes_required()) REQUIRE(meshes.size() == 5);
    for (auto& m : meshes) sets.push_back(std::move(m));
    for (const auto& s : sets) {
        INFO(s.name);
        const std::span<const point3> pts(s.points);
        const auto b = build(pts);
        if (!b) { // only overflow may refuse: coordinates near 1e300 whose box extents overflow
            CHECK((b.error().code == errc::out_of_range || b.error().code == refusal));
            std::printf("[cases] %s %s: %s\n", name, s.name.c_str(), b.error().message());
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
            std::printf("[cases] %s %s: volume / hull %.4f, / CGAL oriented_bounding_box %.4f\n", name, s.name.c_str(),
                        bound::volume(box) / hv, bound::volume(box) / cgal);
        }
    }
    CHECK(build(std::span<const point3>()).error().code == errc::empty_input);
    const point3 nan_pt[] = {{0, 0, 0}, {__builtin_nan(""), 0, 0}};
    CHECK(build(std::span<const point3>(nan_pt)).error().code == errc::not_finite);
}
} // namespace support
