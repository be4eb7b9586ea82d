// Rays against boxes and balls: one ray against many, batch::intersects<Tier>(ray, boxes or balls,
// out), and many rays against one, batch::intersects<Tier>(rays, box or ball, out) (the
// bounding-volume hierarchy's node test for a packet of rays), each many as an array or a
// structure-of-arrays packet (boxes_soa, spheres_soa, rays_soa). out[i] is 1 where the pair i
// meets, else 0: the answer of the scalar intersects<Tier>(ray, box or ball), bit for bit, in every
// tier (tests/batch/ray_solids.cpp checks it on every SIMD target).
// Method (ray_solids_simd.cpp): the approximate tier runs the scalar approximate method in lanes
// (the slab method, Kay and Kajiya, SIGGRAPH 1986; the geometric ray-sphere method, Real-Time
// Rendering 4th ed., section 22.6.2); the filtered tiers run the scalar filter's first stage in
// lanes (the box: the slab parameters with their proven error; the ball: its three signs, degree 2
// to 4, against a block's static bound and the lanes' own) and ask the scalar query of the tier
// for a lane it leaves open.
module;
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>
export module incidence.batch:ray_solids;
import incidence.core;
import incidence.shapes;
import incidence.query;
import :lanes;
import :ray_triangles;
import :solids;

// The SIMD kernels (ray_solids_simd.cpp). ray: six fields (origin x, y, z, direction x, y, z), box
// six, ball four; `rays` true: the ray's fields are arrays of n and the solid's one value each,
// false: the other way. filter = false: the approximate tier (1 or 0); true: the filter's first
// stage, 2 where it leaves the lane to the scalar query.
extern "C++" {
namespace incidence::batch::simd {
void ray_boxes(const double* const* ray, bool rays, const double* const* box, std::size_t n, bool filter, std::uint8_t* out);
void ray_balls(const double* const* ray, bool rays, const double* const* ball, std::size_t n, bool filter, std::uint8_t* out);
} // namespace incidence::batch::simd
}

namespace incidence::batch::detail {

inline void arrays(const rays_soa& r, const double** p) {
    const double* v[6] = {r.ox.data(), r.oy.data(), r.oz.data(), r.dx.data(), r.dy.data(), r.dz.data()};
    for (int k = 0; k < 6; ++k) p[k] = v[k];
}

// n lanes: the kernel of the tier on the ray's fields and the solid's (one side arrays of n, the
// other one value each), then the scalar query where the filter left a lane open.
template <tier Tier, class Solid, class At>
std::size_t ray_solid_block(const double* const* ray, bool rays, const double* const* solid, std::size_t n, std::uint8_t* out,
                            const At& pair) {
    constexpr bool filter = !std::is_same_v<Tier, approximate>;
    if constexpr (std::is_same_v<Solid, aabb3>) simd::ray_boxes(ray, rays, solid, n, filter, out);
    else simd::ray_balls(ray, rays, solid, n, filter, out);
    return settle_open(out, n, [&](std::size_t i) {
        const auto [r, s] = pair(i);
        return incidence::intersects<Tier>(r, s);
    });
}
template <tier Tier, class Solid>
result<std::size_t> ray_many(const ray3& r, std::span<const Solid> many, std::span<std::uint8_t> out) {
    if (out.size() != many.size()) return error{errc::size_mismatch};
    const one_fields<ray3> ray(r);
    return by_blocks<fields_of<Solid>>(
        many, out.data(), [](const Solid& s, double* f) { unpack(s, f); },
        [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return ray_solid_block<Tier, Solid>(ray.p, false, coords, n, o, [&](std::size_t i) { return std::pair{r, many[start + i]}; });
        });
}
template <tier Tier, class Soa>
result<std::size_t> ray_many(const ray3& r, const Soa& many, std::span<std::uint8_t> out) {
    if (!many.consistent() || out.size() != many.size()) return error{errc::size_mismatch};
    using Solid = std::remove_cvref_t<decltype(many[0])>;
    const one_fields<ray3> ray(r);
    const double* p[6] = {};
    arrays(many, p);
    return ray_solid_block<Tier, Solid>(ray.p, false, p, many.size(), out.data(), [&](std::size_t i) { return std::pair{r, many[i]}; });
}
template <tier Tier, class Solid>
result<std::size_t> many_rays(std::span<const ray3> rays, const Solid& s, std::span<std::uint8_t> out) {
    if (out.size() != rays.size()) return error{errc::size_mismatch};
    const one_fields<Solid> solid(s);
    return by_blocks<6>(
        rays, out.data(), [](const ray3& r, double* f) { unpack(r, f); },
        [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return ray_solid_block<Tier, Solid>(coords, true, solid.p, n, o, [&](std::size_t i) { return std::pair{rays[start + i], s}; });
        });
}
template <tier Tier, class Solid>
result<std::size_t> many_rays(const rays_soa& rays, const Solid& s, std::span<std::uint8_t> out) {
    if (!rays.consistent() || out.size() != rays.size()) return error{errc::size_mismatch};
    const one_fields<Solid> solid(s);
    const double* p[6] = {};
    arrays(rays, p);
    return ray_solid_block<Tier, Solid>(p, true, solid.p, rays.size(), out.data(), [&](std::size_t i) { return std::pair{rays[i], s}; });
}

} // namespace incidence::batch::detail

export namespace incidence::batch {

// Does the ray meet each box (ball)? out[i] for many[i] (out as long as many); the number met.
// Tiers as the scalar intersects(ray, box or ball): the same answer, lane by lane.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, std::span<const aabb3> boxes, std::span<std::uint8_t> out) {
    return detail::ray_many<Tier>(r, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, const boxes_soa& boxes, std::span<std::uint8_t> out) {
    return detail::ray_many<Tier>(r, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, std::span<const sphere3> balls, std::span<std::uint8_t> out) {
    return detail::ray_many<Tier>(r, balls, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const ray3& r, const spheres_soa& balls, std::span<std::uint8_t> out) {
    return detail::ray_many<Tier>(r, balls, out);
}
// Does each ray meet the box (ball)? out[i] for rays[i]; the number of rays that meet it.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(std::span<const ray3> rays, const aabb3& b, std::span<std::uint8_t> out) {
    return detail::many_rays<Tier>(rays, b, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const rays_soa& rays, const aabb3& b, std::span<std::uint8_t> out) {
    return detail::many_rays<Tier>(rays, b, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(std::span<const ray3> rays, const sphere3& s, std::span<std::uint8_t> out) {
    return detail::many_rays<Tier>(rays, s, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const rays_soa& rays, const sphere3& s, std::span<std::uint8_t> out) {
    return detail::many_rays<Tier>(rays, s, out);
}

} // namespace incidence::batch
