// One ray against many triangles: batch::intersects<Tier>(ray, triangles, out), for triangles as
// an array of triangle3 or as a structure-of-arrays packet (triangles_soa); and many rays against
// one triangle: batch::intersects<Tier>(rays, triangle, out), rays as an array of ray3 or a packet
// (rays_soa). out[i] is 1 where the ray meets triangle i (ray i meets the triangle), else 0: the
// answer of the scalar intersects<Tier>(ray, triangle), bit for bit, in every tier
// (tests/batch/ray_triangles.cpp checks it on every SIMD target). And the first hit of one ray
// among many triangles: batch::intersection<Tier>(ray, triangles), the hit intersection<Tier>(ray,
// scene) finds in a scene of the same triangles (tests/batch/ray_triangles.cpp checks that too).
// Triangles kept in floats (triangles_soa_f): the same answers in the filtered tiers, and an
// approximate tier in float lanes with its own stated bound (float_approximate_bound, below).
// Method: the lanes run the scalar algorithm's operations in SIMD (ray_triangles_simd.cpp):
// - approximate: the watertight test (Woop, Benthin and Wald, JCGT 2(1), 2013), the scalar
//   approximate tier's, with its bound (catalog: ray_triangle);
// - exact, conservative, aggressive: the five signs of the scalar filter's first decision in the
//   semi-static filter, against a static bound per block of 64 triangles (the largest differences
//   of the block: one comparison per sign and lane) and, where that leaves a lane open, against
//   the lane's own bound; a lane left open still asks the scalar query of the same tier
//   (bench/NOTES.md, "Batches", has the measured shares and times).
// No heap allocation: an array of triangles is transposed 64 at a time into the stack (lanes.cppm).
module;
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
export module incidence.batch:ray_triangles;
import incidence.core;
import incidence.shapes;
import incidence.query;
import incidence.scene;
import :lanes;

// The SIMD kernels (ray_triangles_simd.cpp, compiled for every target Highway knows; the best one
// the processor has runs). coords: nine arrays of n coordinates (a.x, a.y, a.z, b.x, ..., c.z).
// watertight writes 1 or 0; filter writes 1 or 0 where its signs are proven and 2 where not.
extern "C++" {
namespace incidence::batch::simd {
void ray_triangles_watertight(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out);
void ray_triangles_filter(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out);
// rays: six arrays of n coordinates (origin x, y, z, direction x, y, z); triangle: nine fields of
// one value each (a.x, ..., c.z).
void rays_triangle_watertight(const double* const* rays, const double* const* triangle, std::size_t n, std::uint8_t* out);
// The watertight test in float lanes: one ray (floats) against n triangles (nine arrays of floats).
void ray_triangles_watertight_float(const float* origin, const float* direction, const float* const* coords, std::size_t n,
                                    std::uint8_t* out);
void rays_triangle_filter(const double* const* rays, const double* const* triangle, std::size_t n, std::uint8_t* out);
const char* target_name();
} // namespace incidence::batch::simd
}

export namespace incidence::batch {

// Triangles kept as structure of arrays: nine arrays of one length, triangle i being
// {ax[i], ay[i], az[i]}, {bx[i], ...}, {cx[i], ...}; of doubles (triangles_soa) or of floats
// (triangles_soa_f, whose coordinates widen to double exactly).
template <class T>
struct basic_triangles_soa {
    std::span<const T> ax, ay, az, bx, by, bz, cx, cy, cz;
    [[nodiscard]] constexpr std::size_t size() const { return ax.size(); }
    [[nodiscard]] constexpr bool consistent() const {
        const std::size_t n = ax.size();
        return ay.size() == n && az.size() == n && bx.size() == n && by.size() == n && bz.size() == n && cx.size() == n && cy.size() == n &&
               cz.size() == n;
    }
    [[nodiscard]] constexpr triangle3 operator[](std::size_t i) const {
        return {{ax[i], ay[i], az[i]}, {bx[i], by[i], bz[i]}, {cx[i], cy[i], cz[i]}};
    }
    [[nodiscard]] constexpr std::array<const T*, 9> arrays() const {
        return {ax.data(), ay.data(), az.data(), bx.data(), by.data(), bz.data(), cx.data(), cy.data(), cz.data()};
    }
};
using triangles_soa = basic_triangles_soa<double>;
using triangles_soa_f = basic_triangles_soa<float>;

// Rays kept as structure of arrays: six arrays of one length, ray i being
// {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}}.
struct rays_soa {
    std::span<const double> ox, oy, oz, dx, dy, dz;
    [[nodiscard]] constexpr std::size_t size() const { return ox.size(); }
    [[nodiscard]] constexpr bool consistent() const {
        const std::size_t n = ox.size();
        return oy.size() == n && oz.size() == n && dx.size() == n && dy.size() == n && dz.size() == n;
    }
    [[nodiscard]] constexpr ray3 operator[](std::size_t i) const { return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}}; }
};

