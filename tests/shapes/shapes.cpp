// Every checked constructor's error, with its message; accepted shapes round-trip their members.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>
#include <string>
import incidence;

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
