// Benchmarks: batches. One ray against a set of triangles, and a box or a ball against a set of
// points (batch::intersects: <tier>/batch_intersects/{aabb,sphere}_points[_soa]/<dist> beside
// <tier>/scalar_loop/{aabb,sphere}_points/<dist>). The triangles in every tier,
// beside the loop over the scalar query that it replaces, on each SIMD target the processor has:
//   <tier>/batch_intersects/ray_triangles/<dist>              the dispatched (best) target
//   <tier>/batch_intersects/ray_triangles_<TARGET>/<dist>     one target (AVX3 = AVX-512, AVX2, SSE4)
//   <tier>/scalar_loop/ray_triangles/<dist>                   intersects<Tier>(ray, t) for each t
//   <tier>/batch_intersects/ray_triangles_soa/<dist>          the packet entry (batch::triangles_soa)
// Each iteration is one ray against the whole set; the counter s_per_test is the time per
// ray-triangle test, in seconds. Sets: random (triangles and rays in the unit cube, as the other random sets)
// and mesh (a grid mesh whose edges and vertices the rays pass exactly, and rays in its plane: the
// filter leaves many lanes to the scalar query there). Before timing, every lane is checked against
// the scalar query of its tier (and the exact tier against the oracle).
#include "bench.hpp"
#include <hwy/targets.h>
#include <span>

// The filter kernel itself (modules/batch/ray_triangles.cppm declares it; not exported): the
// benchmarks report the share of lanes it leaves to the scalar query.
namespace incidence::batch::simd {
void ray_triangles_filter(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out);
}

namespace bench {
namespace {

struct ray_batch {
    ray3 ray;
    std::vector<triangle3> triangles;
};

std::vector<ray_batch> batch_set(bool near) {
    std::vector<ray_batch> out;
    const std::size_t per_ray = set_size;
    for (int k = 0; k < 16; ++k) {
        ray_batch b;
        if (!near) {
            const point3 o = rp(), aim = rp();
            b.ray = ray3{o, vec3{aim.x - o.x, aim.y - o.y, aim.z - o.z}};
            for (std::size_t i = 0; i < per_ray; ++i) b.triangles.push_back({rp(), rp(), rp()});
        } else {
            // a grid of unit cells in z = 0, each split along a diagonal, as many as the set size
            const int side = static_cast<int>(std::sqrt(static_cast<double>(per_ray) / 2.0)) + 1;
            for (int i = 0; i < side; ++i)
                for (int j = 0; j < side && b.triangles.size() < per_ray; ++j) {
                    const double x = i - side / 2, y = j - side / 2;
                    b.triangles.push_back({{x, y, 0}, {x + 1, y, 0}, {x + 1, y + 1, 0}});
                    b.triangles.push_back({{x, y, 0}, {x + 1, y + 1, 0}, {x, y + 1, 0}});
                }
            b.triangles.resize(per_ray, b.triangles.front());
            const double tx = irand(-4, 4) + (k % 3 == 1 ? 0.5 : 0.0), ty = irand(-4, 4);
            const bool coplanar = k % 4 == 3;
            const point3 o{small(), small(), coplanar ? 0.0 : small()};
            b.ray = ray3{o, vec3{tx - o.x, ty - o.y, -o.z}};
        }
        out.push_back(std::move(b));
    }
    return out;
}

template <class Tier>
bool batch_matches_scalar(const std::vector<ray_batch>& set) {
    for (const ray_batch& b : set) {
        std::vector<std::uint8_t> out(b.triangles.size());
        if (!batch::intersects<Tier>(b.ray, std::span<const triangle3>(b.triangles), out)) return false;
        for (std::size_t i = 0; i < out.size(); ++i)
            if ((out[i] == 1) != intersects<Tier>(b.ray, b.triangles[i])) return false;
    }
    return true;
}
bool exact_matches_oracle(const std::vector<ray_batch>& set) {
    for (const ray_batch& b : set) {
        double o[3], d[3];
        arr(b.ray.origin, o);
        arr(b.ray.direction, d);
        for (const triangle3& t : b.triangles) {
            double a[3], bb[3], c[3];
            arr(t.a, a);
            arr(t.b, bb);
            arr(t.c, c);
            if (intersects<exact>(b.ray, t) != oracle::ray_triangle(o, d, a, bb, c)) return false;
        }
    }
    return true;
}

// The set's triangles as structure of arrays, for the packet entry point.
struct soa_set {
    std::vector<double> c[9];
    batch::triangles_soa view() const { return {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]}; }
};
soa_set as_soa(const ray_batch& b) {
    soa_set s;
    for (const triangle3& t : b.triangles) {
        const double v[9] = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z};
        for (int k = 0; k < 9; ++k) s.c[k].push_back(v[k]);
    }
    return s;
}

