// Benchmarks: batches. One ray against a set of triangles, and its first hit among them
// (<tier>/batch_intersection/ray_triangles/<dist> beside <tier>/scalar_loop_intersection/...); a
// box, a ball or a tetrahedron against a set of points (batch::intersects:
// <tier>/batch_intersects/{aabb,sphere}_points[_soa]/<dist> and tetrahedron_points beside
// <tier>/scalar_loop/...); a box or a ball against a set of boxes or balls (aabb_aabbs,
// aabb_spheres, sphere_aabbs, sphere_spheres, the same way); a set of rays against one triangle,
// box or ball (rays_triangle, rays_aabb, rays_sphere) and one ray against boxes or balls
// (ray_aabbs, ray_spheres; and its first hit among them, <tier>/batch_intersection/ray_aabbs and
// ray_spheres beside <tier>/scalar_loop_intersection/...); boxes against a frustum (frustum_aabbs, and the classic culling test's
// loop, approximate/method_culling_loop/frustum_aabbs) and oriented boxes against it
// (frustum_obbs) and balls (frustum_spheres, and the classic test's loop); oriented boxes against
// one box or one ball (aabb_obbs, sphere_obbs). The triangles in every tier,
// beside the loop over the scalar query that it replaces, on each SIMD target the processor has:
//   <tier>/batch_intersects/ray_triangles/<dist>              the dispatched (best) target
//   <tier>/batch_intersects/ray_triangles_<TARGET>/<dist>     one target (AVX3 = AVX-512, AVX2, SSE4)
//   <tier>/scalar_loop/ray_triangles/<dist>                   intersects<Tier>(ray, t) for each t
//   <tier>/batch_intersects/ray_triangles_soa/<dist>          the packet entry (batch::triangles_soa)
//   <tier>/batch_intersects/ray_triangles_soa_float/<dist>    the float packet (batch::triangles_soa_f;
//                                                             the set rounded to float)
// Each iteration is one ray against the whole set; the counter s_per_test is the time per
// ray-triangle test, in seconds. Sets: random (triangles and rays in the unit cube, as the other random sets)
// and mesh (a grid mesh whose edges and vertices the rays pass exactly, and rays in its plane: the
// filter leaves many lanes to the scalar query there). Before timing, every lane is checked against
// the scalar query of its tier (and the exact tier against the oracle).
#include "bench.hpp"
#include <hwy/targets.h>
#include <algorithm>
#include <optional>
#include <span>
#include <utility>

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
// The set in floats (each number rounded to float; the ray too, so that the approximate tier runs
// in float lanes): the packet entry for triangles_soa_f. Before timing, the filtered tiers' lanes
// against the scalar query on the widened triangles.
struct float_set {
    ray3 ray;
    std::vector<float> c[9];
    batch::triangles_soa_f view() const { return {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]}; }
};
double to_float(double x) { return static_cast<float>(x); }
float_set as_float(const ray_batch& b) {
    float_set s;
    s.ray = ray3{{to_float(b.ray.origin.x), to_float(b.ray.origin.y), to_float(b.ray.origin.z)},
                 {to_float(b.ray.direction.x), to_float(b.ray.direction.y), to_float(b.ray.direction.z)}};
    for (const triangle3& t : b.triangles) {
        const double v[9] = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z};
        for (int k = 0; k < 9; ++k) s.c[k].push_back(static_cast<float>(v[k]));
    }
    return s;
}
template <class Tier>
void reg_float_batch(const std::string& name, const std::vector<ray_batch>& set) {
    benchmark::RegisterBenchmark(name.c_str(), [set](benchmark::State& st) {
        std::vector<float_set> packets;
        for (const ray_batch& b : set) packets.push_back(as_float(b));
        std::vector<std::uint8_t> out(set.front().triangles.size());
        if constexpr (!std::is_same_v<Tier, approximate>)
            for (const float_set& f : packets) {
                if (!batch::intersects<Tier>(f.ray, f.view(), out)) return st.SkipWithError("refused");
                for (std::size_t i = 0; i < out.size(); ++i)
                    if ((out[i] == 1) != intersects<Tier>(f.ray, f.view()[i]))
                        return st.SkipWithError("a lane differs from the scalar answer");
            }
        std::size_t k = 0;
        for (auto _ : st) {
            benchmark::DoNotOptimize(batch::intersects<Tier>(packets[k].ray, packets[k].view(), out));
            benchmark::ClobberMemory();
            if (++k == packets.size()) k = 0;
        }
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

// The first hit of one ray among the set's triangles: the batch (entry 0), and the loop over the
// scalar intersection keeping the least t (entry 1; ties to the first, plain comparisons of the
// tier's t, so only a time to compare with). Before timing, the batch against the scene's first
// hit over the same triangles.
template <class Tier>
void reg_first_hit(const std::string& name, const std::vector<ray_batch>& set, int entry) {
    benchmark::RegisterBenchmark(name.c_str(), [set, entry](benchmark::State& st) {
        for (const ray_batch& b : set) {
            const auto h = batch::intersection<Tier>(b.ray, std::span<const triangle3>(b.triangles));
            const auto scene = scene3::make(std::span<const triangle3>(b.triangles));
            if (!h || !scene) return st.SkipWithError("refused");
            const auto truth = intersection<Tier>(b.ray, scene.value());
            if (h.value().has_value() != truth.has_value() || (truth && h.value()->triangle != truth->triangle))
                if constexpr (!std::is_same_v<Tier, approximate>) return st.SkipWithError("the first hit differs from the scene's");
        }
        std::size_t k = 0, hits = 0;
        for (auto _ : st) {
            const ray_batch& b = set[k];
            if (entry == 0) {
                const auto h = batch::intersection<Tier>(b.ray, std::span<const triangle3>(b.triangles));
                hits += h.value().has_value();
            } else {
                std::optional<std::size_t> best;
                double t_best = 0;
                for (std::size_t i = 0; i < b.triangles.size(); ++i)
                    if (const auto h = intersection<Tier>(b.ray, b.triangles[i])) {
                        const double t = [&] {
                            if constexpr (std::is_same_v<std::decay_t<decltype(h->t)>, double>) return h->t;
                            else return h->t.lo;
                        }();
                        if (!best || t < t_best) best = i, t_best = t;
                    }
                hits += best.has_value();
            }
            benchmark::ClobberMemory();
            if (++k == set.size()) k = 0;
        }
        benchmark::DoNotOptimize(hits);
        st.counters["s_per_test"] = benchmark::Counter(static_cast<double>(set.front().triangles.size()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    });
}

template <class Tier>
void reg_tier(const std::string& tier, const std::string& dist, const std::vector<ray_batch>& set) {
    reg_first_hit<Tier>(tier + "/batch_intersection/ray_triangles/" + dist, set, 0);
    reg_first_hit<Tier>(tier + "/scalar_loop_intersection/ray_triangles/" + dist, set, 1);
    reg_batch<Tier>(tier + "/batch_intersects/ray_triangles/" + dist, set, 0);
    reg_batch<Tier>(tier + "/batch_intersects/ray_triangles_soa/" + dist, set, 0, true);
    reg_float_batch<Tier>(tier + "/batch_intersects/ray_triangles_soa_float/" + dist, set);
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

// One shape against many, for the families without a packet bench above: a tetrahedron against
// points, and a box or a ball against boxes or balls. 16 sets; each iteration one shape against
// its set; before timing every lane is checked against the scalar answer. entry 0: the batch,
// 1: the loop over the scalar query.
// The batch and the scalar query with the arguments in the library's order (rays first).
template <class Tier, class One, class Many>
auto batch_of(const One& one, const std::vector<Many>& many, std::span<std::uint8_t> out) {
    if constexpr (std::is_same_v<Many, ray3>) return batch::intersects<Tier>(std::span<const Many>(many), one, out);
    else return batch::intersects<Tier>(one, std::span<const Many>(many), out);
}
template <class Tier, class One, class Many>
bool scalar_of(const One& one, const Many& m) {
    if constexpr (std::is_same_v<Many, ray3>) return intersects<Tier>(m, one);
    else return intersects<Tier>(one, m);
}
// A set's structure-of-arrays copy (boxes, balls, rays, points), for the packet entries.
template <class Many>
struct soa_of_set {
    static constexpr int fields = std::is_same_v<Many, obb3> ? 15 : 6;
    std::vector<double> f[fields];
    explicit soa_of_set(const std::vector<Many>& many) {
        for (const Many& m : many) {
            double v[fields] = {};
            if constexpr (std::is_same_v<Many, obb3>) {
                const double o[15] = {m.center.x,  m.center.y,  m.center.z,        m.axes[0].x,       m.axes[0].y,
                                      m.axes[0].z, m.axes[1].x, m.axes[1].y,       m.axes[1].z,       m.axes[2].x,
                                      m.axes[2].y, m.axes[2].z, m.half_extents[0], m.half_extents[1], m.half_extents[2]};
                for (int k = 0; k < 15; ++k) v[k] = o[k];
            } else if constexpr (std::is_same_v<Many, aabb3>)
                v[0] = m.min.x, v[1] = m.min.y, v[2] = m.min.z, v[3] = m.max.x, v[4] = m.max.y, v[5] = m.max.z;
            else if constexpr (std::is_same_v<Many, sphere3>) v[0] = m.center.x, v[1] = m.center.y, v[2] = m.center.z, v[3] = m.radius;
            else if constexpr (std::is_same_v<Many, ray3>)
                v[0] = m.origin.x, v[1] = m.origin.y, v[2] = m.origin.z, v[3] = m.direction.x, v[4] = m.direction.y, v[5] = m.direction.z;
            else v[0] = m.x, v[1] = m.y, v[2] = m.z;
            for (int k = 0; k < fields; ++k) f[k].push_back(v[k]);
        }
    }
    auto view() const {
        if constexpr (std::is_same_v<Many, obb3>)
            return batch::obbs_soa{f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], f[9], f[10], f[11], f[12], f[13], f[14]};
        else if constexpr (std::is_same_v<Many, aabb3>) return batch::boxes_soa{f[0], f[1], f[2], f[3], f[4], f[5]};
        else if constexpr (std::is_same_v<Many, sphere3>) return batch::spheres_soa{f[0], f[1], f[2], f[3]};
        else if constexpr (std::is_same_v<Many, ray3>) return batch::rays_soa{f[0], f[1], f[2], f[3], f[4], f[5]};
        else return batch::points_soa{f[0], f[1], f[2]};
    }
};
template <class Tier, class One, class Many>
auto packet_of(const One& one, const soa_of_set<Many>& many, std::span<std::uint8_t> out) {
    if constexpr (std::is_same_v<Many, ray3>) return batch::intersects<Tier>(many.view(), one, out);
    else return batch::intersects<Tier>(one, many.view(), out);
}
// entry 0: the batch on an array; 1: the loop over the scalar query; 2: the batch on a packet.
template <class Tier, class One, class Many>
void reg_one_many(const std::string& name, const std::vector<std::pair<One, std::vector<Many>>>& sets, int entry) {
    benchmark::RegisterBenchmark(name.c_str(), [sets, entry](benchmark::State& st) {
        std::vector<std::uint8_t> out(sets.front().second.size());
        for (const auto& [one, many] : sets) {
            if (!batch_of<Tier>(one, many, out)) return st.SkipWithError("refused");
            for (std::size_t i = 0; i < out.size(); ++i)
                if ((out[i] == 1) != scalar_of<Tier>(one, many[i])) return st.SkipWithError("a lane differs from the scalar answer");
        }
        std::vector<soa_of_set<Many>> packets;
        for (const auto& set : sets) packets.emplace_back(set.second);
        std::size_t k = 0;
        for (auto _ : st) {
            const auto& [one, many] = sets[k];
            if (entry == 0) benchmark::DoNotOptimize(batch_of<Tier>(one, many, out));
            else if (entry == 2) benchmark::DoNotOptimize(packet_of<Tier>(one, packets[k], out));
            else
                for (std::size_t i = 0; i < out.size(); ++i) out[i] = scalar_of<Tier>(one, many[i]) ? 1 : 0;
            benchmark::ClobberMemory();
            if (++k == sets.size()) k = 0;
        }
        st.counters["s_per_test"] = benchmark::Counter(static_cast<double>(out.size()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    });
}
template <class Tier, class One, class Many>
void reg_one_many_tier(const std::string& tier, const std::string& pair, const std::string& dist,
                       const std::vector<std::pair<One, std::vector<Many>>>& sets) {
    reg_one_many<Tier>(tier + "/batch_intersects/" + pair + "/" + dist, sets, 0);
    reg_one_many<Tier>(tier + "/batch_intersects/" + pair + "_soa/" + dist, sets, 2);
    reg_one_many<Tier>(tier + "/scalar_loop/" + pair + "/" + dist, sets, 1);
}
template <class One, class Many>
void reg_one_many_tiers(const std::string& pair, const std::string& dist, const std::vector<std::pair<One, std::vector<Many>>>& sets) {
    reg_one_many_tier<exact>("exact", pair, dist, sets);
    reg_one_many_tier<conservative>("conservative", pair, dist, sets);
    reg_one_many_tier<aggressive>("aggressive", pair, dist, sets);
    reg_one_many_tier<approximate>("approximate", pair, dist, sets);
}

// A tetrahedron and points (random: the unit cube; near_degenerate: on its faces, nudged).
std::vector<std::pair<tetrahedron3, std::vector<point3>>> tetrahedron_points_set(bool near) {
    std::vector<std::pair<tetrahedron3, std::vector<point3>>> out;
    for (int k = 0; k < 16; ++k) {
        const tetrahedron3 t{rp(), rp(), rp(), rp()};
        std::vector<point3> points;
        for (std::size_t i = 0; i < set_size; ++i) {
            if (!near) {
                points.push_back(rp());
                continue;
            }
            const triangle3 f = t.face(static_cast<int>(i % 4));
            const double u = uni(0, 1), v = uni(0, 1 - u);
            points.push_back(np(f.a.x + u * (f.b.x - f.a.x) + v * (f.c.x - f.a.x), f.a.y + u * (f.b.y - f.a.y) + v * (f.c.y - f.a.y),
                                f.a.z + u * (f.b.z - f.a.z) + v * (f.c.z - f.a.z)));
        }
        out.emplace_back(t, std::move(points));
    }
    return out;
}
// Boxes (half-extents up to 0.25) and balls (radii up to 0.25) around one box or ball (random:
// in the unit cube; near_degenerate: touching it, a rounded tangent ball or a face-sharing box,
// nudged).
template <class One, class Many>
std::vector<std::pair<One, std::vector<Many>>> solids_set(bool near) {
    std::vector<std::pair<One, std::vector<Many>>> out;
    for (int k = 0; k < 16; ++k) {
        const point3 c = rp();
        const One one = [&] {
            if constexpr (std::is_same_v<One, aabb3>) return box(rp(), rp());
            else return sphere3{c, uni(0.25, 1.0)};
        }();
        std::vector<Many> many;
        for (std::size_t i = 0; i < set_size; ++i) {
            point3 m = rp();
            const double e = uni(0, 0.25);
            if (near) { // the nearest point of one's boundary to m, and m moved e beyond it (rounded)
                if constexpr (std::is_same_v<One, aabb3>) {
                    m = {std::clamp(m.x, one.min.x, one.max.x), std::clamp(m.y, one.min.y, one.max.y),
                         std::clamp(m.z, one.min.z, one.max.z)};
                    m.x = irand(0, 1) == 0 ? one.min.x - e : one.max.x + e;
                } else {
                    const vec3 d = m - one.center;
                    const double l = std::sqrt(dot(d, d)), s = (one.radius + e) / l;
                    m = {one.center.x + d.x * s, one.center.y + d.y * s, one.center.z + d.z * s};
                }
            }
            if constexpr (std::is_same_v<Many, aabb3>) many.push_back(aabb3{np(m.x - e, m.y - e, m.z - e), np(m.x + e, m.y + e, m.z + e)});
            else many.push_back(sphere3{np(m.x, m.y, m.z), near ? e : uni(0, 0.25)});
        }
        out.emplace_back(one, std::move(many));
    }
    return out;
}

// Rays against one shape, and one ray against shapes (random: the unit cube; near_degenerate:
// rays aimed at a point of the shape's boundary, nudged; shapes placed so the ray grazes them).
template <class Solid>
Solid solid_around(point3 c, double e) {
    if constexpr (std::is_same_v<Solid, aabb3>) return aabb3{{c.x - e, c.y - e, c.z - e}, {c.x + e, c.y + e, c.z + e}};
    else if constexpr (std::is_same_v<Solid, sphere3>) return sphere3{c, e};
    else return triangle3{{c.x - e, c.y - e, c.z}, {c.x + e, c.y - e, c.z + e}, {c.x, c.y + e, c.z - e}};
}
// A point of s's boundary near p (rounded).
point3 on_boundary(const aabb3& b, point3 p) {
    p = {std::clamp(p.x, b.min.x, b.max.x), std::clamp(p.y, b.min.y, b.max.y), std::clamp(p.z, b.min.z, b.max.z)};
    p.x = irand(0, 1) == 0 ? b.min.x : b.max.x;
    return p;
}
point3 on_boundary(const sphere3& s, point3 p) {
    const vec3 d = p - s.center;
    const double k = s.radius / std::sqrt(dot(d, d));
    return {s.center.x + d.x * k, s.center.y + d.y * k, s.center.z + d.z * k};
}
point3 on_boundary(const triangle3& t, point3) { // a point of an edge
    const double u = uni(0, 1);
    return {t.a.x + u * (t.b.x - t.a.x), t.a.y + u * (t.b.y - t.a.y), t.a.z + u * (t.b.z - t.a.z)};
}
template <class Solid>
std::vector<std::pair<Solid, std::vector<ray3>>> rays_set(bool near) {
    std::vector<std::pair<Solid, std::vector<ray3>>> out;
    for (int k = 0; k < 16; ++k) {
        const Solid one = solid_around<Solid>(rp(), uni(0.25, 0.75));
        std::vector<ray3> rays;
        for (std::size_t i = 0; i < set_size; ++i) {
            const point3 o{uni(-2, 2), uni(-2, 2), uni(-2, 2)};
            const point3 target = near ? on_boundary(one, rp()) : rp();
            rays.push_back(ray3{np(o.x, o.y, o.z), target - o});
        }
        out.emplace_back(one, std::move(rays));
    }
    return out;
}
template <class Solid>
std::vector<std::pair<ray3, std::vector<Solid>>> ray_solids_set(bool near) {
    std::vector<std::pair<ray3, std::vector<Solid>>> out;
    for (int k = 0; k < 16; ++k) {
        const point3 o = rp(), aim = rp();
        const ray3 ray{o, aim - o};
        std::vector<Solid> many;
        for (std::size_t i = 0; i < set_size; ++i) {
            const double e = uni(0.01, 0.25);
            Solid s = solid_around<Solid>(rp(), e);
            if (near) { // touching the ray at one of its points p: a box with a corner at p, a ball tangent at p (rounded)
                const point3 p = ray.at(uni(0, 2));
                if constexpr (std::is_same_v<Solid, aabb3>) {
                    s = aabb3{np(p.x, p.y, p.z), np(p.x + e, p.y + e, p.z + e)};
                } else {
                    const vec3 side = cross(ray.direction, rp() - point3{0, 0, 0});
                    const double scale = e / std::sqrt(dot(side, side));
                    s = sphere3{np(p.x + side.x * scale, p.y + side.y * scale, p.z + side.z * scale), e};
                }
            }
            many.push_back(s);
        }
        out.emplace_back(ray, std::move(many));
    }
    return out;
}

// The first hit of one ray among boxes or balls (batch::intersection) beside the loop a user writes
// without it: the scalar intersection<Tier> of every shape, the least entry kept (by its lower end
// in the interval tiers: not an exact order, only the work).
template <class Tier, class Solid>
void reg_first_solid(const std::string& name, const std::vector<std::pair<ray3, std::vector<Solid>>>& sets, int entry) {
    benchmark::RegisterBenchmark(name.c_str(), [sets, entry](benchmark::State& st) {
        std::size_t k = 0, hits = 0;
        for (auto _ : st) {
            const auto& [ray, many] = sets[k];
            if (entry == 0) {
                hits += batch::intersection<Tier>(ray, std::span<const Solid>(many)).value().has_value();
            } else {
                std::optional<std::size_t> best;
                double t_best = 0;
                for (std::size_t i = 0; i < many.size(); ++i)
                    if (const auto h = intersection<Tier>(ray, many[i])) {
                        const double t = [&] {
                            if constexpr (std::is_same_v<std::decay_t<decltype(h->t_enter)>, double>) return h->t_enter;
                            else return h->t_enter.lo;
                        }();
                        if (!best || t < t_best) best = i, t_best = t;
                    }
                hits += best.has_value();
            }
            benchmark::ClobberMemory();
            if (++k == sets.size()) k = 0;
        }
        benchmark::DoNotOptimize(hits);
        st.counters["s_per_test"] = benchmark::Counter(static_cast<double>(sets.front().second.size()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    });
}
template <class Solid>
void reg_first_solid_tiers(const std::string& pair, const std::string& dist, const std::vector<std::pair<ray3, std::vector<Solid>>>& sets) {
    reg_first_solid<exact>("exact/batch_intersection/" + pair + "/" + dist, sets, 0);
    reg_first_solid<exact>("exact/scalar_loop_intersection/" + pair + "/" + dist, sets, 1);
    reg_first_solid<conservative>("conservative/batch_intersection/" + pair + "/" + dist, sets, 0);
    reg_first_solid<approximate>("approximate/batch_intersection/" + pair + "/" + dist, sets, 0);
    reg_first_solid<approximate>("approximate/scalar_loop_intersection/" + pair + "/" + dist, sets, 1);
}

// Boxes (half-extents up to 0.25) against a camera frustum (eye in [-2, 2]^3 looking at a point
// of the unit cube, vertical field of view 0.6..1.4, near 0.1, far 4; random: boxes in the unit
// cube; near_degenerate: a corner on one of its planes (the nearest point of the plane to a random
// point), the box on the plane's outer side, nudged).
std::vector<std::pair<frustum3, std::vector<aabb3>>> frustum_boxes_set(bool near) {
    std::vector<std::pair<frustum3, std::vector<aabb3>>> out;
    while (out.size() < 16) {
        const point3 eye{uni(-2, 2), uni(-2, 2), uni(-2, 2)};
        const auto f = frustum3::from_camera(eye, rp() - eye, vec3{uni(-1, 1), uni(-1, 1), uni(-1, 1)}, uni(0.6, 1.4), 1.0, 0.1, 4.0);
        if (!f.has_value()) continue;
        std::vector<aabb3> boxes;
        for (std::size_t i = 0; i < set_size; ++i) {
            point3 m = rp();
            const double e = uni(0, 0.25);
            if (near) {
                const plane3& h = f.value().planes[static_cast<unsigned>(irand(0, 5))];
                const double t = (dot(h.normal, m - point3{0, 0, 0}) - h.offset) / dot(h.normal, h.normal);
                const point3 p = m - h.normal * t;
                const point3 q{p.x + (h.normal.x > 0 ? e : -e), p.y + (h.normal.y > 0 ? e : -e), p.z + (h.normal.z > 0 ? e : -e)};
                const aabb3 b = box(p, q);
                boxes.push_back(aabb3{np(b.min.x, b.min.y, b.min.z), np(b.max.x, b.max.y, b.max.z)});
            } else {
                boxes.push_back(aabb3{np(m.x - e, m.y - e, m.z - e), np(m.x + e, m.y + e, m.z + e)});
            }
        }
        out.emplace_back(f.value(), std::move(boxes));
    }
    return out;
}
// Balls from a set's boxes: centred at each box's middle, radius half its extent (random); near
// each box's plane point p, a ball centred out along the plane's unit normal by its radius, so
// tangent to the plane at p (rounded; often the frustum's face, else beyond an edge or a corner).
std::vector<std::pair<frustum3, std::vector<sphere3>>> balls_of(const std::vector<std::pair<frustum3, std::vector<aabb3>>>& sets,
                                                                bool near) {
    std::vector<std::pair<frustum3, std::vector<sphere3>>> out;
    for (const auto& [f, boxes] : sets) {
        std::vector<sphere3> balls;
        for (const aabb3& b : boxes) {
            const double e = 0.5 * (b.max.x - b.min.x);
            const point3 m{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y), 0.5 * (b.min.z + b.max.z)};
            if (!near) {
                balls.push_back(sphere3{m, e});
                continue;
            }
            const plane3& h = f.planes[static_cast<unsigned>(irand(0, 5))];
            const double t = (dot(h.normal, m - point3{0, 0, 0}) - h.offset) / dot(h.normal, h.normal);
            const point3 q = m - h.normal * t;
            const vec3 u = h.normal * (1.0 / std::sqrt(dot(h.normal, h.normal)));
            balls.push_back(sphere3{np(q.x + u.x * e, q.y + u.y * e, q.z + u.z * e), e});
        }
        out.emplace_back(f, std::move(balls));
    }
    return out;
}
// Oriented boxes from a set's boxes: each box's centre and extents, its axes a random rotation
// (`turned`; frustum_obbs: the near set's box, whose corner touches a plane before the rotation,
// so rotated about its centre it reaches across) or the unit axes in a random signed order (the
// same box up to the rounding of centre and extents: aabb_obbs' near set, boxes just touching the
// one box's face).
template <class One>
std::vector<std::pair<One, std::vector<obb3>>> obbs_of(const std::vector<std::pair<One, std::vector<aabb3>>>& boxes, bool turned) {
    std::vector<std::pair<One, std::vector<obb3>>> out;
    for (const auto& [one, set] : boxes) {
        std::vector<obb3> obbs;
        for (const aabb3& b : set) {
            std::array<vec3, 3> axes{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
            if (turned) {
                double q[4], n = 0;
                for (double& x : q) x = uni(-1, 1), n += x * x;
                n = std::sqrt(n);
                for (double& x : q) x /= n;
                const double w = q[0], x = q[1], y = q[2], z = q[3];
                axes = {vec3{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                        vec3{2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                        vec3{2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
            } else {
                for (vec3& v : axes)
                    if (irand(0, 1) == 0) v = v * -1.0;
            }
            const point3 c{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y), 0.5 * (b.min.z + b.max.z)};
            obbs.push_back(obb3{c, axes, {0.5 * (b.max.x - b.min.x), 0.5 * (b.max.y - b.min.y), 0.5 * (b.max.z - b.min.z)}});
        }
        out.emplace_back(one, std::move(obbs));
    }
    return out;
}
// A classic culling test in double over the same sets, for comparison: a box's plane rejection
// (method::aabb_frustum_culling), a ball beyond one plane (method::frustum_sphere_planes); not a
// tier: each says yes for some shapes beyond an edge or corner.
template <class Many>
void reg_culling_method(const std::string& name, const std::vector<std::pair<frustum3, std::vector<Many>>>& sets,
                        bool (*keeps)(const frustum3&, const Many&)) {
    benchmark::RegisterBenchmark(name.c_str(), [sets, keeps](benchmark::State& st) {
        std::vector<std::uint8_t> out(sets.front().second.size());
        std::size_t k = 0;
        for (auto _ : st) {
            const auto& [f, many] = sets[k];
            for (std::size_t i = 0; i < out.size(); ++i) out[i] = keeps(f, many[i]) ? 1 : 0;
            benchmark::ClobberMemory();
            if (++k == sets.size()) k = 0;
        }
        st.counters["s_per_test"] = benchmark::Counter(static_cast<double>(out.size()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    });
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
    reg_one_many_tiers("tetrahedron_points", dist, tetrahedron_points_set(near));
    reg_one_many_tiers("aabb_aabbs", dist, solids_set<aabb3, aabb3>(near));
    reg_one_many_tiers("aabb_spheres", dist, solids_set<aabb3, sphere3>(near));
    reg_one_many_tiers("sphere_aabbs", dist, solids_set<sphere3, aabb3>(near));
    reg_one_many_tiers("sphere_spheres", dist, solids_set<sphere3, sphere3>(near));
    reg_one_many_tiers("rays_triangle", dist, rays_set<triangle3>(near));
    reg_one_many_tiers("rays_aabb", dist, rays_set<aabb3>(near));
    reg_one_many_tiers("rays_sphere", dist, rays_set<sphere3>(near));
    const auto ray_boxes = ray_solids_set<aabb3>(near);
    const auto ray_balls = ray_solids_set<sphere3>(near);
    reg_one_many_tiers("ray_aabbs", dist, ray_boxes);
    reg_one_many_tiers("ray_spheres", dist, ray_balls);
    reg_first_solid_tiers("ray_aabbs", dist, ray_boxes);
    reg_first_solid_tiers("ray_spheres", dist, ray_balls);
    const auto culling = frustum_boxes_set(near);
    reg_one_many_tiers("frustum_aabbs", dist, culling);
    reg_culling_method<aabb3>("approximate/method_culling_loop/frustum_aabbs/" + dist, culling,
                              [](const frustum3& f, const aabb3& b) { return method::aabb_frustum_culling(b, f); });
    reg_one_many_tiers("frustum_obbs", dist, obbs_of(culling, true));
    const auto balls = balls_of(culling, near);
    reg_one_many_tiers("frustum_spheres", dist, balls);
    reg_culling_method<sphere3>("approximate/method_culling_loop/frustum_spheres/" + dist, balls,
                                [](const frustum3& f, const sphere3& b) { return method::frustum_sphere_planes(f, b); });
    reg_one_many_tiers("aabb_obbs", dist, obbs_of(solids_set<aabb3, aabb3>(near), !near));
    reg_one_many_tiers("sphere_obbs", dist, obbs_of(solids_set<sphere3, aabb3>(near), !near));
}

} // namespace bench
