// Triangle sets for the scene tests (tests/scene/): random soups at one random scale, and grids
// that objects pass exactly through vertices and edges; the set contract the scene tests and the
// scene harness check. Include after `import incidence;`.
#pragma once
#include "testing.hpp"
#include <algorithm>
#include <set>
#include <type_traits>
#include <vector>

namespace support {

using incidence::aabb3;
using incidence::point3;
using incidence::triangle3;

inline aabb3 box_of(const triangle3& t) {
    return {{std::min({t.a.x, t.b.x, t.c.x}), std::min({t.a.y, t.b.y, t.c.y}), std::min({t.a.z, t.b.z, t.c.z})},
            {std::max({t.a.x, t.b.x, t.c.x}), std::max({t.a.y, t.b.y, t.c.y}), std::max({t.a.z, t.b.z, t.c.z})}};
}

inline bool boxes_meet(const aabb3& a, const aabb3& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// Whether the set a tier lists against a scene (triangles, or pairs of them) keeps its promise: in
// the brute force's set (the scalar tier over everything), equal to it in the exact and aggressive
// tiers, holding the exact set (truth) in the conservative tier, and in the approximate tier
// holding `near` (the plain-double hits whose boxes meet, which the hierarchy never rules out).
template <class Tier, class T>
bool set_contract(const std::set<T>& listed, const std::set<T>& brute, const std::set<T>& truth, const std::set<T>& near) {
    auto within = [](const std::set<T>& a, const std::set<T>& b) { return std::includes(b.begin(), b.end(), a.begin(), a.end()); };
    if (!within(listed, brute)) return false;
    if constexpr (std::is_same_v<Tier, incidence::exact> || std::is_same_v<Tier, incidence::aggressive>) return listed == brute;
    else if constexpr (std::is_same_v<Tier, incidence::conservative>) return within(truth, listed);
    else return within(near, listed);
}

// Random triangles, large ones crossing each other or small ones spread out, at one random scale.
inline std::vector<triangle3> random_soup(rng& r, transform& tr, int n) {
    std::vector<triangle3> ts;
    const bool small = r.coin();
    for (int i = 0; i < n; ++i) {
        const double cx = r.uniform(-1, 1), cy = r.uniform(-1, 1), cz = r.uniform(-1, 1), s = small ? 0.1 : 1.0;
        auto p = [&] {
            return point3{tr.apply(cx * (1 - s) + s * r.uniform(-1, 1), 0), tr.apply(cy * (1 - s) + s * r.uniform(-1, 1), 1),
                          tr.apply(cz * (1 - s) + s * r.uniform(-1, 1), 2)};
        };
        ts.push_back({p(), p(), p()});
    }
    return ts;
}

// Two stacked grids (z = 0 and z = 1, cells of side 1 from -4 to 4 split along a diagonal), some
// triangles repeated (exact ties) or made collinear; axes permuted, then scaled, moved and nudged.
struct grid {
    std::vector<triangle3> ts;
    support::transform tr;
    int perm;
    point3 at(double x, double y, double z) const {
        const double q[3][3] = {{x, y, z}, {z, x, y}, {y, z, x}};
        return {tr.apply(q[perm][0], 0), tr.apply(q[perm][1], 1), tr.apply(q[perm][2], 2)};
    }
};
inline grid make_grid(rng& r) {
    grid g{{}, random_transform(r, r.coin()), r.integer(0, 2)};
    for (int z = 0; z < 2; ++z)
        for (int i = -4; i < 4; ++i)
            for (int j = -4; j < 4; ++j) {
                g.ts.push_back({g.at(i, j, z), g.at(i + 1, j, z), g.at(i + 1, j + 1, z)});
                g.ts.push_back({g.at(i, j, z), g.at(i + 1, j + 1, z), g.at(i, j + 1, z)});
            }
    for (int k = 0; k < 6; ++k) g.ts.push_back(g.ts[static_cast<std::size_t>(r.integer(0, static_cast<int>(g.ts.size()) - 1))]);
    for (int k = 0; k < 4; ++k) {
        const double x = r.integer(-4, 4), y = r.integer(-4, 4);
        g.ts.push_back({g.at(x, y, 0), g.at(x + 1, y + 1, 0), g.at(x + 2, y + 2, 0)});
    }
    return g;
}

} // namespace support
