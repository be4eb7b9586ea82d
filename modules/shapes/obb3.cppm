// obb3{center, axes, half_extents}: the closed solid box { c + s0 a0 + s1 a1 + s2 a2 : |si| <= hi }.
// The axes are read exactly as given: exactness never depends on them being perfectly
// orthonormal (the box is then the parallelepiped they span), but make() refuses axes whose
// lengths or pairwise dot products are more than 1e-6 from orthonormal, and negative extents.
module;
#include <array>
export module incidence.shapes:obb3;
import incidence.core;

export namespace incidence {

struct obb3 {
    point3 center;
    std::array<vec3, 3> axes;
    std::array<double, 3> half_extents;

    [[nodiscard]] static constexpr result<obb3> make(point3 center, const std::array<vec3, 3>& axes,
                                                     const std::array<double, 3>& half_extents) {
        if (!is_finite(center)) return error{errc::not_finite};
        for (int i = 0; i < 3; ++i) {
            const auto u = static_cast<unsigned>(i);
            if (!is_finite(axes[u]) || !is_finite(half_extents[u])) return error{errc::not_finite};
            if (half_extents[u] < 0) return error{errc::negative_radius};
            const double l = dot(axes[u], axes[u]) - 1.0;
            if (l > 1e-6 || l < -1e-6) return error{errc::not_orthonormal};
            for (int j = i + 1; j < 3; ++j) {
                const double d = dot(axes[u], axes[static_cast<unsigned>(j)]);
                if (d > 1e-6 || d < -1e-6) return error{errc::not_orthonormal};
            }
        }
        return obb3{center, axes, half_extents};
    }
};

} // namespace incidence
