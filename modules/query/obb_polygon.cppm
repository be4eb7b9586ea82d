// obb3 against polygon3.
// Semantics: the closed box read as the parallelepiped its axes span (shapes/obb3.cppm) and the
// polygon's point set (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): an edge of the polygon meets the box (the 13-axis obb_segment test), or
// else the box's section Q by the polygon's plane H lies wholly inside the polygon or outside it,
// and one point of Q decides: where a box edge c + s_i a_i + s_j a_j + t a_k (s = +-h) crosses H,
// t = T / D with D = n . a_k and T = n . (a - c) - s_i n . a_i - s_j n . a_j, |t| <= h_k (signs of
// degree 4), the point V / D with V = (c + s_i a_i + s_j a_j) D + T a_k, tested by the homogeneous
// crossing test of point_polygon.cppm (degree <= 7); a box whose every edge is parallel to H lies
// in H or off it, and its point c + h_0 a_0 decides.
// Source: the boundary-plus-inside decomposition of point_polygon.cppm; Gottschalk, Lin and
// Manocha, "OBBTree", SIGGRAPH 1996, section 5, for the edges.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/obb_polygon.cpp).
export module incidence.query:obb_polygon;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :separating_axes;
import :obb_segment;
import :obb_tetrahedron;
import :point_polygon;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& b, const polygon3& g) {
    if (!sat::well_formed(b) || !finite(b) || !planeq::usable(k, g)) return false;
    if (planeq::any_edge(g, [&](const segment3& e) { return intersects(k, b, e); })) return true;
    const point3 a = g.vertices[g.plane_vertices[0]];
    bool crossed = false;
    for (int e = 0; e < 3; ++e) {
        const unsigned ek = static_cast<unsigned>(e), ei = (ek + 1) % 3, ej = (ek + 2) % 3;
        auto D = [=](auto L) { return arith::dot(planeq::normal(L, g), arith::lift(L, b.axes[ek])); };
        const sign d = k.sgn(D);
        if (d == sign::zero) continue; // these edges are parallel to H
        crossed = true;
        for (int m = 0; m < 4; ++m) {
            const double si = (m & 1) ? b.half_extents[ei] : -b.half_extents[ei];
            const double sj = (m & 2) ? b.half_extents[ej] : -b.half_extents[ej];
            auto T = [=](auto L) {
                const auto n = planeq::normal(L, g);
                return arith::dot(n, arith::lift(L, a) - arith::lift(L, b.center)) * L(1.0) - L(si) * arith::dot(n, arith::lift(L, b.axes[ei])) -
                       L(sj) * arith::dot(n, arith::lift(L, b.axes[ej]));
            };
            const double hk = b.half_extents[ek];
            // |t| <= h_k: h_k D - T and h_k D + T both zero or of D's sign
            const sign hi = k.sgn([=](auto L) { return L(hk) * D(L) - T(L); });
            if (hi != sign::zero && hi != d) continue;
            const sign lo = k.sgn([=](auto L) { return L(hk) * D(L) + T(L); });
            if (lo != sign::zero && lo != d) continue;
            auto V = [=](auto L) {
                const auto dd = D(L);
                const auto t = T(L);
                const auto c = arith::lift(L, b.center);
                const auto one = L(1.0);
                const auto ai = arith::lift(L, b.axes[ei]), aj = arith::lift(L, b.axes[ej]), ak = arith::lift(L, b.axes[ek]);
                const auto Si = L(si), Sj = L(sj);
                using R = decltype((c.x * one + Si * ai.x + Sj * aj.x) * dd + t * ak.x);
                return arith::v3<R>{(c.x * one + Si * ai.x + Sj * aj.x) * dd + t * ak.x, (c.y * one + Si * ai.y + Sj * aj.y) * dd + t * ak.y,
                                    (c.z * one + Si * ai.z + Sj * aj.z) * dd + t * ak.z};
            };
            auto Dpad = [=](auto L) { return D(L) * L(1.0); };
            return planeq::inside(k, g, planeq::at_homogeneous<decltype(V), decltype(Dpad)>{V, Dpad, d});
        }
    }
    if (crossed) return false; // no edge crosses H within the box: the box misses H
    // every edge parallel to H (dependent axes): the box lies in H or off it, and its point
    // c + h_0 a_0 decides
    auto V = [=](auto L) {
        const auto c = arith::lift(L, b.center);
        const auto one = L(1.0);
        const auto a0 = arith::lift(L, b.axes[0]);
        const auto h0 = L(b.half_extents[0]);
        using R = decltype(c.x * one + h0 * a0.x);
        return arith::v3<R>{c.x * one + h0 * a0.x, c.y * one + h0 * a0.y, c.z * one + h0 * a0.z};
    };
    auto one = [](auto L) { return L(1.0); };
    const sign on = k.sgn([=](auto L) {
        const auto A = arith::lift(L, a);
        const auto v = V(L);
        const auto o = L(1.0);
        using R = decltype(v.x - A.x * o);
        return arith::dot(planeq::normal(L, g), arith::v3<R>{v.x - A.x * o, v.y - A.y * o, v.z - A.z * o});
    });
    if (on != sign::zero) return false;
    return planeq::inside(k, g, planeq::at_homogeneous<decltype(V), decltype(one)>{V, one, sign::positive});
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const polygon3&);
} // namespace incidence::pair
