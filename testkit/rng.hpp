// The seeded random source shared by the audit's generators and the tests.
#pragma once
#include <cstdint>
#include <random>

namespace audit {
struct rng {
    std::mt19937_64 g;
    // Set by the benchmarks: the tests' generators (support::random_transform) then keep every
    // case at scale 1 near the origin; the tests leave it unset and cover 2^-500..2^500.
    bool at_scale_one = false;
    explicit rng(std::uint64_t s) : g(s) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(g); }
    bool coin() { return integer(0, 1) == 1; }
    std::uint64_t bits() { return g(); }
};
} // namespace audit
