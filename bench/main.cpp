// Google Benchmark: every query x tier x input set (see bench.hpp). The benchmarks live in one
// file per pair family, compiled separately so the build spreads them over the cores.
// Run: bench/incidence_bench --benchmark_format=json  (the numbers belong in notes, not tests)
#include <benchmark/benchmark.h>

namespace bench {
void register_obb(bool near);
void register_flat_lines(bool near);
void register_flat_solids(bool near);
void register_mesh(bool near);
void register_planar2(bool near);
void register_halfspace(bool near);
void register_classic_rays(bool near);
void register_classic_sat(bool near);
void register_contains(bool near);
void register_intersection(bool near);
void register_distance(bool near);
void register_batch(bool near);
void register_scene(bool near);
} // namespace bench

int main(int argc, char** argv) {
    for (const bool near : {false, true}) {
        bench::register_obb(near);
        bench::register_flat_lines(near);
        bench::register_flat_solids(near);
        bench::register_mesh(near);
        bench::register_planar2(near);
        bench::register_halfspace(near);
        bench::register_classic_rays(near);
        bench::register_classic_sat(near);
        bench::register_contains(near);
        bench::register_intersection(near);
        bench::register_distance(near);
        bench::register_batch(near);
        bench::register_scene(near);
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
