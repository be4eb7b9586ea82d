// Exact points on spheres: Pythagorean quadruples x^2 + y^2 + z^2 = w^2, permuted and signed.
#pragma once
namespace support {
struct quad {
    double x, y, z, w;
};
inline quad pythagorean(rng& r) {
    static constexpr double q[][4] = {{1, 2, 2, 3},  {2, 3, 6, 7}, {1, 4, 8, 9}, {4, 4, 7, 9},    {2, 6, 9, 11},
                                      {6, 6, 7, 11}, {0, 3, 4, 5}, {0, 0, 1, 1}, {2, 10, 11, 15}, {1, 12, 12, 17}};
    const auto& e = q[r.integer(0, 9)];
    double v[3] = {e[0], e[1], e[2]};
    const int rot = r.integer(0, 2);
    quad out{v[rot], v[(rot + 1) % 3], v[(rot + 2) % 3], e[3]};
    if (r.coin()) out.x = -out.x;
    if (r.coin()) out.y = -out.y;
    if (r.coin()) out.z = -out.z;
    return out;
}
} // namespace support
