// Many boxes against one frustum (view-frustum culling): batch::intersects<Tier>(frustum, boxes,
// out) and batch::intersects<Tier>(boxes, frustum, out), for boxes as an array of aabb3 or a
// structure-of-arrays packet (boxes_soa), oriented boxes as obb3 or obbs_soa, and balls as sphere3 or
// spheres_soa. out[i] is 1 where boxes[i] meets the closed view volume,
// else 0: the answer of the scalar intersects<Tier>(frustum, boxes[i]), bit for bit, in every tier
// (tests/batch/culling.cpp checks it on every SIMD target).
// Method (culling_simd.cpp): the culling test's two outcomes in lanes (Assarsson and Moeller,
// "Optimized view frustum culling algorithms for bounding boxes", JGT 5(1), 2000, section 3): a
// plane with the box's corner least along its normal outside says no, the box's middle strictly
// inside every plane says yes (signs of degree 2); then a plane two of them imply along an
// edge-edge axis of the separating-axis test with the box wholly beyond it says no (degree 3). In
// plain double for the approximate tier, in the semi-static filter for the others. A box near the
// frustum's edges or corners that no stage decides (or whose sign the filter cannot prove) goes
// to the scalar query, whose exact linear program decides. An oriented box: the first two stages
// only, as its scalar query has them (a plane with the box's least value beyond it, degree 3; the
// centre inside every plane, degree 2). A ball: the first stage of its scalar query (the centre
// inside every plane says yes, degree 2; a plane with the whole ball beyond it says no, degree 4);
// the rest, a ball near the frustum's faces, edges and corners, to the scalar query's search for
// its nearest point (engines/ball_halfspaces.cppm).
module;
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
export module incidence.batch:culling;
import incidence.core;
import incidence.shapes;
import incidence.arith;
import incidence.detail;
import incidence.query;
import :lanes;
import :solids;

// The SIMD kernel (culling_simd.cpp): planes are the six planes as (n_x, n_y, n_z, c), edges the
// implied planes of halfspaces::edge_planes as (i, j, alpha, beta, upper_x, upper_y, upper_z),
// boxes six arrays of n (min x, y, z, max x, y, z); it writes 2 where a lane is left to the scalar
// query.
extern "C++" {
namespace incidence::batch::simd {
void frustum_boxes(const double* planes, const double* edges, int edge_count, const double* const* boxes, std::size_t n, bool filter,
                   std::uint8_t* out);
// obbs: fifteen arrays of n (centre x, y, z, axis 0 x, y, z, axis 1, axis 2, half extents 0, 1, 2).
void frustum_obbs(const double* planes, const double* const* obbs, std::size_t n, bool filter, std::uint8_t* out);
// balls: four arrays of n (centre x, y, z, radius).
void frustum_balls(const double* planes, const double* const* balls, std::size_t n, bool filter, std::uint8_t* out);
} // namespace incidence::batch::simd
}

