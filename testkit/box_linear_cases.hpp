// Near-degenerate and random cases for a box against a ray, a segment or a line: a box with
// small dyadic bounds (flat boxes included) and a line through a point on its face, edge or
// corner (or a quarter off it), sometimes in a face plane or axis-parallel, then a random exact-
// or-nudged scale and translation. The caller turns (origin, direction) into its shape. Include
// after testing.hpp.
#pragma once
#include <utility>

namespace support {
struct box_linear_case {
    incidence::aabb3 box;
    double O[3], D[3]; // untransformed origin and direction (small dyadics)
    transform tr;
    incidence::point3 point(double t) const { // origin + t direction, transformed
        return {tr.apply(O[0] + t * D[0], 0), tr.apply(O[1] + t * D[1], 1), tr.apply(O[2] + t * D[2], 2)};
    }
    incidence::vec3 direction() const { return {tr.dir(D[0]), tr.dir(D[1]), tr.dir(D[2])}; }
};
inline box_linear_case box_linear_near(rng& r) {
    box_linear_case c;
    double lo[3], hi[3], target[3];
    for (int i = 0; i < 3; ++i) {
        lo[i] = small(r);
        hi[i] = lo[i] + r.integer(0, 8) * 0.5; // flat boxes included
    }
    for (int i = 0; i < 3; ++i) { // a face, edge or corner point, sometimes a quarter off
        const int w = r.integer(0, 2);
        target[i] = w == 0 ? lo[i] : (w == 1 ? hi[i] : (lo[i] + hi[i]) * 0.5);
        if (r.integer(0, 5) == 0) target[i] += r.coin() ? 0.25 : -0.25;
    }
    for (int i = 0; i < 3; ++i) {
        c.O[i] = small(r);
        if (r.integer(0, 4) == 0) c.O[i] = target[i]; // in a face plane / axis-parallel
        c.D[i] = target[i] - c.O[i];
        if (r.integer(0, 9) == 0) c.D[i] = -c.D[i];
    }
    c.tr = random_transform(r, true);
    const auto& tr = c.tr;
    c.box = ordered(incidence::aabb3{{tr.apply(lo[0], 0), tr.apply(lo[1], 1), tr.apply(lo[2], 2)},
                                     {tr.apply(hi[0], 0), tr.apply(hi[1], 1), tr.apply(hi[2], 2)}});
    return c;
}
inline box_linear_case box_linear_random(rng& r) {
    box_linear_case c;
    c.tr = random_transform(r, false);
    auto q = [&](int i) { return random_coord(r, c.tr, i); };
    const incidence::point3 a{q(0), q(1), q(2)}, b{q(0), q(1), q(2)};
    c.box = ordered(incidence::aabb3{a, b});
    for (int i = 0; i < 3; ++i) c.O[i] = q(i), c.D[i] = c.tr.scale_only(r.uniform(-1, 1));
    c.tr.t[0] = c.tr.t[1] = c.tr.t[2] = 0; // O and D are final coordinates: the identity from here
    c.tr.k = 0;
    return c;
}
} // namespace support
