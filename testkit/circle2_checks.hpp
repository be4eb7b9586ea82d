// The checks of a circle2 against a point2, circle2, segment2, ray2, line2 or polygon2, and of
// contains(circle2, point2 | segment2 | circle2 | polygon2) and contains(polygon2, circle2), on circle2_cases.hpp's cases against its
// oracle (every tier's contract, both argument orders, classify). Include after testing.hpp,
// check.hpp and the CGAL oracle header.
#pragma once
#include <optional>
#include <string>
#include "circle2_cases.hpp"
#include "ball_halfspace_checks.hpp"
#include "contain_checks.hpp"

namespace support {

inline std::string shape_str(const incidence::circle2& c) { return "circle2 " + str(c.center) + " " + hex(c.radius); }
template <class B>
std::string disk_partner_str(const B& b) {
    if constexpr (std::is_same_v<B, incidence::polygon2>) {
        std::string s = "polygon2";
        for (const incidence::point2 p : b.vertices) s += " " + str(p);
        return s;
    } else {
        return shape_str(b);
    }
}
// Every tier of intersects(circle2, B) against the oracle (ball_halfspace_checks.hpp's qp_oracle_run).
template <class B>
void disk_oracle(const std::string& name, long n, double approx_bound) {
    rng r(seed() + 41);
    polygon_store store;
    qp_oracle_run(
        name, n, approx_bound, r, [&](rng& g, bool near) { return near ? disk_near<B>(g, store) : disk_random<B>(g, store); },
        [](const incidence::circle2& c, const B& b) { return std::optional<bool>(disk_truth(c, b)); },
        [](const incidence::circle2& c, const B& b) { return shape_str(c) + " " + disk_partner_str(b); });
}

template <class B>
void disk_contains(const std::string& name, long n, double approx_bound) {
    polygon_store store;
    contains_oracle<incidence::circle2, B>(
        name + " (circle around the other)", n, approx_bound, [&](rng& g) { return disk_random_around<B>(g, store); },
        [&](rng& g) { return disk_holding<B>(g, store); }, false,
        [](const incidence::circle2& c, const B& b) { return disk_holds_truth(c, b); },
        [](const incidence::circle2& c, const B& b) { return shape_str(c) + " " + disk_partner_str(b); });
}

// contains(polygon2, circle2) on `n` random disks (disk_random) and `n` disks in a star polygon
// (disk_in_star) against polygon_holds_disk_truth.
inline void polygon_holds_disk(const std::string& name, long n, double approx_bound) {
    using incidence::circle2;
    using incidence::polygon2;
    polygon_store store;
    contains_oracle<polygon2, circle2>(
        name + " (polygon around the disk)", n, approx_bound,
        [&](rng& g) {
            const auto [c, p] = disk_random_around<polygon2>(g, store);
            return std::pair{p, c};
        },
        [&](rng& g) {
            const circle2 c = disk_in_star(g, store);
            return std::pair{store.view(), c};
        },
        false, [](const polygon2& p, const circle2& c) { return polygon_holds_disk_truth(p, c); },
        [](const polygon2& p, const circle2& c) { return disk_partner_str(p) + " " + shape_str(c); });
}

} // namespace support
