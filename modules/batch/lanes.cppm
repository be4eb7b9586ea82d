// The batches' shared driver: an array of shapes read in blocks of 64 into structure-of-arrays on
// the stack (no heap allocation), each block handed to a SIMD kernel, and the lanes a filtered
// kernel left open (2) answered by the scalar query of the tier.
module;
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
export module incidence.batch:lanes;
import incidence.core;
import incidence.shapes;

namespace incidence::batch::detail {

inline constexpr std::size_t block = 64;

// A shape's numbers in the order the kernels read them as fields: a ray's origin then direction, a
// triangle's a, b, c, a box's min then max, a ball's centre then radius, an oriented box's centre,
// axes and half extents.
inline void unpack(const ray3& r, double* f) {
    const double v[6] = {r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z};
    for (int k = 0; k < 6; ++k) f[k] = v[k];
}
inline void unpack(const triangle3& t, double* f) {
    const double v[9] = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z};
    for (int k = 0; k < 9; ++k) f[k] = v[k];
}
inline void unpack(const aabb3& b, double* f) {
    const double v[6] = {b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z};
    for (int k = 0; k < 6; ++k) f[k] = v[k];
}
inline void unpack(const sphere3& s, double* f) {
    const double v[4] = {s.center.x, s.center.y, s.center.z, s.radius};
    for (int k = 0; k < 4; ++k) f[k] = v[k];
}
inline void unpack(const obb3& b, double* f) {
    const double v[15] = {b.center.x,  b.center.y,  b.center.z,        b.axes[0].x,       b.axes[0].y,
                          b.axes[0].z, b.axes[1].x, b.axes[1].y,       b.axes[1].z,       b.axes[2].x,
                          b.axes[2].y, b.axes[2].z, b.half_extents[0], b.half_extents[1], b.half_extents[2]};
    for (int k = 0; k < 15; ++k) f[k] = v[k];
}
template <class S>
inline constexpr std::size_t fields_of = sizeof(S) / sizeof(double);
static_assert(fields_of<ray3> == 6 && fields_of<triangle3> == 9 && fields_of<aabb3> == 6 && fields_of<sphere3> == 4 &&
              fields_of<obb3> == 15);

// The one shape of a batch as fields, each pointing at its one value (the kernels broadcast it).
template <class Shape>
struct one_fields {
    double values[fields_of<Shape>] = {};
    const double* p[fields_of<Shape>];
    explicit one_fields(const Shape& s) {
        unpack(s, values);
        for (std::size_t k = 0; k < fields_of<Shape>; ++k) p[k] = values + k;
    }
};

// Runs kernel(coords, n, out) over `items` in blocks: coords are the Fields arrays of up to 64
// numbers that unpack(item, fields) writes for each item. The number of lanes that answered 1.
template <std::size_t Fields, class Shape, class Unpack, class Kernel>
std::size_t by_blocks(std::span<const Shape> items, std::uint8_t* out, const Unpack& unpack, const Kernel& kernel) {
    double buffer[Fields][block];
    const double* coords[Fields];
    for (std::size_t k = 0; k < Fields; ++k) coords[k] = buffer[k];
    std::size_t met = 0;
    for (std::size_t start = 0; start < items.size(); start += block) {
        const std::size_t n = items.size() - start < block ? items.size() - start : block;
        for (std::size_t i = 0; i < n; ++i) {
            double fields[Fields];
            unpack(items[start + i], fields);
            for (std::size_t k = 0; k < Fields; ++k) buffer[k][i] = fields[k];
        }
        met += kernel(coords, n, out + start, start);
    }
    return met;
}

// The same over Fields arrays of n floats, widened to double (exactly) 64 at a time.
template <std::size_t Fields, class Kernel>
std::size_t widened_blocks(const float* const* arrays, std::size_t n, std::uint8_t* out, const Kernel& kernel) {
    double buffer[Fields][block];
    const double* coords[Fields];
    for (std::size_t k = 0; k < Fields; ++k) coords[k] = buffer[k];
    std::size_t met = 0;
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        for (std::size_t k = 0; k < Fields; ++k)
            for (std::size_t i = 0; i < m; ++i) buffer[k][i] = arrays[k][start + i];
        met += kernel(coords, m, out + start, start);
    }
    return met;
}

// Is x a float (a NaN is not)? Compared in double, so that no double out of float's range is
// converted.
constexpr bool is_float(double x) {
    if (!(x == x)) return false;
    if (x > 0x1.fffffep127 || x < -0x1.fffffep127) return x == __builtin_huge_val() || x == -__builtin_huge_val();
    return static_cast<double>(static_cast<float>(x)) == x;
}
// A ray's origin and direction as six floats, where all six are floats.
constexpr std::optional<std::array<float, 6>> floats_of(const ray3& r) {
    const double v[6] = {r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z};
    std::array<float, 6> f{};
    for (std::size_t k = 0; k < 6; ++k) {
        if (!is_float(v[k])) return std::nullopt;
        f[k] = static_cast<float>(v[k]);
    }
    return f;
}

// After a kernel: the scalar answer(i) where a lane is open (2; only the filtered kernels leave
// lanes open); the number of lanes met.
template <class Scalar>
std::size_t settle_open(std::uint8_t* out, std::size_t n, const Scalar& answer) {
    std::size_t met = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (out[i] == 2) out[i] = answer(i) ? 1 : 0;
        met += out[i];
    }
    return met;
}

} // namespace incidence::batch::detail
