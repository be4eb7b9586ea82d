// Two closed meshes with known answers, for the mesh pairs' fixtures: the unit cube (12 outward
// triangles) and the same cube with its top face dented down to (1/2, 1/2, 1/4) (non-convex:
// (1/2, 1/2, 1/2) lies in the dent, outside). Include after `import incidence;`.
#pragma once
#include <array>
#include <cstdint>
#include <span>

namespace support {
// vertex i: x = i & 1, y = (i >> 1) & 1, z = (i >> 2) & 1; vertex 8 the dent's apex
inline constexpr std::array<incidence::point3, 9> cube_vertices{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0.5, 0.5, 0.25}}};
inline constexpr std::array<std::array<std::uint32_t, 3>, 12> cube_triangles{
    {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}}};
inline constexpr std::array<std::array<std::uint32_t, 3>, 14> dented_triangles{{{0, 4, 6},
                                                                                {0, 6, 2},
                                                                                {1, 3, 7},
                                                                                {1, 7, 5},
                                                                                {0, 1, 5},
                                                                                {0, 5, 4},
                                                                                {2, 6, 7},
                                                                                {2, 7, 3},
                                                                                {0, 2, 3},
                                                                                {0, 3, 1},
                                                                                {4, 5, 8},
                                                                                {5, 7, 8},
                                                                                {7, 6, 8},
                                                                                {6, 4, 8}}};
inline constexpr incidence::mesh3 cube{std::span<const incidence::point3>(cube_vertices.data(), 8), cube_triangles};
inline constexpr incidence::mesh3 dented{cube_vertices, dented_triangles};
} // namespace support
