// Fixtures of the 3D polygon pairs (tests/query/*polygon*.cpp, tests/static/static.cpp).
#pragma once
#include <array>
#include <cstdint>

namespace support::polygon3_fixtures {

using namespace incidence;

// The square [0, 4]^2 at z = 1 with the square hole [1, 3]^2 (rings in opposite orientations).
inline constexpr std::array<point3, 8> holed_vertices{
    {{0, 0, 1}, {4, 0, 1}, {4, 4, 1}, {0, 4, 1}, {1, 1, 1}, {1, 3, 1}, {3, 3, 1}, {3, 1, 1}}};
inline constexpr std::array<std::uint32_t, 2> holed_ends{4, 8};
// plane vertices 0, 2 (the farthest from 0) and 1; the projection drops z
inline constexpr polygon3 holed{holed_vertices, holed_ends, {0, 2, 1}, 2};
// The square [-2, 2]^2 at z = 1 with the hole [-3/2, 3/2]^2: the integer frustum's section there,
// [-1, 1]^2, lies in the hole.
inline constexpr std::array<point3, 8> ring_vertices{
    {{-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}, {-1.5, -1.5, 1}, {-1.5, 1.5, 1}, {1.5, 1.5, 1}, {1.5, -1.5, 1}}};
inline constexpr polygon3 ring{ring_vertices, holed_ends, {0, 2, 1}, 2};
// A non-convex L in the tilted plane x + z = 2 (projected along y... the normal (1, 0, 1) has
// its largest component first: the projection drops x).
inline constexpr std::array<point3, 6> l_vertices{{{0, 0, 2}, {2, 0, 0}, {2, 1, 0}, {1, 1, 1}, {1, 2, 1}, {0, 2, 2}}};
inline constexpr polygon3 tilted_l{l_vertices, {}, {0, 4, 1}, 0};

} // namespace support::polygon3_fixtures
