// The closed shapes the harnesses read from raw doubles (any bits: possibly empty, inverted,
// non-finite or self-intersecting). Include after `import incidence;`.
#pragma once
#include <array>
#include <cstdint>

namespace fuzz {
// A closed mesh of octahedron topology on six vertices.
constexpr std::array<std::array<std::uint32_t, 3>, 8> octahedron{
    {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};

// Plane i from h[4i .. 4i + 3] (normal, offset), the 18 doubles read again past the end.
inline incidence::plane3 plane_at(const double* h, unsigned i) {
    return incidence::plane3{{h[4 * i % 18], h[(4 * i + 1) % 18], h[(4 * i + 2) % 18]}, h[(4 * i + 3) % 18]};
}
// 1 to 4 planes (count), a frustum's six planes, a 14-DOP's bounds (maybe inverted: empty).
inline incidence::convex_polyhedron3 polyhedron_from(const double* h, int count) {
    incidence::convex_polyhedron3 c{};
    c.count = count;
    for (unsigned i = 0; i < static_cast<unsigned>(count); ++i) c.planes[i] = plane_at(h, i);
    return c;
}
inline incidence::frustum3 frustum_from(const double* h) {
    incidence::frustum3 f{};
    for (unsigned i = 0; i < 6; ++i) f.planes[i] = plane_at(h, i);
    return f;
}
inline incidence::kdop<14> kdop14_from(const double* h) {
    incidence::kdop<14> k{};
    for (unsigned i = 0; i < 7; ++i) k.min[i] = h[i], k.max[i] = h[i + 7];
    return k;
}
} // namespace fuzz
