// Polygons with known answers, for the polygon pairs' fixtures: the square [0, 4]^2 with the
// square hole [1, 3]^2 (rings in opposite orientations), and a C shape (the square [0, 4]^2 less
// the notch (1, 4) x [1, 3] opening to the right). Include after `import incidence;`.
#pragma once
#include <array>
#include <cstdint>

namespace support {
inline constexpr std::array<incidence::point2, 8> frame_vertices{{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {1, 3}, {3, 3}, {3, 1}}};
inline constexpr std::array<std::uint32_t, 2> frame_ends{{4, 8}};
inline constexpr incidence::polygon2 frame{frame_vertices, frame_ends};
inline constexpr std::array<incidence::point2, 8> c_vertices{{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {4, 3}, {4, 4}, {0, 4}}};
inline constexpr incidence::polygon2 c_shape{c_vertices, {}};
} // namespace support
