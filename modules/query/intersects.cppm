// intersects<Tier>(a, b) -> bool and classify(a, b) -> certainty: does a meet b (closed sets, so
// touching counts)? Every pair is written once, in lexicographic order of the shape names, as a
// kernel-generic body (modules/query/intersects/); the reversed order forwards.
module;
#include <optional>
#include <type_traits>
export module incidence.query:intersects;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.detail;
import :tiers;

export namespace incidence {

template <class A, class B>
concept canonical_pair = requires(arith::filter_kernel& k, const A& a, const B& b) {
    { detail::intersects(k, a, b) };
};
template <class A, class B>
concept has_pair = canonical_pair<A, B> || canonical_pair<B, A>;

// Does a meet b? Closed sets: touching counts.
template <tier Tier = exact, class A, class B>
requires has_pair<A, B>
[[nodiscard]] constexpr bool intersects(const A& a, const B& b) {
    if constexpr (canonical_pair<A, B>) {
        if constexpr (std::is_same_v<Tier, approximate> && detail::approximate_override<A, B>) return detail::intersects_approximate(a, b);
        else if constexpr (detail::by_comparisons<A, B>) return detail::decide_pair<approximate>(a, b, detail::intersects_body{});
        else return detail::decide_pair<Tier>(a, b, detail::intersects_body{});
    } else {
        return intersects<Tier>(b, a);
    }
}

// The floating-point filter's verdict alone: yes, no, or uncertain (never wrong).
template <class A, class B>
requires has_pair<A, B>
[[nodiscard]] constexpr certainty classify(const A& a, const B& b) {
    if constexpr (canonical_pair<A, B>) {
        return detail::classify_pair(a, b, detail::intersects_body{});
    } else {
        return classify(b, a);
    }
}

} // namespace incidence
