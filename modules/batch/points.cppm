// Many points against one solid, the inside tests: batch::intersects<Tier>(solid, points, out) for
// a box, a sphere or a tetrahedron, for points as an array of point3 or as a
// structure-of-arrays packet (points_soa). out[i] is 1 where point i lies in the closed box or
// ball or solid tetrahedron, else 0: the answer of the scalar intersects<Tier>(solid, point), bit for
// bit, in every tier (tests/batch/points.cpp checks it on every SIMD target).
// Method (points_simd.cpp): the box by the scalar body's six comparisons, exact in every tier;
// the ball by the sign of r r - |p - c|^2 (degree 2), in plain double for the approximate tier,
// and in the filtered tiers in the semi-static filter against a static bound per block of 64
// points, then each lane's own bound, then the scalar query for a lane still open; the
// tetrahedron by its bounding box, then the signs of the four volumes with the point in place of
// one vertex (degree 3; Ericson, Real-Time Collision Detection, 2005, section 3.4), the same way.
module;
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
export module incidence.batch:points;
import incidence.core;
import incidence.shapes;
import incidence.query;
import :lanes;

// The SIMD kernels (points_simd.cpp). The n points: coords, three arrays of n coordinates (x, y,
// z), or, where xyz is not null, xyz, 3 n coordinates interleaved point after point. box: min.x,
// min.y, min.z, max.x, max.y, max.z. The filter writes 2 where it could not prove the sign.
extern "C++" {
namespace incidence::batch::simd {
void box_points(const double* box, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out);
void sphere_points_approximate(const double* center, double radius, const double* const* coords, const double* xyz, std::size_t n,
                               std::uint8_t* out);
void sphere_points_filter(const double* center, double radius, const double* const* coords, const double* xyz, std::size_t n,
                          std::uint8_t* out);
// t: the vertices a, b, c, d, three coordinates each. Both write 2 where the scalar query decides.
void tetrahedron_points_approximate(const double* t, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out);
void tetrahedron_points_filter(const double* t, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out);
} // namespace incidence::batch::simd
}

export namespace incidence::batch {

// Points kept as structure of arrays: three arrays of one length, point i being {x[i], y[i], z[i]}.
struct points_soa {
    std::span<const double> x, y, z;
    [[nodiscard]] constexpr std::size_t size() const { return x.size(); }
    [[nodiscard]] constexpr bool consistent() const { return y.size() == x.size() && z.size() == x.size(); }
    [[nodiscard]] constexpr point3 operator[](std::size_t i) const { return {x[i], y[i], z[i]}; }
};

} // namespace incidence::batch

namespace incidence::batch::detail {

template <tier Tier, class At>
std::size_t box_points_block(const aabb3& b, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out,
                             const At& at) {
    const double box[6] = {b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z};
    simd::box_points(box, coords, xyz, n, out); // comparisons: the same answer in every tier, no lane open
    return settle_open(out, n, [&](std::size_t i) { return incidence::intersects<Tier>(b, at(i)); });
}

template <tier Tier, class At>
std::size_t sphere_points_block(const sphere3& s, const double* const* coords, const double* xyz, std::size_t n, std::uint8_t* out,
                                const At& at) {
    const double c[3] = {s.center.x, s.center.y, s.center.z};
    if constexpr (std::is_same_v<Tier, approximate>) simd::sphere_points_approximate(c, s.radius, coords, xyz, n, out);
    else simd::sphere_points_filter(c, s.radius, coords, xyz, n, out);
    return settle_open(out, n, [&](std::size_t i) { return incidence::intersects<Tier>(at(i), s); });
}

template <tier Tier, class At>
std::size_t tetrahedron_points_block(const tetrahedron3& t, const double* const* coords, const double* xyz, std::size_t n,
                                     std::uint8_t* out, const At& at) {
    if (!is_finite(t.a) || !is_finite(t.b) || !is_finite(t.c) ||
        !is_finite(t.d)) { // no point is in it, in every tier (the scalar query's first test)
        std::memset(out, 0, n);
        return 0;
    }
    const double v[12] = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z, t.d.x, t.d.y, t.d.z};
    if constexpr (std::is_same_v<Tier, approximate>) simd::tetrahedron_points_approximate(v, coords, xyz, n, out);
    else simd::tetrahedron_points_filter(v, coords, xyz, n, out);
    return settle_open(out, n, [&](std::size_t i) { return incidence::intersects<Tier>(at(i), t); });
}

