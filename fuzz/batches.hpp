// The batches' contract in the harnesses: every lane of batch::intersects<Tier>(one, many) equals the
// scalar intersects<Tier>(one, many[i]) in the four tiers (rays first: (rays, one) and (ray, one)), and the count is theirs, on the SIMD
// target `pick` chooses among those the processor has (Highway). Any difference aborts. Include
// after `import incidence;`. And the nine triangles two harnesses share.
#pragma once
#include <hwy/targets.h>
#include <array>
#include <cstdint>
#include <algorithm>
#include <cstdlib>
#include <optional>
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
// The same in one tier, which `pick` chooses beside the target: for pairs whose scalar reference
// runs the exact fallback on most raw bit patterns, where four tiers per input would make the
// corpus replay four times as long. The corpus's inputs spread over the four.
template <class One, class Many>
void batch_contracts_one_tier(const One& one, std::span<const Many> many, std::uint8_t pick) {
    static const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    hwy::SetSupportedTargetsForTest(targets[pick % targets.size()]);
    switch (pick / targets.size() % 4) {
    case 0: batch_is_scalar<incidence::exact>(one, many); break;
    case 1: batch_is_scalar<incidence::conservative>(one, many); break;
    case 2: batch_is_scalar<incidence::aggressive>(one, many); break;
    default: batch_is_scalar<incidence::approximate>(one, many); break;
    }
    hwy::SetSupportedTargetsForTest(0);
}

// The first hit of a ray among boxes or balls (batch::intersection): there is one exactly where the
// scalar exact intersection finds some shape hit; its entry is the least of the shapes' correctly
// rounded entries (which order ties below an ulp the batch decides itself: the tests check that)
// and its values are its shape's scalar exact values; conservative and aggressive name the same
// shape, their intervals holding the exact values; approximate finishes. Any difference aborts.
template <class Solid>
void first_hit_contracts(const incidence::ray3& r, std::span<const Solid> many) {
    using namespace incidence;
    const auto e = batch::intersection<exact>(r, many);
    if (!e) std::abort();
    std::optional<double> least;
    for (const Solid& s : many)
        if (const auto h = intersection<exact>(r, s)) least = least ? std::min(*least, h->t_enter) : h->t_enter;
    if (e.value().has_value() != least.has_value()) std::abort();
    if (const auto& h = e.value()) {
        const auto scalar = intersection<exact>(r, many[h->index]);
        if (!scalar || scalar->t_enter != h->t_enter || h->t_enter != *least) std::abort();
        for (const auto& x : {batch::intersection<conservative>(r, many), batch::intersection<aggressive>(r, many)}) {
            if (!x || !x.value() || x.value()->index != h->index || !x.value()->t_enter.contains(h->t_enter) ||
                !x.value()->t_exit.contains(h->t_exit))
                std::abort();
        }
    }
    if (!batch::intersection<approximate>(r, many)) std::abort();
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
