// The checks every polygon pair's test runs (tests/query/<pair>.cpp for polygon2 against a
// point2, segment2, ray2, line2 or polygon2): the CGAL Epeck oracle with every tier contract, and
// the same answer for rewritten polygons (every ring rotated by one vertex, every ring reversed,
// a single ring's end listed or not), rewritten partners and exact translations of both.
// Include after check.hpp and flat_checks.hpp.
#pragma once
#include <algorithm>
#include <string>
#include "polygon_cases.hpp"

namespace support {

inline std::string shape_str(const incidence::polygon2& g) {
    std::string s = "polygon2 " + std::to_string(g.vertices.size()) + " vertices";
    for (const auto& p : g.vertices) s += " " + str(p);
    s += ", ring ends";
    for (auto e : g.ring_ends) s += " " + std::to_string(e);
    return s;
}

inline bool polygon_store_finite(const polygon_store& g) {
    for (const auto& p : g.v)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    return true;
}

// Calls f(a, b) in the pair's canonical argument order.
template <class B, class F>
auto canonical(const incidence::polygon2& g, const B& b, F f) {
    if constexpr (incidence::canonical_pair<incidence::polygon2, B>) return f(g, b);
    else return f(b, g);
}

template <class B>
void polygon_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed());
    polygon_store store, other;
    for (int near = 0; near < 2; ++near) {
        tally t{name + (near ? " near-degenerate" : " random")};
        long skipped = 0;
        for (long i = 0; i < n; ++i) {
            const B b = near ? polygon_near<B>(r, store, other) : polygon_random<B>(r, store, other);
            const polygon2 g = store.view();
            // a far translation that overflowed, or rounded a ring into touching itself: outside
            // the oracle's domain (Polygon_2::bounded_side needs simple rings)
            bool ok = polygon_store_finite(store) && oracle::polygon_simple(polygon_data_of(g));
            if constexpr (std::is_same_v<B, polygon2>) ok = ok && polygon_store_finite(other) && oracle::polygon_simple(polygon_data_of(b));
            else
                for (double x : to_flat(b).v) ok = ok && std::isfinite(x);
            if (!ok) {
                ++skipped;
                continue;
            }
            const bool truth = polygon_truth(g, b);
            canonical(g, b, [&](const auto& x, const auto& y) {
                check_pair(t, x, y, truth, approx_bound, [&] { return shape_str(x) + " " + shape_str(y); });
                return 0;
            });
        }
        std::printf("[cases] %s: %ld generated cases skipped (not finite, or rounded into a non-simple ring)\n", t.name.c_str(), skipped);
        t.print();
        require_contracts(t);
    }
}

// Rewrites of a polygon that keep its point set.
inline std::vector<polygon_store> polygon_rewrites(const polygon_store& g) {
    std::vector<polygon_store> out;
    const incidence::polygon2 view = g.view();
    for (int how = 0; how < 2; ++how) { // every ring rotated by one vertex; every ring reversed
        polygon_store w = g;
        for (std::size_t i = 0; i < view.rings(); ++i) {
            auto b = w.v.begin() + static_cast<long>(view.ring_begin(i)), e = w.v.begin() + static_cast<long>(view.ring_end(i));
            if (how == 0) std::rotate(b, b + 1, e);
            else std::reverse(b, e);
        }
        out.push_back(w);
    }
    if (view.rings() == 1) { // the single ring's end listed, or not
        polygon_store w = g;
        if (w.ends.empty()) w.ends.push_back(static_cast<std::uint32_t>(w.v.size()));
        else w.ends.clear();
        out.push_back(w);
    }
    return out;
}

template <class B>
void polygon_symmetries(const std::string& name, long n) {
    using namespace incidence;
    rng r(seed() + 71);
    polygon_store store, other;
    long checked = 0, bad = 0, yes = 0;
    for (long i = 0; i < n; ++i) {
        const B b = (i % 2) ? polygon_near<B>(r, store, other) : polygon_random<B>(r, store, other);
        const polygon2 g = store.view();
        const bool e = intersects(g, b);
        yes += e;
        auto same = [&](bool x) {
            ++checked;
            if (x != e && ++bad <= 5) std::printf("  %s differs: %s %s\n", name.c_str(), shape_str(g).c_str(), shape_str(b).c_str());
        };
        for (const auto& w : polygon_rewrites(store)) same(intersects(w.view(), b));
        if constexpr (std::is_same_v<B, polygon2>) {
            for (const auto& w : polygon_rewrites(other)) same(intersects(g, w.view()));
        } else {
            for (const auto& b2 : same_set(b)) same(intersects(g, b2));
        }
        const vec3 v{std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)), std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)),
                     0.0};
        auto shift_all = [&](polygon_store& w) {
            for (auto& p : w.v) {
                const auto q = translated(p, v);
                if (!q) return false;
                p = *q;
            }
            return true;
        };
        polygon_store moved_store = store;
        if constexpr (std::is_same_v<B, polygon2>) {
            polygon_store moved_other = other;
            if (shift_all(moved_store) && shift_all(moved_other)) same(intersects(moved_store.view(), moved_other.view()));
        } else {
            const auto bt = translated(b, v);
            if (shift_all(moved_store) && bt) same(intersects(moved_store.view(), *bt));
        }
    }
    std::printf("[cases] %s rewrites and exact translations: %ld checked (%ld pairs intersect), %ld differ\n", name.c_str(), checked, yes,
                bad);
    CHECK(bad == 0);
    CHECK(yes > 0);
}

} // namespace support
