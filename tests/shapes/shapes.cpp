// Every checked constructor's error, with its message; accepted shapes round-trip their members.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <array>
#include <span>
#include <cmath>
#include <limits>
#include <string>
import incidence;

namespace test_shapes_shapes { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
constexpr double nan_ = std::numeric_limits<double>::quiet_NaN();
constexpr double inf_ = std::numeric_limits<double>::infinity();
template <class R>
void refused(const R& r, errc code) {
    REQUIRE_FALSE(r.has_value());
    CHECK(r.error().code == code);
    CHECK(std::string(r.error().message()).size() > 10);
}
} // namespace

TEST_CASE("shapes: make() reports why input is invalid", "[shapes]") {
    refused(ray3::make({nan_, 0, 0}, {1, 0, 0}), errc::not_finite);
    refused(ray3::make({0, 0, 0}, {inf_, 0, 0}), errc::not_finite);
    refused(ray3::make({0, 0, 0}, {0, 0, 0}), errc::zero_direction);
    refused(line3::make({0, 0, 0}, {0, 0, 0}), errc::zero_direction);
    refused(line3::make({0, -inf_, 0}, {1, 0, 0}), errc::not_finite);
    refused(segment3::make({0, 0, 0}, {0, 0, 0}), errc::degenerate_segment);
    refused(segment3::make({0, 0, nan_}, {0, 0, 0}), errc::not_finite);
    refused(plane3::make({0, 0, 0}, 1), errc::zero_normal);
    refused(plane3::make({0, 0, 1}, nan_), errc::not_finite);
    refused(sphere3::make({0, 0, 0}, -1), errc::negative_radius);
    refused(capsule3::make({0, 0, 0}, {1, 1, 1}, -1), errc::negative_radius);
    refused(capsule3::make({0, 0, 0}, {1, 1, 1}, nan_), errc::not_finite);
    refused(capsule3::make({0, 0, inf_}, {1, 1, 1}, 1), errc::not_finite);
    CHECK(capsule3::make({0, 0, 0}, {0, 0, 0}, 0).has_value()); // a point
    refused(sphere3::make({0, 0, 0}, nan_), errc::not_finite);
    refused(aabb3::make({0, 0, 1}, {1, 1, 0}), errc::inverted_box);
    refused(aabb3::make({0, 0, 0}, {1, inf_, 1}), errc::not_finite);
    refused(triangle3::make({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), errc::degenerate_triangle);
    refused(triangle3::make({0, 0, 0}, {0, 0, 0}, {0, 0, 0}), errc::degenerate_triangle);
    refused(triangle3::make({0, 0, 0}, {1, 0, 0}, {nan_, 0, 0}), errc::not_finite);
    // collinear by exact arithmetic, not by a tolerance: one ulp off is a valid triangle
    CHECK(triangle3::make({0, 0, 0}, {1, 1, 1}, {2, 2, std::nextafter(2.0, 3.0)}).has_value());
    refused(triangle3::make({0.1, 0.2, 0.3}, {0.2, 0.4, 0.6}, {0.4, 0.8, 1.2}), errc::degenerate_triangle);
    CHECK(sphere3::make({0, 0, 0}, 0).has_value());
    CHECK(aabb3::make({0, 0, 0}, {0, 0, 0}).has_value());
    // half-space sets
    const std::array<plane3, 2> two{plane3{{1, 0, 0}, 1}, plane3{{0, 0, 0}, 1}};
    refused(convex_polyhedron3::make(std::span<const plane3>(two.data(), 0)), errc::empty_input);
    refused(convex_polyhedron3::make(two), errc::zero_normal);
    refused(convex_polyhedron3::make(std::array<plane3, 1>{plane3{{1, 0, 0}, nan_}}), errc::not_finite);
    refused(convex_polyhedron3::make(std::array<plane3, 33>{}), errc::too_large);
    CHECK(convex_polyhedron3::make(std::span<const plane3>(two.data(), 1)).value().count == 1);
    std::array<plane3, 6> six{};
    for (unsigned i = 0; i < 6; ++i) six[i] = plane3{{0, 0, 1}, double(i)};
    CHECK(frustum3::make(six).has_value());
    six[4].normal = {0, 0, 0};
    refused(frustum3::make(six), errc::zero_normal);
    // cameras
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 1, 1, 1, 10), errc::zero_direction);
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 0, 2}, 1, 1, 1, 10), errc::up_parallel_to_forward);
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 0, 0}, 1, 1, 1, 10), errc::up_parallel_to_forward);
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 0, 1, 1, 10), errc::invalid_field_of_view);
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 3.2, 1, 1, 10), errc::invalid_field_of_view);
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1, -1, 1, 10), errc::invalid_field_of_view);
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1, 1, 0, 10), errc::invalid_clip_range);
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1, 1, 10, 10), errc::invalid_clip_range);
    refused(frustum3::from_camera({nan_, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1, 1, 1, 10), errc::not_finite);
    refused(frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1, 1, 1, inf_), errc::not_finite);
    refused(frustum3::from_camera({1e308, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1, 1, 1.7e308), errc::out_of_range);
    // a huge or subnormal forward vector is a direction like any other
    const auto tiny_forward = frustum3::from_camera({0, 0, 0}, {0, 0, -0x1p-1074}, {0, 1e300, 0}, 1.5, 1.25, 0.5, 8);
    const auto unit_forward = frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1.5, 1.25, 0.5, 8);
    REQUIRE(tiny_forward.has_value());
    REQUIRE(unit_forward.has_value());
    for (unsigned i = 0; i < 6; ++i) {
        CHECK(tiny_forward.value().planes[i].normal == unit_forward.value().planes[i].normal);
        CHECK(tiny_forward.value().planes[i].offset == unit_forward.value().planes[i].offset);
    }
}

