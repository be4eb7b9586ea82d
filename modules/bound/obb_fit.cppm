// Shared by the OBB constructions: exact point-in-box for an obb3 (its axes read exactly), and
// the box with given axes around a point set, rounded outward until every point is provably in.
// Point in box: with M = [a0 a1 a2] and D = det M, p - c = sum si ai has si = Di / D (Cramer,
// Di = det M with column i replaced by p - c), so |si| <= hi  <=>  -hi |D| <= Di <=> ... <= hi |D|,
// two exact signs per axis.
module;
#include <array>
#include <span>
export module incidence.bound:obb_fit;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::bound {

namespace obb_detail {
// -h |D| <= Di <= h |D| for axis I, where sd is the sign of D.
template <int I>
[[nodiscard]] constexpr bool within(const obb3& b, point3 p, sign sd, bool& valid) {
    const vec3 a0 = b.axes[0], a1 = b.axes[1], a2 = b.axes[2];
    const point3 c = b.center;
    const double h = b.half_extents[I];
    auto di = [=](auto L) {
        const auto d = arith::lift(L, p) - arith::lift(L, c);
        if constexpr (I == 0)
            return arith::det3(d, arith::lift(L, a1) - arith::lift(L, vec3{0, 0, 0}), arith::lift(L, a2) - arith::lift(L, vec3{0, 0, 0}));
        else if constexpr (I == 1)
            return arith::det3(arith::lift(L, a0) - arith::lift(L, vec3{0, 0, 0}), d, arith::lift(L, a2) - arith::lift(L, vec3{0, 0, 0}));
        else return arith::det3(arith::lift(L, a0) - arith::lift(L, vec3{0, 0, 0}), arith::lift(L, a1) - arith::lift(L, vec3{0, 0, 0}), d);
    };
    auto D = [=](auto L) { return arith::det3(arith::lift(L, a0), arith::lift(L, a1), arith::lift(L, a2)); };
    const sign up = arith::exact_sign([=](auto L) { return L(h) * D(L) - di(L); }, valid);
    const sign lo = arith::exact_sign([=](auto L) { return L(h) * D(L) + di(L); }, valid);
    return valid && up != -sd && lo != -sd;
}
} // namespace obb_detail

[[nodiscard]] constexpr bool contains(const obb3& b, point3 p) {
    const vec3 a0 = b.axes[0], a1 = b.axes[1], a2 = b.axes[2];
    bool valid = true;
    const sign sd =
        arith::exact_sign([=](auto L) { return arith::det3(arith::lift(L, a0), arith::lift(L, a1), arith::lift(L, a2)); }, valid);
    if (sd == sign::zero || !valid) return false;
    return obb_detail::within<0>(b, p, sd, valid) && obb_detail::within<1>(b, p, sd, valid) && obb_detail::within<2>(b, p, sd, valid);
}

// The box with axes `axes` (nearly orthonormal) around the points: extents from the projections,
// then widened until every point is provably inside. Errors: overflow.
[[nodiscard]] inline result<obb3> fit_box(const std::array<vec3, 3>& axes, std::span<const point3> points) {
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) lo[i] = __builtin_huge_val(), hi[i] = -__builtin_huge_val();
    for (const point3& p : points)
        for (int i = 0; i < 3; ++i) {
            const double s = dot(axes[static_cast<unsigned>(i)], p - point3{0, 0, 0});
            lo[i] = s < lo[i] ? s : lo[i];
            hi[i] = s > hi[i] ? s : hi[i];
        }
    point3 c{0, 0, 0};
    std::array<double, 3> h{};
    for (int i = 0; i < 3; ++i) {
        const auto u = static_cast<unsigned>(i);
        c = c + axes[u] * (0.5 * lo[i] + 0.5 * hi[i]);
        const double mag =
            (lo[i] < 0 ? -lo[i] : lo[i]) > (hi[i] < 0 ? -hi[i] : hi[i]) ? (lo[i] < 0 ? -lo[i] : lo[i]) : (hi[i] < 0 ? -hi[i] : hi[i]);
        h[u] = (0.5 * hi[i] - 0.5 * lo[i]) + mag * 0x1p-48 + 0x1p-1060; // rounding of the projections
    }
    obb3 b{c, axes, h};
    if (!is_finite(c) || !is_finite(h[0]) || !is_finite(h[1]) || !is_finite(h[2])) return error{errc::out_of_range};
    const double scale = arith::abs(c.x) + arith::abs(c.y) + arith::abs(c.z);
    for (const point3& p : points) {
        if (contains(b, p)) continue;
        // widen to this point's projections, with room for their rounding, then double if needed
        for (int i = 0; i < 3; ++i) {
            const auto u = static_cast<unsigned>(i);
            const double sp = dot(axes[u], p - c);
            const double need = (sp < 0 ? -sp : sp) * (1 + 0x1p-30) + scale * 0x1p-44 + 0x1p-1060;
            if (need > b.half_extents[u]) b.half_extents[u] = need;
        }
        for (int k = 0; k < 2200 && !contains(b, p); ++k)
            for (double& x : b.half_extents) x = x * 2 + 0x1p-1060;
        if (!contains(b, p)) return error{errc::out_of_range};
    }
    return b;
}

[[nodiscard]] constexpr double volume(const obb3& b) { return 8.0 * b.half_extents[0] * b.half_extents[1] * b.half_extents[2]; }

} // namespace incidence::bound
