// Shapes the half-space pair tests share (constexpr, for the static_asserts too). Include after
// `import incidence;`.
#pragma once
#include <array>

namespace support::polyhedron_fixtures {

using namespace incidence;

// The unit cube with its corner (1, 1, 1) cut off by x + y + z <= 5/2.
inline constexpr convex_polyhedron3 unit_cube_cut{{plane3{{1, 0, 0}, 1}, plane3{{-1, 0, 0}, 0}, plane3{{0, 1, 0}, 1}, plane3{{0, -1, 0}, 0},
                                                   plane3{{0, 0, 1}, 1}, plane3{{0, 0, -1}, 0}, plane3{{1, 1, 1}, 2.5}},
                                                  7};
// x <= 1 and x >= 2: each half-space non-empty, together nothing.
inline constexpr convex_polyhedron3 empty_slab{{plane3{{1, 0, 0}, 1}, plane3{{-1, 0, 0}, -2}}, 2};
// x <= 0 alone (unbounded).
inline constexpr convex_polyhedron3 half_space{{plane3{{1, 0, 0}, 0}}, 1};
// z <= x and z <= -x: the wedge below z = -|x| (unbounded). A box above it that no single one of
// its planes has wholly beyond it, such as [-1, 1] x [0, 1] x [1/2, 1], still misses it.
inline constexpr convex_polyhedron3 roof{{plane3{{-1, 0, 1}, 0}, plane3{{1, 0, 1}, 0}}, 2};
// Eye at the origin looking along +z with 45-degree side planes (|x|, |y| <= z), near 1, far 4:
// corners (+-1, +-1, 1) and (+-4, +-4, 4), all exact.
inline constexpr frustum3 integer_frustum{{plane3{{0, 0, -1}, -1}, plane3{{0, 0, 1}, 4}, plane3{{-1, 0, -1}, 0}, plane3{{1, 0, -1}, 0},
                                           plane3{{0, -1, -1}, 0}, plane3{{0, 1, -1}, 0}}};
// f reflected through the point c (x -> 2c - x): a plane n . x <= d becomes -n . x <= d - 2 n . c
// (exact when that offset is).
constexpr frustum3 reflected(const frustum3& f, point3 c) {
    frustum3 g = f;
    for (auto& p : g.planes) p = plane3{-p.normal, p.offset - 2 * dot(p.normal, c - point3{0, 0, 0})};
    return g;
}
// A large triangle in the plane z = z0 (corners (-10, -10), (10, -10), (0, 10)): its edges miss the
// unit cube, and the integer frustum's section |x|, |y| <= z0 while z0 < 10/3, so where it meets
// those, it is by its interior.
constexpr triangle3 wide_triangle(double z0) { return {{-10, -10, z0}, {10, -10, z0}, {0, 10, z0}}; }
// A large tetrahedron below the plane z = z0, its top face in that plane: it holds the unit cube and
// the integer frustum whole when z0 is above them.
constexpr tetrahedron3 wide_tetrahedron(double z0) { return {{-100, -100, z0}, {100, -100, z0}, {0, 100, z0}, {0, 0, z0 - 400}}; }
// Looking down -z from the origin, 90 degrees, square, near 1, far 100 (computed planes).
inline const frustum3 camera = frustum3::from_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1.5707963267948966, 1.0, 1.0, 100.0).value();

} // namespace support::polyhedron_fixtures