// The name of the SIMD target the batches run on here ("AVX3" for AVX-512, "AVX2", "SSE4", ...).
[[nodiscard]] inline const char* simd_target() { return simd::target_name(); }

} // namespace incidence::batch

namespace incidence::batch::detail {

// One block of n lanes, SoA: the kernel of the tier, then the scalar query where the filter left a
// lane open. The number of lanes met.
template <tier Tier, class At>
std::size_t ray_triangles_block(const ray3& r, const double* const* coords, std::size_t n, std::uint8_t* out, const At& at) {
    const double o[3] = {r.origin.x, r.origin.y, r.origin.z};
    const double d[3] = {r.direction.x, r.direction.y, r.direction.z};
    if constexpr (std::is_same_v<Tier, approximate>) simd::ray_triangles_watertight(o, d, coords, n, out);
    else simd::ray_triangles_filter(o, d, coords, n, out);
    return settle_open(out, n, [&](std::size_t i) { return incidence::intersects<Tier>(r, at(i)); });
}

// The first hit's candidates, block by block (detail::triangles_first_hit): the triangles
// [start, start + n) copied out and the filter's lanes (0: the ray surely misses), from an array
// or from a packet.
struct first_hit_context {
    double origin[3], direction[3];
    const triangle3* array;
    const triangles_soa* packet;
};
inline void first_hit_candidates(const void* p, std::size_t start, std::size_t n, std::uint8_t* candidate, triangle3* triangles) {
    const auto& c = *static_cast<const first_hit_context*>(p);
    double buffer[9][block];
    const double* coords[9];
    for (std::size_t i = 0; i < n; ++i) {
        const triangle3 t = c.array != nullptr ? c.array[start + i] : (*c.packet)[start + i];
        triangles[i] = t;
        double v[9];
        unpack(t, v);
        for (int k = 0; k < 9; ++k) buffer[k][i] = v[k];
    }
    for (int k = 0; k < 9; ++k) coords[k] = buffer[k];
    simd::ray_triangles_filter(c.origin, c.direction, coords, n, candidate);
}
inline first_hit_context first_hit_of(const ray3& r, const triangle3* array, const triangles_soa* packet) {
    return {{r.origin.x, r.origin.y, r.origin.z}, {r.direction.x, r.direction.y, r.direction.z}, array, packet};
}
static_assert(incidence::detail::candidate_block <= block);

// n rays (six SoA arrays) against one triangle, the same way.
template <tier Tier, class At>
std::size_t rays_triangle_block(const double* const* rays, const triangle3& t, std::size_t n, std::uint8_t* out, const At& at) {
    const one_fields<triangle3> triangle(t);
    if constexpr (std::is_same_v<Tier, approximate>) simd::rays_triangle_watertight(rays, triangle.p, n, out);
    else simd::rays_triangle_filter(rays, triangle.p, n, out);
    return settle_open(out, n, [&](std::size_t i) { return incidence::intersects<Tier>(at(i), t); });
}

} // namespace incidence::batch::detail

export namespace incidence::batch {

// Does the ray meet each triangle? out[i] for triangles[i] (out must be as long as triangles);
// the number of triangles met. Tiers as the scalar intersects: the same answer, lane by lane.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, std::span<const triangle3> triangles, std::span<std::uint8_t> out) {
    if (out.size() != triangles.size()) return error{errc::size_mismatch};
    return detail::by_blocks<9>(
        triangles, out.data(), [](const triangle3& t, double* f) { detail::unpack(t, f); },
        [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return detail::ray_triangles_block<Tier>(r, coords, n, o, [&](std::size_t i) { return triangles[start + i]; });
        });
}

