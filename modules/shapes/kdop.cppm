// kdop<K>{min, max}: the discrete oriented polytope of K/2 slabs, K = 6, 14, 18 or 26:
// { p : min[i] <= dot(d_i, p) <= max[i] for every direction d_i } with the integer directions
// below, read exactly (dot(d_i, p) is a signed sum of coordinates, no rounding in the meaning).
// Directions (Klosowski, Held, Mitchell, Sowizral, Zikan, IEEE TVCG 4(1), 1998, section 4):
//   6: the axes; 14: axes + the 4 cube diagonals; 18: axes + the 6 edge diagonals;
//   26: axes + 4 cube diagonals + 6 edge diagonals.
module;
#include <array>
export module incidence.shapes:kdop;
import incidence.core;

export namespace incidence {

struct direction3 {
    int x, y, z;
};

template <int K>
requires(K == 6 || K == 14 || K == 18 || K == 26)
struct kdop {
    static constexpr int slabs = K / 2;
    std::array<double, K / 2> min;
    std::array<double, K / 2> max;

    [[nodiscard]] static constexpr std::array<direction3, K / 2> directions() {
        constexpr direction3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        constexpr direction3 corners[4] = {{1, 1, 1}, {1, -1, 1}, {1, 1, -1}, {1, -1, -1}};
        constexpr direction3 edges[6] = {{1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, -1, 0}, {1, 0, -1}, {0, 1, -1}};
        std::array<direction3, K / 2> d{};
        int n = 0;
        for (const auto& a : axes) d[static_cast<unsigned>(n++)] = a;
        if constexpr (K == 14 || K == 26)
            for (const auto& a : corners) d[static_cast<unsigned>(n++)] = a;
        if constexpr (K == 18 || K == 26)
            for (const auto& a : edges) d[static_cast<unsigned>(n++)] = a;
        return d;
    }

    // Refuses non-finite bounds and min > max in some direction (an empty slab).
    [[nodiscard]] static constexpr result<kdop> make(const std::array<double, K / 2>& min, const std::array<double, K / 2>& max) {
        for (int i = 0; i < K / 2; ++i) {
            const auto u = static_cast<unsigned>(i);
            if (!is_finite(min[u]) || !is_finite(max[u])) return error{errc::not_finite};
            if (min[u] > max[u]) return error{errc::inverted_box};
        }
        return kdop{min, max};
    }
};

} // namespace incidence