// A solid against an array of points, copied 64 at a time into doubles on the stack (a point3 is
// three doubles: the kernels read them interleaved), or against a packet.
template <class Block>
result<std::size_t> over_points(std::span<const point3> points, std::span<std::uint8_t> out, const Block& run) {
    static_assert(sizeof(point3) == 3 * sizeof(double));
    if (out.size() != points.size()) return error{errc::size_mismatch};
    double xyz[3 * block];
    const double* none[3] = {};
    std::size_t met = 0;
    for (std::size_t start = 0; start < points.size(); start += block) {
        const std::size_t n = points.size() - start < block ? points.size() - start : block;
        std::memcpy(xyz, points.data() + start, n * sizeof(point3));
        met += run(none, xyz, n, out.data() + start, [&](std::size_t i) { return points[start + i]; });
    }
    return met;
}
template <class Block>
result<std::size_t> over_points(const points_soa& points, std::span<std::uint8_t> out, const Block& run) {
    if (!points.consistent() || out.size() != points.size()) return error{errc::size_mismatch};
    const double* coords[3] = {points.x.data(), points.y.data(), points.z.data()};
    return run(coords, nullptr, points.size(), out.data(), [&](std::size_t i) { return points[i]; });
}

} // namespace incidence::batch::detail

export namespace incidence::batch {

// Does each point lie in the closed box (or ball)? out[i] for points[i] (out as long as points);
// the number inside. Tiers as the scalar intersects: the same answer, lane by lane.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const aabb3& b, std::span<const point3> points, std::span<std::uint8_t> out) {
    return detail::over_points(points, out, [&](const double* const* c, const double* xyz, std::size_t n, std::uint8_t* o, const auto& at) {
        return detail::box_points_block<Tier>(b, c, xyz, n, o, at);
    });
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const aabb3& b, const points_soa& points, std::span<std::uint8_t> out) {
    return detail::over_points(points, out, [&](const double* const* c, const double* xyz, std::size_t n, std::uint8_t* o, const auto& at) {
        return detail::box_points_block<Tier>(b, c, xyz, n, o, at);
    });
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const sphere3& s, std::span<const point3> points, std::span<std::uint8_t> out) {
    return detail::over_points(points, out, [&](const double* const* c, const double* xyz, std::size_t n, std::uint8_t* o, const auto& at) {
        return detail::sphere_points_block<Tier>(s, c, xyz, n, o, at);
    });
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const sphere3& s, const points_soa& points, std::span<std::uint8_t> out) {
    return detail::over_points(points, out, [&](const double* const* c, const double* xyz, std::size_t n, std::uint8_t* o, const auto& at) {
        return detail::sphere_points_block<Tier>(s, c, xyz, n, o, at);
    });
}

template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const tetrahedron3& t, std::span<const point3> points, std::span<std::uint8_t> out) {
    return detail::over_points(points, out, [&](const double* const* c, const double* xyz, std::size_t n, std::uint8_t* o, const auto& at) {
        return detail::tetrahedron_points_block<Tier>(t, c, xyz, n, o, at);
    });
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const tetrahedron3& t, const points_soa& points, std::span<std::uint8_t> out) {
    return detail::over_points(points, out, [&](const double* const* c, const double* xyz, std::size_t n, std::uint8_t* o, const auto& at) {
        return detail::tetrahedron_points_block<Tier>(t, c, xyz, n, o, at);
    });
}

} // namespace incidence::batch
