// The tier driver (docs/DESIGN.md, "Tiers"): how a kernel-generic body (namespace incidence::detail)
// becomes each tier's answer. Yes/no: decide_pair and classify_pair; values: find_pair (a hit or
// none) and value_pair (a number). Not exported: the front door's partitions use it.
module;
#include <optional>
#include <type_traits>
export module incidence.query:tiers;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.detail;

namespace incidence::detail {
template <class A, class B>
concept approximate_override = requires(const A& a, const B& b) { detail::intersects_approximate(a, b); };
// A pair whose intersects body reads its shapes through exact comparisons only, never a kernel
// sign (detail::decided_by_comparisons): every kernel gives the exact answer, so every tier runs it
// as the approximate tier does, without a filter pass around it (bench/NOTES.md: the pass kept the
// compiler from turning its early exits into a branch-free chain).
template <class A, class B>
concept by_comparisons =
    requires { requires detail::decided_by_comparisons(static_cast<const A*>(nullptr), static_cast<const B*>(nullptr)); };

// The tiers that filter (exact, conservative, aggressive) and classify, for one canonical pair:
// body(k, a, b) is the pair's kernel-generic body. When the filter cannot decide, its last
// unproven sign's error bound under- or overflowed (arith::in_trusted_range), and the pair's
// largest length is 2^60 or more, or below 2^-60, the pair is scaled towards scale 1
// (detail::scene::normalized) and filtered again before anything is exact: in a scene near 2^-500
// or 2^500 the filter's range, not the configuration, is what failed. Both filter passes go
// through one call of the body, so it is compiled (and inlined) once. A pair with a view (a mesh,
// a polygon), which is not copied, is filtered again with every input scaled as it is lifted
// (arith::scaled_filter_kernel), through a second instance of the body.
template <class A, class B>
inline constexpr bool scaled_by_inputs =
    !(detail::scene::scalable<A> && detail::scene::scalable<B>) && detail::scene::scannable<A> && detail::scene::scannable<B>;
// In 3D (signs of degree 4 to 6) such a pair that looks far from scale 1 goes to the scaled pass
// at once; in the plane (degree 2 or 3) the filter's own range reaches much further, so there the
// scaled pass only follows a first pass that failed out of range.
template <class A, class B>
inline constexpr bool scaled_first =
    scaled_by_inputs<A, B> && !detail::scene::shape_of<A, polygon2> && !detail::scene::shape_of<B, polygon2>;
// The pass with every input scaled by 2^-top as it is lifted, top = the exponent of the largest
// input; nullopt when the pair is near scale 1 already (or has a value that is not finite).
// Run time only (arith::lift_scaled_filter).
template <class A, class B, class Body>
[[nodiscard]] constexpr std::optional<certainty> scaled_inputs_pass(const A& a, const B& b, const Body& body) {
    const int top = detail::scene::far_input_exponent(a, b);
    if (top == 0) return std::nullopt;
    arith::scaled_filter_kernel g{arith::power_of_two(-top)};
    const bool r = body(g, a, b);
    return g.failed() ? certainty::uncertain : to_certainty(r);
}
// The filter pass's kernel: for a pair with a mesh3 or a polygon3, the one that settles exact zeros
// as they arise (arith::settling_filter_kernel). Not for polygon2: its signs (degree 2 and 3) are
// cheap to rerun exactly, and settling measured slower there (bench/NOTES.md, "Measured choices").
template <class S>
inline constexpr bool settles_zeros = detail::scene::shape_of<S, mesh3> || detail::scene::shape_of<S, polygon3>;
template <class A, class B>
using filter_kernel_of = std::conditional_t<settles_zeros<A> || settles_zeros<B>, arith::settling_filter_kernel, arith::filter_kernel>;
template <class A, class B, class Body>
[[nodiscard]] constexpr certainty filter_passes(const A*& a, const B*& b, const Body& body,
                                                std::optional<detail::scene::scaled_pair<A, B>>& scaled) {
    // A pair with a view whose first vertex lies far from scale 1: the scaled pass first, and only
    // (where that glance misleads, the exact tier still decides).
    bool scaled_tried = false;
    if constexpr (scaled_first<A, B>)
        if (!__builtin_is_constant_evaluated() && detail::scene::looks_far(*a, *b)) {
            if (const auto c = scaled_inputs_pass(*a, *b, body)) return *c;
            scaled_tried = true; // near scale 1 after all: the plain pass, and no second scan
        }
    for (;;) {
        filter_kernel_of<A, B> f;
        const bool r = body(f, *a, *b);
        if (!f.failed()) return to_certainty(r);
        if constexpr (detail::scene::scalable<A> && detail::scene::scalable<B>) {
            if (!scaled && !arith::in_trusted_range(f.unproven))
                if (const int top = detail::scene::far_exponent(*a, *b); top != 0 && (scaled = detail::scene::normalized(*a, *b, top))) {
                    a = &scaled->a, b = &scaled->b;
                    continue;
                }
        } else if constexpr (scaled_by_inputs<A, B>) {
            if (!__builtin_is_constant_evaluated() && !scaled_tried && !arith::in_trusted_range(f.unproven))
                if (const auto c = scaled_inputs_pass(*a, *b, body)) return *c;
        }
        return certainty::uncertain;
    }
}
template <class Tier, class A, class B, class Body>
[[nodiscard]] constexpr bool decide_pair(const A& a, const B& b, const Body& body) {
    if constexpr (std::is_same_v<Tier, approximate>) {
        arith::approx_kernel k;
        return body(k, a, b);
    } else {
        const A* pa = &a;
        const B* pb = &b;
        std::optional<detail::scene::scaled_pair<A, B>> scaled;
        const certainty c = filter_passes(pa, pb, body, scaled);
        if (c != certainty::uncertain) return c == certainty::yes;
        if constexpr (std::is_same_v<Tier, conservative>) return true;
        else if constexpr (std::is_same_v<Tier, aggressive>) return false;
        else return detail::exactly<Body, bool>(*pa, *pb);
    }
}
template <class A, class B, class Body>
[[nodiscard]] constexpr certainty classify_pair(const A& a, const B& b, const Body& body) {
    const A* pa = &a;
    const B* pb = &b;
    std::optional<detail::scene::scaled_pair<A, B>> scaled;
    return filter_passes(pa, pb, body, scaled);
}
} // namespace incidence::detail

