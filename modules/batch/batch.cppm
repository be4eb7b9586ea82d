// incidence.batch: many queries at once, in SIMD lanes with run-time dispatch (Google Highway):
// one binary runs AVX-512 where the processor has it, AVX2 or SSE4 elsewhere. Each batch answers
// as its scalar query of the same tier does, lane by lane. The SIMD code lives in ordinary .cpp
// units (Highway compiles them once per target); the partitions declare their entry points.
export module incidence.batch;
export import :ray_triangles;
export import :points;
export import :solids;
export import :ray_solids;
export import :culling;
