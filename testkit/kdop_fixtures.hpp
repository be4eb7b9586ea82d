// k-DOPs with known answers, for the k-DOP pairs' fixtures: the unit cube as a 6-DOP; the cube
// with its corner (1, 1, 1) cut by x + y + z <= 5/2 (a 14-DOP); the cube with its edge x = y = 1
// cut by x + y <= 3/2 (an 18-DOP); a 14-DOP whose slabs are each non-empty but never meet
// together (x + y + z >= 7/2 in the unit cube); the cube as a 26-DOP with every diagonal slab
// loose. Include after `import incidence;`.
#pragma once

namespace support {
inline constexpr incidence::kdop<6> unit6{{0, 0, 0}, {1, 1, 1}};
inline constexpr incidence::kdop<14> corner_cut{{0, 0, 0, 0, -1, -1, -2}, {1, 1, 1, 2.5, 2, 2, 1}};
inline constexpr incidence::kdop<18> edge_cut{{0, 0, 0, 0, 0, 0, -1, -1, -1}, {1, 1, 1, 1.5, 2, 2, 1, 1, 1}};
inline constexpr incidence::kdop<14> empty14{{0, 0, 0, 3.5, -1, -1, -2}, {1, 1, 1, 4, 2, 2, 1}};
inline constexpr incidence::kdop<26> unit26{{0, 0, 0, -5, -5, -5, -5, -5, -5, -5, -5, -5, -5}, {1, 1, 1, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5}};
} // namespace support
