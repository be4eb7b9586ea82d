// Benchmarks: scenes. Rays from a camera into the Stanford bunny (bunny00 from libcgal-demo,
// 75,408 triangles) held in a scene3, beside the peer that renderers use:
//   <tier>/scene_first_hit/ray_bunny/<dist>     intersection<Tier>(ray, scene): the first contact
//   <tier>/scene_any_hit/ray_bunny/<dist>       intersects<Tier>(ray, scene)
//   exact/brute_first_hit/ray_bunny/<dist>      intersection<exact>(ray, mesh3): every triangle
//   peer/embree_intersect1/ray_bunny/<dist>     Embree 3's rtcIntersect1 (float vertices)
//   peer/embree_intersect16/ray_bunny/<dist>    rtcIntersect16, sixteen rays a call
// One iteration is one ray (sixteen for rtcIntersect16); s_per_ray is the time per ray. Rays: from a
// camera outside the mesh's box towards random points of the box (random, about half of them
// hit), or towards the mesh's vertices (near_degenerate: each passes within rounding of a vertex,
// where six or more triangles meet). Before timing, the exact tier's first hits are checked against
// the brute force over every triangle (CGAL's oracle checks the same scene query in the tests);
// embree_other_pct counts the rays where Embree names another triangle than the exact first contact,
// or hits where it does not, or misses where it does.
#include "bench.hpp"
#include "embree_peer.hpp"
#include "testkit/mesh_io.hpp"
#include <filesystem>
#include <memory>

