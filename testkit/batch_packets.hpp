// The batches' packets in the tests: a shape's numbers in the order of its packet's arrays, and a
// packet (structure of arrays) built from an array of shapes. Include after `import incidence;`.
#pragma once
#include <type_traits>
#include <vector>

namespace support {

inline void batch_fields(const incidence::aabb3& b, double* v) {
    const double f[6] = {b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z};
    for (int k = 0; k < 6; ++k) v[k] = f[k];
}
inline void batch_fields(const incidence::sphere3& s, double* v) {
    const double f[4] = {s.center.x, s.center.y, s.center.z, s.radius};
    for (int k = 0; k < 4; ++k) v[k] = f[k];
}
inline void batch_fields(const incidence::obb3& b, double* v) {
    const double f[15] = {b.center.x,  b.center.y,  b.center.z,        b.axes[0].x,       b.axes[0].y,
                          b.axes[0].z, b.axes[1].x, b.axes[1].y,       b.axes[1].z,       b.axes[2].x,
                          b.axes[2].y, b.axes[2].z, b.half_extents[0], b.half_extents[1], b.half_extents[2]};
    for (int k = 0; k < 15; ++k) v[k] = f[k];
}
inline incidence::obb3 obb_of_fields(const double* v) {
    using incidence::vec3;
    return {{v[0], v[1], v[2]}, {vec3{v[3], v[4], v[5]}, vec3{v[6], v[7], v[8]}, vec3{v[9], v[10], v[11]}}, {v[12], v[13], v[14]}};
}

// The packet of an array of boxes, balls or oriented boxes: its arrays, and the view of them.
template <class Shape>
struct packet {
    static constexpr int fields = std::is_same_v<Shape, incidence::aabb3> ? 6 : std::is_same_v<Shape, incidence::sphere3> ? 4 : 15;
    std::vector<double> f[fields];
    explicit packet(const std::vector<Shape>& shapes) {
        for (const Shape& s : shapes) {
            double v[fields];
            batch_fields(s, v);
            for (int k = 0; k < fields; ++k) f[k].push_back(v[k]);
        }
    }
    [[nodiscard]] auto view() const {
        using namespace incidence;
        if constexpr (std::is_same_v<Shape, aabb3>) return batch::boxes_soa{f[0], f[1], f[2], f[3], f[4], f[5]};
        else if constexpr (std::is_same_v<Shape, sphere3>) return batch::spheres_soa{f[0], f[1], f[2], f[3]};
        else return batch::obbs_soa{f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], f[9], f[10], f[11], f[12], f[13], f[14]};
    }
};

} // namespace support
