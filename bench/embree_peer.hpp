// Embree 3 (Debian libembree-dev) as the ray-casting peer of the scene benchmarks, never a library
// dependency. Its own translation unit: Embree's headers never meet `import incidence;`. Embree
// holds vertices in float, so its scene is the mesh with every coordinate rounded to float.
#pragma once
#include <cstddef>
#include <cstdint>

namespace embree_peer {

struct hit {
    float t;
    std::uint32_t triangle; // the primitive's index; meaningful where found
    bool found;
};

class scene {
public:
    // Vertices as x, y, z triples; triangles as three vertex indices each.
    scene(const double* xyz, std::size_t vertices, const std::uint32_t* triangles, std::size_t count);
    ~scene();
    scene(const scene&) = delete;
    scene& operator=(const scene&) = delete;
    // rtcIntersect1: the first hit of the ray o + t d, t >= 0.
    [[nodiscard]] hit intersect1(const double o[3], const double d[3]) const;
    // rtcIntersect16: sixteen rays (o and d: 16 triples each).
    void intersect16(const double* o, const double* d, hit* out) const;

private:
    void* device_;
    void* scene_;
};

} // namespace embree_peer
