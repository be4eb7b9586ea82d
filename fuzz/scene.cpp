// scene3 (incidence.scene) on raw bytes: nine triangles (the layout of the ray_triangle harness: t,
// u, t's vertices permuted, t's edges with other apexes, doubles 0..31) as a scene; the ray and the
// segment of doubles 0..5 against it (intersects in every tier, the exact first hit and the
// interval tiers' first hits), the box of doubles 0..5 and the tetrahedron of doubles 18..29
// against it (intersects and intersecting in every tier), and the scene against a second scene of
// t and u (every pair met): each against the brute force over the triangles (fuzz/scenes.hpp).
// NaN, infinities, subnormals and huge values included: a scene refuses non-finite triangles.
// Any finding aborts.
#include "replay.hpp"
#include <cstdint>
#include <cstring>
#include <span>
import incidence;
#include "batches.hpp"
#include "scenes.hpp"

using namespace incidence;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    double v[32] = {};
    std::memcpy(v, data, size < sizeof v ? size : sizeof v);
    const ray3 r{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    const segment3 s{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    const auto ts = nine_triangles(v);
    const triangle3 &t = ts[0], &u = ts[1];
    const point3 p{v[18], v[19], v[20]}, q{v[21], v[22], v[23]}, w{v[24], v[25], v[26]}, x{v[27], v[28], v[29]};
    const triangle3 pair[2] = {t, u};
    scene_contracts(r, std::span<const triangle3>(ts));
    scene_contracts(s, std::span<const triangle3>(ts));
    solid_scene_contracts(aabb3{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}, std::span<const triangle3>(ts), std::span<const triangle3>(pair));
    solid_scene_contracts(tetrahedron3{p, q, w, x}, std::span<const triangle3>(ts), std::span<const triangle3>(pair));
    return 0;
}
