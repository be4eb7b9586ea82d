// The checks of a ball or a capsule against a polygon3 or a solid mesh3 (polygon_sphere,
// capsule_polygon, mesh_sphere, capsule_mesh) on ball_view_cases.hpp's cases, against
// ball_view_truth.hpp's oracle. Include after testing.hpp, check.hpp, the CGAL oracle header,
// flat_checks.hpp, mesh_checks.hpp, polygon3_cases.hpp, polygon3_checks.hpp and capsule_checks.hpp.
#pragma once
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include "ball_view_cases.hpp"

namespace support {

// Every tier against the oracle (qp_oracle_run) on n random and n near-degenerate cases of the
// ball or capsule Round against V (polygon3 or mesh3), in the pair's canonical argument order.
template <class V, class Round>
void round_view_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 61);
    view_store s;
    auto pair_of = [&](const Round& x) {
        V v{};
        if constexpr (std::is_same_v<V, polygon3>) v = s.polygon.g;
        else v = s.mesh.view();
        if constexpr (canonical_pair<V, Round>) return std::pair<V, Round>{v, x};
        else return std::pair<Round, V>{x, v};
    };
    using P = decltype(pair_of(Round{}));
    auto gen = [&](rng& g, bool near) -> std::optional<P> {
        std::optional<Round> x;
        if constexpr (std::is_same_v<V, polygon3>) x = near ? round_near_polygon<Round>(g, s) : round_random_polygon<Round>(g, s);
        else x = near ? round_near_mesh<Round>(g, s) : round_random_mesh<Round>(g, s);
        if (!x) return std::nullopt;
        return pair_of(*x);
    };
    auto truth = [](const auto& a, const auto& b) {
        if constexpr (std::is_same_v<std::decay_t<decltype(a)>, V>) {
            if constexpr (std::is_same_v<V, polygon3>) return round_polygon_truth(a, b);
            else return round_mesh_truth(a, b);
        } else {
            if constexpr (std::is_same_v<V, polygon3>) return round_polygon_truth(b, a);
            else return round_mesh_truth(b, a);
        }
    };
    qp_oracle_run(name, n, approx_bound, r, gen, truth, [](const auto& a, const auto& b) { return shape_str(a) + " " + shape_str(b); });
}

} // namespace support
