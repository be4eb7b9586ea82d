// The containment oracle test of the boxes and the ball (contain_cases.hpp's generators and
// truth): contains_oracle. Include after testing.hpp and check.hpp.
#pragma once
#include <cstddef>
#include <string>
#include <type_traits>
#include "contain_cases.hpp"
#include "obb_check.hpp"

namespace support {

inline std::string str(const sphere3& s) { return "sphere " + str(s.center) + " " + hex(s.radius); }

// contains(a, b) on `n` random, `n` near (the holding generator, nudged or not) and `n` holding
// cases: every tier's contract against contains_truth, both answers seen, and contained cases
// that the filter cannot decide (touching from inside); comparisons_only: a test that is all
// coordinate comparisons, which the filter always decides. truth_of(a, b) and describe(a, b), where
// given, replace contains_truth and str (for shapes whose oracle lives elsewhere).
template <class A, class B, class Random, class Holding, class Truth = std::nullptr_t, class Describe = std::nullptr_t>
void contains_oracle(const std::string& name, long n, double approx_bound, Random random, Holding holding, bool comparisons_only = false,
                     Truth truth_of = nullptr, Describe describe = nullptr) {
    rng r(seed() + 113);
    tally t{name + " contains"};
    long yes = 0, touching = 0;
    for (long i = 0; i < 2 * n; ++i) {
        const auto [a, b] = i % 2 ? holding(r) : random(r);
        bool truth = false;
        if constexpr (std::is_null_pointer_v<Truth>) truth = contains_truth(a, b);
        else truth = truth_of(a, b);
        yes += truth;
        // contained, and the filter cannot tell: touching from inside, or within rounding of it
        touching += truth && incidence::classify_contains(a, b) == incidence::certainty::uncertain;
        check_contains(t, a, b, truth, approx_bound, [&] {
            if constexpr (std::is_null_pointer_v<Describe>) return str(a) + " " + str(b);
            else return describe(a, b);
        });
    }
    t.print();
    std::printf("[cases] %s contains: %ld of %ld contained, %ld of them undecided by the filter\n", name.c_str(), yes, t.n, touching);
    require_contracts(t);
    CHECK(yes > t.n / 5);
    CHECK(yes < t.n);
    CHECK((comparisons_only ? touching == 0 : touching > 0)); // coordinate comparisons leave nothing open
}

} // namespace support
