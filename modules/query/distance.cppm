// squared_distance<Tier>(a, b) and max_squared_distance<Tier>(a, b): the squared distance between
// the nearest (farthest) points. exact: correctly rounded; conservative and aggressive: an interval
// that contains the exact value; approximate: plain double with the pair's stated bound. The bodies:
// modules/query/distance/.
module;
#include <type_traits>
export module incidence.query:distance;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.detail;
import :tiers;

export namespace incidence {

template <tier Tier = exact>
[[nodiscard]] constexpr auto squared_distance(const aabb3& b, const point3& p) {
    return detail::value_pair<Tier>(b, p, detail::nearest_body{});
}
template <tier Tier = exact>
[[nodiscard]] constexpr auto squared_distance(const point3& p, const aabb3& b) {
    return squared_distance<Tier>(b, p);
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
