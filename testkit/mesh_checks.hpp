// The checks every mesh pair's test runs (tests/query/<pair>.cpp for mesh3 against a point,
// segment, ray, line, plane, triangle, tetrahedron, box, OBB or mesh): the CGAL Epeck oracle with
// every tier contract, and the same answer for rewritten meshes (every triangle's vertices
// rotated, every triangle reversed), rewritten partners and exact translations of both.
// Include after check.hpp and flat_checks.hpp.
#pragma once
#include <stdexcept>
#include <string>
#include "mesh_cases.hpp"
#include "obb_check.hpp"

namespace support {

inline std::string shape_str(const incidence::mesh3& m) {
    std::string s = "mesh " + std::to_string(m.vertices.size()) + " vertices";
    for (const auto& p : m.vertices) s += " " + str(p);
    return s + ", " + std::to_string(m.triangles.size()) + " triangles";
}

// Calls f(a, b) in the pair's canonical argument order.
template <class B, class F>
auto canonical(const incidence::mesh3& m, const B& b, F f) {
    if constexpr (incidence::canonical_pair<incidence::mesh3, B>) return f(m, b);
    else return f(b, m);
}

template <class B>
void mesh_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed());
    mesh_store store, other;
    for (int near = 0; near < 2; ++near) {
        tally t{name + (near ? " near-degenerate" : " random")};
        long skipped = 0, held = 0;
        for (long i = 0; i < n; ++i) {
            const B b = near ? mesh_near<B>(r, store, other) : mesh_random<B>(r, store, other);
            const mesh3 m = store.view();
            bool finite = true;
            for (const auto& p : m.vertices) finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            if constexpr (std::is_same_v<B, plane3>) finite = finite && std::isfinite(b.offset);
            if constexpr (is_set_for_mesh<B>::value) finite = finite && finite_shape(b);
            if (!finite) {
                ++skipped;
                continue;
            } // a far translation that overflowed
            bool truth = false;
            try {
                truth = mesh_truth(m, b);
            } catch (const std::runtime_error&) { // the LP's certificate check declined (inputs across the exponent range)
                ++skipped;
                continue;
            }
            canonical(m, b, [&](const auto& x, const auto& y) {
                check_pair(t, x, y, truth, approx_bound, [&] { return shape_str(x) + " " + shape_str(y); });
                return 0;
            });
            if constexpr (is_set_for_mesh<B>::value) { // the set inside the mesh: no triangle meets it, a point of it decides
                bool off = truth;
                for (std::size_t j = 0; j < m.triangles.size() && off; ++j) off = !intersects(b, m.triangle(j));
                held += off;
            }
        }
        std::printf("[cases] %s: %ld generated cases skipped (not finite, or the oracle declined)\n", t.name.c_str(), skipped);
        t.print();
        require_contracts(t);
        if constexpr (is_set_for_mesh<B>::value) {
            std::printf("[cases] %s: the set lies inside the mesh, meeting no triangle, in %ld cases\n", t.name.c_str(), held);
            if (near) CHECK(held > 0);
        }
    }
}

template <class B>
void mesh_symmetries(const std::string& name, long n) {
    using namespace incidence;
    rng r(seed() + 71);
    mesh_store store, other, rewritten;
    long checked = 0, bad = 0, yes = 0;
    for (long i = 0; i < n; ++i) {
        const B b = (i % 2) ? mesh_near<B>(r, store, other) : mesh_random<B>(r, store, other);
        const mesh3 m = store.view();
        const bool e = intersects(m, b);
        yes += e;
        auto same = [&](bool x) {
            ++checked;
            if (x != e && ++bad <= 5) std::printf("  %s differs: %s %s\n", name.c_str(), shape_str(m).c_str(), shape_str(b).c_str());
        };
        for (int how = 0; how < 2; ++how) { // every triangle rotated; every triangle reversed
            rewritten = store;
            for (auto& t : rewritten.t)
                t = how == 0 ? std::array<std::uint32_t, 3>{t[1], t[2], t[0]} : std::array<std::uint32_t, 3>{t[0], t[2], t[1]};
            same(intersects(rewritten.view(), b));
        }
        if constexpr (!std::is_same_v<B, mesh3> && !std::is_same_v<B, obb3>) {
            for (const auto& b2 : same_set(b)) same(intersects(m, b2));
            const vec3 v{std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)),
                         std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)),
                         std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20))};
            rewritten = store;
            bool exact_move = true;
            for (auto& p : rewritten.v) {
                const auto q = shifted(p, v);
                if (!q) exact_move = false;
                else p = *q;
            }
            const auto bt = translated(b, v);
            if (exact_move && bt) same(intersects(rewritten.view(), *bt));
        }
    }
    std::printf("[cases] %s rewrites and exact translations: %ld checked (%ld pairs intersect), %ld differ\n", name.c_str(), checked, yes,
                bad);
    CHECK(bad == 0);
    CHECK(yes > 0);
}

// contains(mesh, b) on n cases of gen(rng, store) (the mesh left in store, b returned) against
// truth_of(m, b) (std::runtime_error: the oracle declined), with every tier contract; both answers
// must occur, "contained" in at least a twentieth. Returns how many contained cases feature(m, b)
// holds for.
template <class Gen, class Truth, class Feature>
long contains_in_store(const std::string& name, long n, std::uint64_t seed_offset, double approx_bound, Gen gen, Truth truth_of,
                       Feature feature) {
    using namespace incidence;
    rng r(seed() + seed_offset);
    mesh_store store;
    tally t{name};
    long yes = 0, skipped = 0, featured = 0;
    for (long i = 0; i < n; ++i) {
        const auto b = gen(r, store);
        bool fin = finite_shape(b);
        for (const auto& p : store.v) fin = fin && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        if (!fin) {
            ++skipped;
            continue;
        }
        const mesh3 m = store.view();
        bool truth = false;
        try {
            truth = truth_of(m, b);
        } catch (const std::runtime_error&) {
            ++skipped;
            continue;
        }
        yes += truth;
        if (truth) featured += feature(m, b);
        check_contains(t, m, b, truth, approx_bound, [&] { return shape_str(m) + " " + shape_str(b); });
    }
    t.print();
    std::printf("[cases] %s: %ld contained, %ld skipped (declined or not finite)\n", t.name.c_str(), yes, skipped);
    require_contracts(t);
    CHECK(yes > t.n / 20);
    CHECK(yes < t.n);
    return featured;
}

} // namespace support