namespace incidence::detail {

// A hit or none, in each tier's contract:
//   approximate   the body in plain double; exists is uncertain (plain double proves nothing);
//   exact         the filter's signs with correctly rounded values, then, where a sign was left
//                 open, the whole body in the exact kernel;
//   conservative  the filter's signs with enclosed values; where a sign was left open, the pair's
//                 possible hit (exists uncertain, every value enclosed whatever the hit is);
//   aggressive    the same, and none where a sign was left open.
template <class Tier, class A, class B, class Body>
[[nodiscard]] constexpr auto find_pair(const A& a, const B& b, const Body& body) {
    if constexpr (std::is_same_v<Tier, approximate>) {
        arith::approx_kernel k;
        auto h = body(k, a, b);
        if (h) h->exists = certainty::uncertain;
        return h;
    } else if constexpr (std::is_same_v<Tier, exact>) {
        arith::rounding_kernel<filter_kernel_of<A, B>> f;
        auto h = body(f, a, b);
        if (!f.failed()) return h;
        return detail::exactly<Body, decltype(h)>(a, b);
    } else {
        filter_kernel_of<A, B> f;
        auto h = body(f, a, b);
        if (!f.failed()) return h;
        if constexpr (std::is_same_v<Tier, aggressive>) return decltype(h){};
        else return possible_hit(a, b);
    }
}

// A number (a squared distance), in each tier's contract; an interval tier whose filter left a sign
// open encloses the correctly rounded value by the doubles on either side of it.
template <class Tier, class A, class B, class Body>
[[nodiscard]] constexpr auto value_pair(const A& a, const B& b, const Body& body) {
    if constexpr (std::is_same_v<Tier, approximate>) {
        arith::approx_kernel k;
        return body(k, a, b);
    } else if constexpr (std::is_same_v<Tier, exact>) {
        arith::rounding_kernel<arith::filter_kernel> f;
        const double v = body(f, a, b);
        if (!f.failed()) return v;
        return detail::exactly<Body, double>(a, b);
    } else {
        arith::filter_kernel f;
        const interval v = body(f, a, b);
        if (!f.failed()) return v;
        const double x = detail::exactly<Body, double>(a, b);
        return interval{arith::next_down(x), arith::next_up(x)};
    }
}

} // namespace incidence::detail
