// Point sets for the bounding-volume tests: generic, degenerate and real. Include after
// `import incidence;` and testing.hpp.
#pragma once
#include "mesh_io.hpp"
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace support {

struct point_set {
    std::string name;
    std::vector<incidence::point3> points;
};

// The meshes run.sh unpacks from Debian's libcgal-demo into build/data/meshes.
inline std::vector<point_set> real_meshes() {
    std::vector<point_set> out;
    const std::filesystem::path dir = std::filesystem::path(INCIDENCE_SOURCE_DIR) / "build/data/meshes";
    for (const char* m : {"bunny00", "armadillo", "elephant", "fandisk", "ChineseDragon-10kv"}) {
        const auto f = dir / (std::string(m) + ".off");
        if (std::filesystem::exists(f)) out.push_back({m, audit::read_mesh(f.string()).vertices});
    }
    return out;
}
inline bool meshes_required() { return std::getenv("INCIDENCE_REQUIRE_MESHES") != nullptr; }

inline std::vector<point_set> point_sets(rng& r, long n) {
    using incidence::point3;
    std::vector<point_set> s;
    auto add = [&](std::string name, auto f) {
        point_set p{std::move(name), {}};
        for (long i = 0; i < n; ++i) p.points.push_back(f(i));
        s.push_back(std::move(p));
    };
    add("cube", [&](long) { return point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}; });
    add("flat slab", [&](long) { return point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(0, 1e-9)}; });
    add("coplanar (z = x + y)", [&](long) {
        const double x = r.integer(-1000, 1000), y = r.integer(-1000, 1000);
        return point3{x, y, x + y};
    });
    add("collinear", [&](long) {
        const double t = r.integer(-100000, 100000);
        return point3{3 * t, -2 * t + 1, t};
    });
    add("duplicates of 5 points", [&](long i) { return point3{double(i % 5), double((i % 5) * (i % 5)), 1.0}; });
    add("one point repeated", [&](long) { return point3{0.1, 0.2, 0.3}; });
    add("cospherical (radius 13, integer points)", [&](long) {
        static constexpr int q[][3] = {{3, 4, 12}, {4, 3, 12}, {12, 3, 4}, {12, 4, 3}, {3, 12, 4}, {4, 12, 3},
                                       {0, 5, 12}, {5, 0, 12}, {12, 5, 0}, {13, 0, 0}, {0, 13, 0}, {0, 0, 13}};
        const auto& e = q[r.integer(0, 11)];
        return point3{(r.coin() ? 1 : -1) * double(e[0]) + 7, (r.coin() ? 1 : -1) * double(e[1]) - 3, (r.coin() ? 1 : -1) * double(e[2])};
    });
    add("one-ulp cluster",
        [&](long) { return point3{nudge(1.0, r.integer(-3, 3)), nudge(-2.0, r.integer(-3, 3)), nudge(0.5, r.integer(-3, 3))}; });
    add("near 1e300", [&](long) { return point3{r.uniform(-1, 1) * 1e300, r.uniform(-1, 1) * 1e300, 1e300}; });
    add("near 1e-300", [&](long) { return point3{r.uniform(-1, 1) * 1e-300, r.uniform(-1, 1) * 1e-300, 1e-300}; });
    add("subnormal", [&](long) { return point3{r.integer(-50, 50) * 0x1p-1074, r.integer(-50, 50) * 0x1p-1074, 0.0}; });
    add("far from the origin", [&](long) { return point3{1e9 + r.uniform(0, 1), -1e9 + r.uniform(0, 1), 1e9}; });
    s.push_back({"one point", {point3{1, 2, 3}}});
    s.push_back({"two points", {point3{1, 2, 3}, point3{-1, 0.5, 7}}});
    return s;
}

} // namespace support
