// The batches' contract in the harnesses: every lane of batch::intersects<Tier>(one, many) equals the
// scalar intersects<Tier>(one, many[i]) in the four tiers, and the count is theirs, on the SIMD
// target `pick` chooses among those the processor has (Highway). Any difference aborts. Include
// after `import incidence;`.
#pragma once
#include <hwy/targets.h>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

template <class Tier, class One, class Many>
void batch_is_scalar(const One& one, std::span<const Many> many) {
    std::uint8_t out[16];
    if (many.size() > sizeof out) std::abort();
    const auto met = incidence::batch::intersects<Tier>(one, many, std::span<std::uint8_t>(out, many.size()));
    if (!met) std::abort();
    std::size_t count = 0;
    for (std::size_t i = 0; i < many.size(); ++i) {
        const std::uint8_t scalar = incidence::intersects<Tier>(one, many[i]) ? 1 : 0;
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
