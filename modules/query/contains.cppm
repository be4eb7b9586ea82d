// contains<Tier>(a, b) -> bool and classify_contains(a, b) -> certainty: is b inside a (closed
// sets)? The bodies: modules/query/contains/. covers(a, b, c): do two boxes cover a third?
module;
#include <optional>
#include <type_traits>
export module incidence.query:contains;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.detail;
import :tiers;

export namespace incidence {

// Is b inside a (closed sets)?
template <tier Tier = exact, class A, class B>
requires requires(arith::filter_kernel& k, const A& a, const B& b) { detail::contains(k, a, b); }
[[nodiscard]] constexpr bool contains(const A& a, const B& b) {
    return detail::decide_pair<Tier>(a, b, detail::contains_body{});
}

template <class A, class B>
requires requires(arith::filter_kernel& k, const A& a, const B& b) { detail::contains(k, a, b); }
[[nodiscard]] constexpr certainty classify_contains(const A& a, const B& b) {
    return detail::classify_pair(a, b, detail::contains_body{});
}

// Do the boxes a and b together cover the box c completely? Exact (comparisons only).
[[nodiscard]] constexpr bool covers(const aabb3& a, const aabb3& b, const aabb3& c) { return detail::covers(a, b, c); }

} // namespace incidence
