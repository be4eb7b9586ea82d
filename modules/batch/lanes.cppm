// The batches' shared driver: an array of shapes read in blocks of 64 into structure-of-arrays on
// the stack (no heap allocation), each block handed to a SIMD kernel, and the lanes a filtered
// kernel left open (2) answered by the scalar query of the tier.
module;
#include <cstddef>
#include <cstdint>
#include <span>
export module incidence.batch:lanes;
import incidence.core;

namespace incidence::batch::detail {

inline constexpr std::size_t block = 64;

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