template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, const triangles_soa& triangles, std::span<std::uint8_t> out) {
    if (!triangles.consistent() || out.size() != triangles.size()) return error{errc::size_mismatch};
    const auto coords = triangles.arrays();
    return detail::ray_triangles_block<Tier>(r, coords.data(), triangles.size(), out.data(), [&](std::size_t i) { return triangles[i]; });
}

// The same for triangles kept in floats. The filtered tiers widen the coordinates to double (no
// rounding) and answer as for triangles_soa: the scalar answer, lane by lane. The approximate tier
// runs the watertight test in float lanes (twice as many per vector as double) where the ray's six
// numbers are floats too, and in double otherwise (then the scalar approximate answer). In float it
// is wrong only where one of the filter's deciding signs (the five of modules/engines/triangle.cppm's
// linear_triangle) lies within float_approximate_bound of its permanent, for inputs whose nonzero
// differences (a vertex minus the origin, an edge, the direction) have magnitudes in [2^-40, 2^40]
// (so that no product of three overflows or underflows float); tests/batch/ray_triangles.cpp
// checks it against the exact tier.
inline constexpr double float_approximate_bound = 0x1p-16;
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, const triangles_soa_f& triangles, std::span<std::uint8_t> out) {
    if (!triangles.consistent() || out.size() != triangles.size()) return error{errc::size_mismatch};
    const auto arrays = triangles.arrays();
    if constexpr (std::is_same_v<Tier, approximate>) {
        if (const auto ray = detail::floats_of(r)) {
            simd::ray_triangles_watertight_float(ray->data(), ray->data() + 3, arrays.data(), triangles.size(), out.data());
            return detail::settle_open(out.data(), triangles.size(), [](std::size_t) { return false; });
        }
    }
    return detail::widened_blocks<9>(
        arrays.data(), triangles.size(), out.data(), [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return detail::ray_triangles_block<Tier>(r, coords, n, o, [&](std::size_t i) { return triangles[start + i]; });
        });
}

// The first hit of the ray among the triangles: the least parameter, ties to the least index, as
// intersection<Tier>(ray, scene) over a scene of the same triangles defines it (t, point, normal,
// barycentrics and the triangle's index; exact correctly rounded, conservative and aggressive
// enclosures, approximate plain double with exists uncertain). The filter's lanes rule out the
// triangles the ray surely misses; the rest are weighed by the scene's search.
template <tier Tier = exact>
[[nodiscard]] result<std::optional<scene_hit<scene_value_t<Tier>>>> intersection(const ray3& r, std::span<const triangle3> triangles) {
    const detail::first_hit_context c = detail::first_hit_of(r, triangles.data(), nullptr);
    return incidence::detail::triangles_first_hit<Tier>(r, triangles.size(), detail::first_hit_candidates, &c);
}
template <tier Tier = exact>
[[nodiscard]] result<std::optional<scene_hit<scene_value_t<Tier>>>> intersection(const ray3& r, const triangles_soa& triangles) {
    if (!triangles.consistent()) return error{errc::size_mismatch};
    const detail::first_hit_context c = detail::first_hit_of(r, nullptr, &triangles);
    return incidence::detail::triangles_first_hit<Tier>(r, triangles.size(), detail::first_hit_candidates, &c);
}

// Does each ray meet the triangle? out[i] for rays[i] (out as long as rays); the number of rays
// that meet it. Tiers as the scalar intersects(ray, triangle): the same answer, lane by lane.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(std::span<const ray3> rays, const triangle3& t, std::span<std::uint8_t> out) {
    if (out.size() != rays.size()) return error{errc::size_mismatch};
    return detail::by_blocks<6>(
        rays, out.data(), [](const ray3& r, double* f) { detail::unpack(r, f); },
        [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return detail::rays_triangle_block<Tier>(coords, t, n, o, [&](std::size_t i) { return rays[start + i]; });
        });
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const rays_soa& rays, const triangle3& t, std::span<std::uint8_t> out) {
    if (!rays.consistent() || out.size() != rays.size()) return error{errc::size_mismatch};
    const double* coords[6] = {rays.ox.data(), rays.oy.data(), rays.oz.data(), rays.dx.data(), rays.dy.data(), rays.dz.data()};
    return detail::rays_triangle_block<Tier>(coords, t, rays.size(), out.data(), [&](std::size_t i) { return rays[i]; });
}

} // namespace incidence::batch