TEST_CASE("shapes: a camera frustum's planes bound its view volume", "[shapes]") {
    // eye (1, 2, 3) looking along +x, up +z, 60 degrees vertically, aspect 2, near 0.5, far 20
    const double fov = 1.0471975511965976, a = std::tan(fov / 2), b = 2 * a;
    const auto f = frustum3::from_camera({1, 2, 3}, {4, 0, 0}, {0, 0, 0.5}, fov, 2.0, 0.5, 20);
    REQUIRE(f.has_value());
    auto side = [&](point3 p) { // the largest n . p - offset over the planes, relative to the scale
        double m = -1e300;
        for (const auto& pl : f.value().planes) m = std::max(m, dot(pl.normal, p - point3{0, 0, 0}) - pl.offset);
        return m;
    };
    // right = f x up = (1, 0, 0) x (0, 0, 1) = (0, -1, 0): the view volume's corners, then points
    // just inside and just outside each face
    for (double z : {0.5, 20.0})
        for (double sx : {-1.0, 1.0})
            for (double sy : {-1.0, 1.0}) {
                const point3 corner{1 + z, 2 - sx * b * z, 3 + sy * a * z};
                CHECK(std::fabs(side(corner)) < 1e-12 * (1 + z));
                const point3 inward{1 + z * (z < 1 ? 1.01 : 0.99), 2 - sx * b * z * 0.98, 3 + sy * a * z * 0.98};
                CHECK(side(inward) < 0);
                CHECK(side(point3{1 + z, 2 - sx * b * z * 1.01, 3}) > 0);
                CHECK(side(point3{1 + z, 2, 3 + sy * a * z * 1.01}) > 0);
            }
    CHECK(side(point3{1.49, 2, 3}) > 0);  // before the near plane
    CHECK(side(point3{21.01, 2, 3}) > 0); // beyond the far plane
    CHECK(side(point3{1, 2, 3}) > 0);     // the eye
}

TEST_CASE("shapes: accepted shapes keep their members, and make() is constexpr", "[shapes]") {
    const auto r = ray3::make({1, 2, 3}, {0, 0, 1});
    REQUIRE(r);
    CHECK(r.value().origin == point3{1, 2, 3});
    CHECK(r.value().at(2.0) == point3{1, 2, 5});
    static_assert(sphere3::make({0, 0, 0}, 1).has_value());
    static_assert(!aabb3::make({1, 0, 0}, {0, 0, 0}).has_value());
    static_assert(triangle3::make({0, 0, 0}, {1, 0, 0}, {0, 1, 0}).has_value());
    static_assert(!triangle3::make({0, 0, 0}, {1, 0, 0}, {2, 0, 0}).has_value());
}

} // namespace test_shapes_shapes