namespace incidence::batch::detail {

// n boxes (their fields' arrays) against f: the kernel of the tier, then the scalar query where a
// lane is open. The number of boxes met.
template <tier Tier, class Box, class At>
std::size_t culling_block(const frustum3& f, const double* const* boxes, std::size_t n, std::uint8_t* out, const At& at) {
    double planes[24];
    for (unsigned p = 0; p < 6; ++p) {
        const plane3& h = f.planes[p];
        planes[4 * p] = h.normal.x, planes[4 * p + 1] = h.normal.y, planes[4 * p + 2] = h.normal.z, planes[4 * p + 3] = h.offset;
    }
    bool finite = true;
    for (const double v : planes) finite = finite && v - v == 0.0;
    if (!finite) {
        std::memset(out, 2, n); // no set: the scalar query says so without a sign
    } else if constexpr (std::is_same_v<Box, obb3>) {
        simd::frustum_obbs(planes, boxes, n, !std::is_same_v<Tier, approximate>, out);
    } else if constexpr (std::is_same_v<Box, sphere3>) {
        bool zero_normal = false; // a plane the scalar query leaves out (all of space, or none): to the scalar query
        for (unsigned p = 0; p < 6; ++p)
            zero_normal = zero_normal || (planes[4 * p] == 0.0 && planes[4 * p + 1] == 0.0 && planes[4 * p + 2] == 0.0);
        if (zero_normal) std::memset(out, 2, n);
        else simd::frustum_balls(planes, boxes, n, !std::is_same_v<Tier, approximate>, out);
    } else {
        // the implied planes, in the kernel of the scalar query's first pass
        const auto implied = [&] {
            if constexpr (std::is_same_v<Tier, approximate>) {
                arith::approx_kernel k;
                return incidence::detail::halfspaces::edge_planes(k, f.planes.data(), 6);
            } else {
                arith::filter_kernel k;
                return incidence::detail::halfspaces::edge_planes(k, f.planes.data(), 6);
            }
        }();
        static_assert(sizeof implied.at / sizeof implied.at[0] == 45, "fifteen pairs of planes, three axes each");
        double edges[7 * 45];
        for (int e = 0; e < implied.n; ++e) {
            const auto& x = implied.at[static_cast<unsigned>(e)];
            const double v[7] = {double(x.i), double(x.j), x.alpha, x.beta, double(x.upper[0]), double(x.upper[1]), double(x.upper[2])};
            for (int k = 0; k < 7; ++k) edges[7 * e + k] = v[k];
        }
        simd::frustum_boxes(planes, edges, implied.n, boxes, n, !std::is_same_v<Tier, approximate>, out);
    }
    return settle_open(out, n, [&](std::size_t i) { return incidence::intersects<Tier>(f, at(i)); });
}

template <tier Tier, class Box>
result<std::size_t> culling(const frustum3& f, std::span<const Box> boxes, std::span<std::uint8_t> out) {
    if (out.size() != boxes.size()) return error{errc::size_mismatch};
    return by_blocks<fields_of<Box>>(
        boxes, out.data(), [](const Box& b, double* v) { unpack(b, v); },
        [&](const double* const* coords, std::size_t n, std::uint8_t* o, std::size_t start) {
            return culling_block<Tier, Box>(f, coords, n, o, [&](std::size_t i) { return boxes[start + i]; });
        });
}
template <tier Tier, class Soa>
result<std::size_t> culling(const frustum3& f, const Soa& boxes, std::span<std::uint8_t> out) {
    if (!boxes.consistent() || out.size() != boxes.size()) return error{errc::size_mismatch};
    using Box = std::remove_cvref_t<decltype(boxes[0])>;
    const double* p[fields_of<Box>] = {};
    arrays(boxes, p);
    return culling_block<Tier, Box>(f, p, boxes.size(), out.data(), [&](std::size_t i) { return boxes[i]; });
}

} // namespace incidence::batch::detail

export namespace incidence::batch {

// Does each box meet the frustum? out[i] for boxes[i] (out as long as boxes); the number met.
// Tiers as the scalar intersects: the same answer, box by box. Either argument order.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const frustum3& f, std::span<const aabb3> boxes, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const frustum3& f, const boxes_soa& boxes, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(std::span<const aabb3> boxes, const frustum3& f, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const boxes_soa& boxes, const frustum3& f, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, boxes, out);
}
// Does each oriented box meet the frustum? The same way, oriented boxes as obb3 or obbs_soa.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const frustum3& f, std::span<const obb3> boxes, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const frustum3& f, const obbs_soa& boxes, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(std::span<const obb3> boxes, const frustum3& f, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, boxes, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const obbs_soa& boxes, const frustum3& f, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, boxes, out);
}

// Does each ball meet the frustum? The same way, balls as sphere3 or spheres_soa.
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const frustum3& f, std::span<const sphere3> balls, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, balls, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const frustum3& f, const spheres_soa& balls, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, balls, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(std::span<const sphere3> balls, const frustum3& f, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, balls, out);
}
template <tier Tier = exact>
[[nodiscard]] result<std::size_t> intersects(const spheres_soa& balls, const frustum3& f, std::span<std::uint8_t> out) {
    return detail::culling<Tier>(f, balls, out);
}

} // namespace incidence::batch
