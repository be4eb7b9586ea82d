// The batches' contract in the harnesses: every lane of batch::intersects<Tier>(one, many) equals the
// scalar intersects<Tier>(one, many[i]) in the four tiers (rays first: (rays, one) and (ray, one)), and the count is theirs, on the SIMD
// target `pick` chooses among those the processor has (Highway). Any difference aborts. Include
// after `import incidence;`. And the nine triangles two harnesses share.
#pragma once
#include <hwy/targets.h>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <type_traits>
#include <vector>

template <class Tier, class One, class Many>
void batch_is_scalar(const One& one, std::span<const Many> many) {
    std::uint8_t out[16];
    if (many.size() > sizeof out) std::abort();
    constexpr bool rays = std::is_same_v<Many, incidence::ray3>; // rays come first, as in the scalar query
    const auto met = [&] {
        if constexpr (rays) return incidence::batch::intersects<Tier>(many, one, std::span<std::uint8_t>(out, many.size()));
        else return incidence::batch::intersects<Tier>(one, many, std::span<std::uint8_t>(out, many.size()));
    }();
    if (!met) std::abort();
    std::size_t count = 0;
    for (std::size_t i = 0; i < many.size(); ++i) {
        bool yes;
        if constexpr (rays) yes = incidence::intersects<Tier>(many[i], one);
        else yes = incidence::intersects<Tier>(one, many[i]);
        const std::uint8_t scalar = yes ? 1 : 0;
        if (out[i] != scalar) std::abort();
        count += scalar;
    }
    if (met.value() != count) std::abort();
}
template <class One, class Many>
void batch_contracts(const One& one, std::span<const Many> many, std::uint8_t pick) {
    static const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    hwy::SetSupportedTargetsForTest(targets[pick % targets.size()]);
    batch_is_scalar<incidence::exact>(one, many);
    batch_is_scalar<incidence::conservative>(one, many);
    batch_is_scalar<incidence::aggressive>(one, many);
    batch_is_scalar<incidence::approximate>(one, many);
    hwy::SetSupportedTargetsForTest(0);
}

// The nine triangles the ray_triangle and scene harnesses read from doubles 0..31: t (6..14), u (the
// ray's two points and 15..17), t's vertices permuted, p q w (18..26), t's edges with other apexes
// (x: 27..29), the ray's origin, and one with doubles 30, 31, 0.
inline std::array<incidence::triangle3, 9> nine_triangles(const double* v) {
    using incidence::point3, incidence::triangle3;
    const triangle3 t{{v[6], v[7], v[8]}, {v[9], v[10], v[11]}, {v[12], v[13], v[14]}};
    const triangle3 u{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[15], v[16], v[17]}};
    const point3 p{v[18], v[19], v[20]}, q{v[21], v[22], v[23]}, w{v[24], v[25], v[26]}, x{v[27], v[28], v[29]};
    return {t, u, {t.b, t.c, t.a}, {t.a, t.c, t.b}, {p, q, w}, {t.a, t.b, x}, {t.b, t.c, p}, {u.a, q, t.c}, {{v[30], v[31], v[0]}, t.a, w}};
}
