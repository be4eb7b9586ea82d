// squared_distance<Tier>(a, b), distance<Tier>(a, b), max_squared_distance<Tier>(a, b) and
// signed_distance<Tier>(a, b): the squared distance between the nearest (farthest) points, the
// distance, and the signed distance from a point to a solid (positive outside, negative inside,
// zero on the boundary). exact: correctly rounded;
// conservative and aggressive: an interval that contains the exact value; approximate: plain double
// with the pair's stated bound. The bodies: modules/query/distance/.
module;
#include <type_traits>
export module incidence.query:distance;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.detail;
import :tiers;

export namespace incidence {

// The solids a point's squared and signed distance is defined for.
template <class S>
concept distance_solid =
    std::is_same_v<S, aabb3> || std::is_same_v<S, obb3> || std::is_same_v<S, sphere3> || std::is_same_v<S, capsule3> ||
    std::is_same_v<S, tetrahedron3> || std::is_same_v<S, convex_polyhedron3> || std::is_same_v<S, frustum3> || std::is_same_v<S, kdop<6>> ||
    std::is_same_v<S, kdop<14>> || std::is_same_v<S, kdop<18>> || std::is_same_v<S, kdop<26>> || std::is_same_v<S, mesh3>;

// squared_distance(s, p) = squared_distance(p, s): zero inside the solid; the empty half-space set:
// +infinity; a NaN or infinite number, an inverted box or a malformed mesh: NaN.
template <tier Tier = exact, distance_solid S>
[[nodiscard]] constexpr auto squared_distance(const S& s, const point3& p) {
    if constexpr (std::is_same_v<S, sphere3> || std::is_same_v<S, tetrahedron3>)
        return detail::value_pair<Tier>(p, s, detail::nearest_body{});
    else return detail::value_pair<Tier>(s, p, detail::nearest_body{});
}
template <tier Tier = exact, distance_solid S>
[[nodiscard]] constexpr auto squared_distance(const point3& p, const S& s) {
    return squared_distance<Tier>(s, p);
}
// signed_distance(s, p) = signed_distance(p, s): positive outside, negative inside, zero on the
// boundary (a set with no boundary: -infinity inside; the empty set: +infinity).
template <tier Tier = exact, distance_solid S>
[[nodiscard]] constexpr auto signed_distance(const S& s, const point3& p) {
    if constexpr (std::is_same_v<S, sphere3> || std::is_same_v<S, tetrahedron3>)
        return detail::value_pair<Tier>(p, s, detail::signed_body{});
    else return detail::value_pair<Tier>(s, p, detail::signed_body{});
}
template <tier Tier = exact, distance_solid S>
[[nodiscard]] constexpr auto signed_distance(const point3& p, const S& s) {
    return signed_distance<Tier>(s, p);
}
// distance(s, p) = distance(p, s): zero inside the solid, the signed distance outside (the
// positive part of a correctly rounded value is correctly rounded; of an enclosure, an enclosure).
template <tier Tier = exact, distance_solid S>
[[nodiscard]] constexpr auto distance(const S& s, const point3& p) {
    const auto d = signed_distance<Tier>(s, p);
    if constexpr (std::is_same_v<decltype(d), const interval>) return interval{d.lo < 0.0 ? 0.0 : d.lo, d.hi < 0.0 ? 0.0 : d.hi};
    else return d < 0.0 ? 0.0 : d;
}
template <tier Tier = exact, distance_solid S>
[[nodiscard]] constexpr auto distance(const point3& p, const S& s) {
    return distance<Tier>(s, p);
}

// Points, segments, rays, lines and triangles against each other, in either order: the squared
// distance and the distance between their nearest points (0 where they meet; a NaN or infinite
// number: NaN).
template <class S>
concept flat_distance_shape = detail::linear_distance::linear_part<S> || std::is_same_v<S, triangle3>;
template <tier Tier = exact, flat_distance_shape A, flat_distance_shape B>
[[nodiscard]] constexpr auto squared_distance(const A& a, const B& b) {
    if constexpr (detail::linear_distance::rank<A> <= detail::linear_distance::rank<B>)
        return detail::value_pair<Tier>(a, b, detail::nearest_body{});
    else return detail::value_pair<Tier>(b, a, detail::nearest_body{});
}
template <tier Tier = exact, flat_distance_shape A, flat_distance_shape B>
[[nodiscard]] constexpr auto distance(const A& a, const B& b) {
    if constexpr (detail::linear_distance::rank<A> <= detail::linear_distance::rank<B>)
        return detail::value_pair<Tier>(a, b, detail::euclidean_body{});
    else return detail::value_pair<Tier>(b, a, detail::euclidean_body{});
}

template <tier Tier = exact>
[[nodiscard]] constexpr auto max_squared_distance(const aabb3& b, const point3& p) {
    return detail::value_pair<Tier>(b, p, detail::farthest_body{});
}
template <tier Tier = exact>
[[nodiscard]] constexpr auto max_squared_distance(const point3& p, const aabb3& b) {
    return max_squared_distance<Tier>(b, p);
}

} // namespace incidence
