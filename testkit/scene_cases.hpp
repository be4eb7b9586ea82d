// Triangle sets for the scene tests (tests/scene/): random soups at one random scale, and grids
// that objects pass exactly through vertices and edges. Include after `import incidence;` and
// testing.hpp.
#pragma once
#include <algorithm>
#include <vector>

namespace support {

using incidence::aabb3;
using incidence::point3;
using incidence::triangle3;

inline aabb3 box_of(const triangle3& t) {
    return {{std::min({t.a.x, t.b.x, t.c.x}), std::min({t.a.y, t.b.y, t.c.y}), std::min({t.a.z, t.b.z, t.c.z})},
            {std::max({t.a.x, t.b.x, t.c.x}), std::max({t.a.y, t.b.y, t.c.y}), std::max({t.a.z, t.b.z, t.c.z})}};
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
