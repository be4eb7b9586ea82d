// orient2d, orient3d, incircle, insphere with Shewchuk's sign conventions, exact for every
// finite input and usable in constant expressions.
// Source: Shewchuk, DCG 18 (1997), section 4 (the determinants) and section 2 (exactness);
// here the adaptive stages are the generic kernel's: filter, expansions, dyadic integers.
// Worst-case expansion lengths (kernel stage 2): orient2d 16, orient3d 192, incircle 1536;
// insphere (9216) goes straight from the filter to the dyadic stage.
module;
#include <type_traits>
export module incidence.predicates:orient;
import incidence.core;
import incidence.arith;

export namespace incidence {

namespace poly {
// The predicate polynomials, generic over the number type (see incidence.arith:kernel).
// Each takes the lift L first; callers wrap them as [=](auto L) { return poly::f(L, ...); }.
template <class L>
[[nodiscard]] constexpr auto orient2d(L l, const point2& a, const point2& b, const point2& c) {
    const auto A = arith::lift(l, a), B = arith::lift(l, b), C = arith::lift(l, c);
    return arith::cross(A - C, B - C);
}
template <class L>
[[nodiscard]] constexpr auto orient3d(L l, const point3& a, const point3& b, const point3& c, const point3& d) {
    const auto A = arith::lift(l, a), B = arith::lift(l, b), C = arith::lift(l, c), D = arith::lift(l, d);
    return arith::det3(A - D, B - D, C - D);
}
template <class Lf>
[[nodiscard]] constexpr auto incircle(Lf L, const point2& a, const point2& b, const point2& c, const point2& d) {
    {
        const auto D = arith::lift(L, d);
        const auto ad = arith::lift(L, a) - D, bd = arith::lift(L, b) - D, cd = arith::lift(L, c) - D;
        const auto alift = ad.x * ad.x + ad.y * ad.y;
        const auto blift = bd.x * bd.x + bd.y * bd.y;
        const auto clift = cd.x * cd.x + cd.y * cd.y;
        return alift * (bd.x * cd.y - cd.x * bd.y) + blift * (cd.x * ad.y - ad.x * cd.y) + clift * (ad.x * bd.y - bd.x * ad.y);
    }
}
template <class Lf>
[[nodiscard]] constexpr auto insphere(Lf L, const point3& a, const point3& b, const point3& c, const point3& d, const point3& e) {
    {
        const auto E = arith::lift(L, e);
        const auto ae = arith::lift(L, a) - E, be = arith::lift(L, b) - E, ce = arith::lift(L, c) - E, de = arith::lift(L, d) - E;
        const auto ab = ae.x * be.y - be.x * ae.y, bc = be.x * ce.y - ce.x * be.y;
        const auto cd = ce.x * de.y - de.x * ce.y, da = de.x * ae.y - ae.x * de.y;
        const auto ac = ae.x * ce.y - ce.x * ae.y, bd = be.x * de.y - de.x * be.y;
        const auto abc = ae.z * bc - be.z * ac + ce.z * ab;
        const auto bcd = be.z * cd - ce.z * bd + de.z * bc;
        const auto cda = ce.z * da + de.z * ac + ae.z * cd;
        const auto dab = de.z * ab + ae.z * bd + be.z * da;
        const auto alift = ae.x * ae.x + ae.y * ae.y + ae.z * ae.z;
        const auto blift = be.x * be.x + be.y * be.y + be.z * be.z;
        const auto clift = ce.x * ce.x + ce.y * ce.y + ce.z * ce.z;
        const auto dlift = de.x * de.x + de.y * de.y + de.z * de.z;
        return (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
    }
}
} // namespace poly

template <class Tier>
concept sign_tier = std::is_same_v<Tier, exact> || std::is_same_v<Tier, approximate>;

template <sign_tier Tier, class F>
[[nodiscard, gnu::always_inline]] constexpr sign evaluate_sign(const F& f) {
    if constexpr (std::is_same_v<Tier, approximate>) return arith::approx_kernel{}.sgn(f);
    else return arith::exact_kernel{}.sgn(f);
}

// positive: a, b, c are in counterclockwise order.
template <sign_tier Tier = exact>
[[nodiscard]] constexpr sign orient2d(point2 a, point2 b, point2 c) {
    return evaluate_sign<Tier>([=](auto L) { return poly::orient2d(L, a, b, c); });
}
// positive: d lies below the plane through a, b, c, "below" being the side from which a, b, c
// appear clockwise (so a, b, c are counterclockwise seen from above). Equals det[a-d; b-d; c-d].
template <sign_tier Tier = exact>
[[nodiscard]] constexpr sign orient3d(point3 a, point3 b, point3 c, point3 d) {
    return evaluate_sign<Tier>([=](auto L) { return poly::orient3d(L, a, b, c, d); });
}
// positive: d lies inside the circle through a, b, c, which must be counterclockwise.
template <sign_tier Tier = exact>
[[nodiscard]] constexpr sign incircle(point2 a, point2 b, point2 c, point2 d) {
    return evaluate_sign<Tier>([=](auto L) { return poly::incircle(L, a, b, c, d); });
}
// positive: e lies inside the sphere through a, b, c, d, which must have orient3d(a,b,c,d) > 0.
template <sign_tier Tier = exact>
[[nodiscard]] constexpr sign insphere(point3 a, point3 b, point3 c, point3 d, point3 e) {
    return evaluate_sign<Tier>([=](auto L) { return poly::insphere(L, a, b, c, d, e); });
}

// The filter alone: the sign when it is provable in floating point, otherwise std::nullopt-like
// sign::zero with `proven == false`.
struct filtered_sign {
    sign value;
    bool proven;
};
template <class F>
[[nodiscard]] constexpr filtered_sign classify_sign(const F& f) {
    arith::filter_kernel k;
    const sign s = k.sgn(f);
    return {s, !k.failed()};
}

} // namespace incidence