namespace bench {
namespace {

struct bunny {
    audit::mesh mesh;
    std::vector<triangle3> triangles;
    std::unique_ptr<scene3> scene;
    std::unique_ptr<embree_peer::scene> peer;
    std::vector<ray3> rays;
};

std::shared_ptr<bunny> load(bool near) {
    const auto file = std::filesystem::path(INCIDENCE_SOURCE_DIR) / "build/data/meshes/bunny00.off";
    if (!std::filesystem::exists(file)) return nullptr;
    auto b = std::make_shared<bunny>();
    b->mesh = audit::read_mesh(file.string());
    for (const auto& f : b->mesh.faces) b->triangles.push_back({b->mesh.vertices[f[0]], b->mesh.vertices[f[1]], b->mesh.vertices[f[2]]});
    auto s = scene3::make(b->triangles);
    if (!s) return nullptr;
    b->scene = std::make_unique<scene3>(std::move(s).value());
    std::vector<double> xyz;
    std::vector<std::uint32_t> idx;
    for (const point3& p : b->mesh.vertices) xyz.insert(xyz.end(), {p.x, p.y, p.z});
    for (const auto& f : b->mesh.faces) idx.insert(idx.end(), {f[0], f[1], f[2]});
    b->peer = std::make_unique<embree_peer::scene>(xyz.data(), b->mesh.vertices.size(), idx.data(), b->mesh.faces.size());
    aabb3 box{b->mesh.vertices[0], b->mesh.vertices[0]};
    for (const point3& p : b->mesh.vertices)
        box = {{std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)},
               {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)}};
    const point3 mid{(box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2, (box.min.z + box.max.z) / 2};
    const double extent = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
    const point3 camera{mid.x + 0.6 * extent, mid.y + 0.8 * extent, mid.z + 1.9 * extent};
    for (std::size_t i = 0; i < std::max<std::size_t>(set_size, 64); ++i) {
        point3 aim{uni(box.min.x, box.max.x), uni(box.min.y, box.max.y), uni(box.min.z, box.max.z)};
        if (near) aim = b->mesh.vertices[static_cast<std::size_t>(irand(0, static_cast<int>(b->mesh.vertices.size()) - 1))];
        b->rays.push_back(ray3{camera, vec3{aim.x - camera.x, aim.y - camera.y, aim.z - camera.z}});
    }
    return b;
}

// The exact first hit of the scene against the brute force (the least correctly rounded t over
// every triangle, and that triangle's values), on the first 32 rays.
bool exact_matches_brute_force(const bunny& b) {
    for (std::size_t k = 0; k < 32 && k < b.rays.size(); ++k) {
        const ray3& r = b.rays[k];
        std::optional<triangle_hit<double>> least;
        for (const triangle3& t : b.triangles)
            if (const auto h = intersection<exact>(r, t); h && (!least || h->t < least->t)) least = h;
        const auto h = intersection<exact>(r, *b.scene);
        if (h.has_value() != least.has_value()) return false;
        if (h && (h->t != least->t || intersection<exact>(r, b.triangles[h->triangle])->point != h->point)) return false;
    }
    return true;
}

double embree_other_pct(const bunny& b) {
    long other = 0;
    for (const ray3& r : b.rays) {
        double o[3], d[3];
        arr(r.origin, o);
        arr(r.direction, d);
        const embree_peer::hit e = b.peer->intersect1(o, d);
        const auto h = intersection<exact>(r, *b.scene);
        other += e.found != h.has_value() || (h && e.triangle != h->triangle);
    }
    return 100.0 * static_cast<double>(other) / static_cast<double>(b.rays.size());
}

template <class F>
void reg_rays(const std::string& name, std::shared_ptr<bunny> b, int per_iteration, F f) {
    const bool peer = name.find("embree") != std::string::npos;
    benchmark::RegisterBenchmark(name.c_str(), [b, per_iteration, f, peer](benchmark::State& st) {
        std::size_t k = 0;
        for (auto _ : st) {
            f(*b, k);
            k += static_cast<std::size_t>(per_iteration);
            if (k + static_cast<std::size_t>(per_iteration) > b->rays.size()) k = 0;
        }
        st.counters["s_per_ray"] =
            benchmark::Counter(per_iteration, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
        if (peer) st.counters["embree_other_pct"] = embree_other_pct(*b);
    });
}

template <class Tier>
void reg_tier(const std::string& tier, const std::string& dist, const std::shared_ptr<bunny>& b) {
    reg_rays(tier + "/scene_first_hit/ray_bunny/" + dist, b, 1,
             [](const bunny& x, std::size_t k) { benchmark::DoNotOptimize(intersection<Tier>(x.rays[k], *x.scene)); });
    reg_rays(tier + "/scene_any_hit/ray_bunny/" + dist, b, 1,
             [](const bunny& x, std::size_t k) { benchmark::DoNotOptimize(intersects<Tier>(x.rays[k], *x.scene)); });
}

} // namespace

void register_scene(bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    const auto b = load(near);
    if (!b) {
        benchmark::RegisterBenchmark(("exact/scene_first_hit/ray_bunny/" + dist).c_str(), [](benchmark::State& st) {
            st.SkipWithError("build/data/meshes/bunny00.off is missing (run.sh unpacks it)");
        });
        return;
    }
    if (!exact_matches_brute_force(*b)) {
        benchmark::RegisterBenchmark(("exact/scene_first_hit/ray_bunny/" + dist).c_str(),
                                     [](benchmark::State& st) { st.SkipWithError("the exact first hit differs from the brute force"); });
        return;
    }
    reg_tier<exact>("exact", dist, b);
    reg_tier<conservative>("conservative", dist, b);
    reg_tier<aggressive>("aggressive", dist, b);
    reg_tier<approximate>("approximate", dist, b);
    reg_rays("exact/brute_first_hit/ray_bunny/" + dist, b, 1, [](const bunny& x, std::size_t k) {
        std::optional<triangle_hit<double>> least;
        for (const triangle3& t : x.triangles)
            if (const auto h = intersection<exact>(x.rays[k], t); h && (!least || h->t < least->t)) least = h;
        benchmark::DoNotOptimize(least);
    });
    reg_rays("peer/embree_intersect1/ray_bunny/" + dist, b, 1, [](const bunny& x, std::size_t k) {
        double o[3], d[3];
        arr(x.rays[k].origin, o);
        arr(x.rays[k].direction, d);
        benchmark::DoNotOptimize(x.peer->intersect1(o, d));
    });
    reg_rays("peer/embree_intersect16/ray_bunny/" + dist, b, 16, [](const bunny& x, std::size_t k) {
        double o[48], d[48];
        for (int i = 0; i < 16; ++i) {
            arr(x.rays[k + static_cast<std::size_t>(i)].origin, o + 3 * i);
            arr(x.rays[k + static_cast<std::size_t>(i)].direction, d + 3 * i);
        }
        embree_peer::hit h[16];
        x.peer->intersect16(o, d, h);
        benchmark::DoNotOptimize(h);
    });
}

} // namespace bench
