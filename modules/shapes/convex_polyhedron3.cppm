// convex_polyhedron3{planes, count}: the closed convex set of the first `count` half-spaces,
// { p : dot(planes[i].normal, p) <= planes[i].offset for every i < count }, outward normals, read
// exactly (no rounding in the meaning). Its vertices, where three planes meet, are rational points
// that are not doubles in general, so the half-spaces are the shape and nothing is derived from
// them. The set may be unbounded (normals that do not surround the origin) or empty (half-spaces
// that never meet together): queries answer for the set as it is. At most `capacity` half-spaces,
// stored in place, so a value never allocates. Aggregate construction accepts anything; a count
// outside [0, capacity] or a non-finite number makes no set (every query says no), a zero normal
// is all of space (offset >= 0) or nothing.
module;
#include <array>
#include <span>
export module incidence.shapes:convex_polyhedron3;
import incidence.core;
import :plane3;

export namespace incidence {

struct convex_polyhedron3 {
    static constexpr int capacity = 32;
    std::array<plane3, capacity> planes;
    int count;

    // Refuses no half-spaces, more than `capacity`, non-finite values and zero normals.
    [[nodiscard]] static constexpr result<convex_polyhedron3> make(std::span<const plane3> half_spaces) {
        if (half_spaces.empty()) return error{errc::empty_input};
        if (half_spaces.size() > static_cast<std::size_t>(capacity)) return error{errc::too_large};
        convex_polyhedron3 c{{}, static_cast<int>(half_spaces.size())};
        for (std::size_t i = 0; i < half_spaces.size(); ++i) {
            const auto p = plane3::make(half_spaces[i].normal, half_spaces[i].offset);
            if (!p.has_value()) return p.error();
            c.planes[i] = p.value();
        }
        return c;
    }
};

} // namespace incidence