// The share of lanes the SIMD filter leaves to the scalar query, in percent.
double open_pct(const std::vector<ray_batch>& set) {
    std::size_t open = 0, lanes = 0;
    for (const ray_batch& b : set) {
        std::vector<double> c[9];
        for (const triangle3& t : b.triangles) {
            const double v[9] = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z};
            for (int k = 0; k < 9; ++k) c[k].push_back(v[k]);
        }
        const double* coords[9];
        for (int k = 0; k < 9; ++k) coords[k] = c[k].data();
        const double o[3] = {b.ray.origin.x, b.ray.origin.y, b.ray.origin.z},
                     d[3] = {b.ray.direction.x, b.ray.direction.y, b.ray.direction.z};
        std::vector<std::uint8_t> out(b.triangles.size());
        incidence::batch::simd::ray_triangles_filter(o, d, coords, out.size(), out.data());
        for (const std::uint8_t x : out) open += x == 2;
        lanes += out.size();
    }
    return 100.0 * static_cast<double>(open) / static_cast<double>(lanes);
}

// target 0: the dispatched one; soa: the packet entry point (else the array of triangle3).
template <class Tier>
void reg_batch(const std::string& name, const std::vector<ray_batch>& set, std::int64_t target, bool soa = false) {
    benchmark::RegisterBenchmark(name.c_str(), [set, target, soa](benchmark::State& st) {
        hwy::SetSupportedTargetsForTest(target);
        if (!batch_matches_scalar<Tier>(set)) {
            hwy::SetSupportedTargetsForTest(0);
            st.SkipWithError("a lane differs from the scalar answer");
            return;
        }
        std::vector<std::uint8_t> out(set.front().triangles.size());
        std::vector<soa_set> packets;
        for (const ray_batch& b : set) packets.push_back(as_soa(b));
        std::size_t k = 0;
        for (auto _ : st) {
            const ray_batch& b = set[k];
            if (soa) benchmark::DoNotOptimize(batch::intersects<Tier>(b.ray, packets[k].view(), out));
            else benchmark::DoNotOptimize(batch::intersects<Tier>(b.ray, std::span<const triangle3>(b.triangles), out));
            benchmark::ClobberMemory();
            if (++k == set.size()) k = 0;
        }
        if constexpr (!std::is_same_v<Tier, approximate>) st.counters["open_pct"] = open_pct(set);
        hwy::SetSupportedTargetsForTest(0);
        st.counters["s_per_test"] = benchmark::Counter(static_cast<double>(out.size()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    });
}
template <class Tier>
void reg_loop(const std::string& name, const std::vector<ray_batch>& set) {
    benchmark::RegisterBenchmark(name.c_str(), [set](benchmark::State& st) {
        std::vector<std::uint8_t> out(set.front().triangles.size());
        std::size_t k = 0;
        for (auto _ : st) {
            const ray_batch& b = set[k];
            for (std::size_t i = 0; i < b.triangles.size(); ++i) out[i] = intersects<Tier>(b.ray, b.triangles[i]) ? 1 : 0;
            benchmark::DoNotOptimize(out.data());
            benchmark::ClobberMemory();
            if (++k == set.size()) k = 0;
        }
        st.counters["s_per_test"] = benchmark::Counter(static_cast<double>(out.size()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    });
}

template <class Tier>
void reg_tier(const std::string& tier, const std::string& dist, const std::vector<ray_batch>& set) {
    reg_batch<Tier>(tier + "/batch_intersects/ray_triangles/" + dist, set, 0);
    reg_batch<Tier>(tier + "/batch_intersects/ray_triangles_soa/" + dist, set, 0, true);
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        const std::string t = hwy::TargetName(target);
        if (t == "AVX3" || t == "AVX2" || t == "SSE4")
            reg_batch<Tier>(tier + "/batch_intersects/ray_triangles_" + t + "/" + dist, set, target);
    }
    reg_loop<Tier>(tier + "/scalar_loop/ray_triangles/" + dist, set);
}

// Points against one box and one ball: 16 solids, each against the set's points (random: in the
// unit cube around them; near_degenerate: every point within 4 ulps of the solid's boundary).
struct solid_points {
    aabb3 box;
    sphere3 ball;
    std::vector<point3> points;
};
std::vector<solid_points> points_set(bool near) {
    std::vector<solid_points> out;
    for (int k = 0; k < 16; ++k) {
        solid_points s;
        s.box = box(rp(), rp());
        s.ball = sphere3{rp(), uni(0.25, 1.0)};
        for (std::size_t i = 0; i < set_size; ++i) {
            if (!near) {
                s.points.push_back(rp());
            } else if (i % 2 == 0) { // on a face of the box, nudged
                point3 p{uni(s.box.min.x, s.box.max.x), uni(s.box.min.y, s.box.max.y), uni(s.box.min.z, s.box.max.z)};
                p.x = irand(0, 1) == 0 ? s.box.min.x : s.box.max.x;
                s.points.push_back(np(p.x, p.y, p.z));
            } else { // on the sphere (rounded), nudged
                const double a = uni(0, 6.283185307179586), b = uni(-1, 1), c = std::sqrt(1 - b * b);
                const point3 m = s.ball.center;
                s.points.push_back(
                    np(m.x + s.ball.radius * c * std::cos(a), m.y + s.ball.radius * c * std::sin(a), m.z + s.ball.radius * b));
            }
        }
        out.push_back(std::move(s));
    }
    return out;
}

template <class Tier, bool Ball>
void reg_points(const std::string& name, const std::vector<solid_points>& set, int entry) { // entry 0 array, 1 packet, 2 scalar loop
    benchmark::RegisterBenchmark(name.c_str(), [set, entry](benchmark::State& st) {
        auto solid = [](const solid_points& s) {
            if constexpr (Ball) return s.ball;
            else return s.box;
        };
        std::vector<std::uint8_t> out(set.front().points.size());
        for (const solid_points& s : set) { // every lane against the scalar answer before timing
            if (!batch::intersects<Tier>(solid(s), std::span<const point3>(s.points), out)) return st.SkipWithError("refused");
            for (std::size_t i = 0; i < out.size(); ++i)
                if ((out[i] == 1) != intersects<Tier>(solid(s), s.points[i]))
                    return st.SkipWithError("a lane differs from the scalar answer");
        }
        std::vector<std::vector<double>> soa;
        for (const solid_points& s : set)
            for (int k = 0; k < 3; ++k) {
                soa.emplace_back();
                for (const point3& p : s.points) soa.back().push_back(k == 0 ? p.x : (k == 1 ? p.y : p.z));
            }
        std::size_t k = 0;
        for (auto _ : st) {
            const solid_points& s = set[k];
            if (entry == 0) benchmark::DoNotOptimize(batch::intersects<Tier>(solid(s), std::span<const point3>(s.points), out));
            else if (entry == 1)
                benchmark::DoNotOptimize(
                    batch::intersects<Tier>(solid(s), batch::points_soa{soa[3 * k], soa[3 * k + 1], soa[3 * k + 2]}, out));
            else
                for (std::size_t i = 0; i < out.size(); ++i) out[i] = intersects<Tier>(solid(s), s.points[i]) ? 1 : 0;
            benchmark::ClobberMemory();
            if (++k == set.size()) k = 0;
        }
        st.counters["s_per_test"] = benchmark::Counter(static_cast<double>(out.size()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    });
}
template <class Tier>
void reg_points_tier(const std::string& tier, const std::string& dist, const std::vector<solid_points>& set) {
    reg_points<Tier, false>(tier + "/batch_intersects/aabb_points/" + dist, set, 0);
    reg_points<Tier, false>(tier + "/batch_intersects/aabb_points_soa/" + dist, set, 1);
    reg_points<Tier, false>(tier + "/scalar_loop/aabb_points/" + dist, set, 2);
    reg_points<Tier, true>(tier + "/batch_intersects/sphere_points/" + dist, set, 0);
    reg_points<Tier, true>(tier + "/batch_intersects/sphere_points_soa/" + dist, set, 1);
    reg_points<Tier, true>(tier + "/scalar_loop/sphere_points/" + dist, set, 2);
}

} // namespace

void register_batch(bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    const auto set = batch_set(near);
    if (!exact_matches_oracle(set)) {
        benchmark::RegisterBenchmark(("exact/batch_intersects/ray_triangles/" + dist).c_str(),
                                     [](benchmark::State& st) { st.SkipWithError("the exact tier disagrees with the oracle"); });
        return;
    }
    reg_tier<exact>("exact", dist, set);
    reg_tier<conservative>("conservative", dist, set);
    reg_tier<aggressive>("aggressive", dist, set);
    reg_tier<approximate>("approximate", dist, set);
    const auto points = points_set(near);
    reg_points_tier<exact>("exact", dist, points);
    reg_points_tier<conservative>("conservative", dist, points);
    reg_points_tier<aggressive>("aggressive", dist, points);
    reg_points_tier<approximate>("approximate", dist, points);
}

} // namespace bench
