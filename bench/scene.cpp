// Benchmarks: scenes. Rays from a camera into the Stanford bunny (bunny00 from libcgal-demo,
// 75,408 triangles) held in a scene3, beside the peer that renderers use:
//   <tier>/scene_first_hit/ray_bunny/<dist>     intersection<Tier>(ray, scene): the first contact
//   <tier>/scene_any_hit/ray_bunny/<dist>       intersects<Tier>(ray, scene)
//   exact/brute_first_hit/ray_bunny/<dist>      intersection<exact>(ray, mesh3): every triangle
//   peer/embree_intersect1/ray_bunny/<dist>     Embree 3's rtcIntersect1 (float vertices)
//   peer/embree_intersect16/ray_bunny/<dist>    rtcIntersect16, sixteen rays a call
//   <tier>/scene_pairs/bunny_moved/<dist>       intersecting<Tier>(bunny, moved, out): every pair of
//                                               triangles met, the bunny against a copy of itself
//                                               moved by 1/16 of its width (random) or not moved
//                                               (near_degenerate: every triangle touches its copy and
//                                               its neighbours' copies exactly)
//   peer/fcl_collide_all/bunny_moved/<dist>     FCL's fcl::collide on two BVHModel<OBBRSS>, every
//                                               contact asked for
// One iteration is one ray (sixteen for rtcIntersect16); s_per_ray is the time per ray. Rays: from a
// camera outside the mesh's box towards random points of the box (random, about half of them
// hit), or towards the mesh's vertices (near_degenerate: each passes within rounding of a vertex,
// where six or more triangles meet). Before timing, the exact tier's first hits are checked against
// the brute force over every triangle (CGAL's oracle checks the same scene query in the tests);
// embree_other_pct counts the rays where Embree names another triangle than the exact first contact,
// or hits where it does not, or misses where it does. The pairs: every pair the exact tier lists is
// checked met by the scalar exact test before timing; pairs counts them, fcl_missed the pairs FCL
// does not report, fcl_extra those it reports that do not meet.
#include "bench.hpp"
#include "embree_peer.hpp"
#include "testkit/mesh_io.hpp"
#include <filesystem>
#include <memory>
#include <set>
#include <utility>

namespace bench {
namespace {

struct bunny {
    audit::mesh mesh;
    std::vector<triangle3> triangles;
    std::unique_ptr<scene3> scene;
    std::unique_ptr<embree_peer::scene> peer;
    std::vector<ray3> rays;
    std::vector<triangle3> pair_triangles;  // the bunny's triangles for the pairs (the first 2,048 in a smoke run)
    std::vector<triangle3> moved_triangles; // their copy moved along x
    std::unique_ptr<scene3> pair_scene, moved;
    std::unique_ptr<fcl_peer::mesh_pair> fcl;
    std::vector<std::pair<std::size_t, std::size_t>> pairs; // the exact tier's
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
    auto moved_copy = [&](double shift) {
        // a smoke run (a few cases per set, at -O0) pairs the first 2,048 triangles only
        const std::size_t n = set_size < 1024 ? std::min<std::size_t>(2048, b->triangles.size()) : b->triangles.size();
        b->pair_triangles.assign(b->triangles.begin(), b->triangles.begin() + static_cast<std::ptrdiff_t>(n));
        std::vector<double> mx = xyz;
        for (std::size_t i = 0; i < mx.size(); i += 3) mx[i] += shift;
        for (const triangle3& t : b->pair_triangles)
            b->moved_triangles.push_back({{t.a.x + shift, t.a.y, t.a.z}, {t.b.x + shift, t.b.y, t.b.z}, {t.c.x + shift, t.c.y, t.c.z}});
        b->pair_scene = std::make_unique<scene3>(scene3::make(b->pair_triangles).value());
        b->moved = std::make_unique<scene3>(scene3::make(b->moved_triangles).value());
        b->fcl = std::make_unique<fcl_peer::mesh_pair>(xyz.data(), b->mesh.vertices.size(), idx.data(), n, mx.data(),
                                                       b->mesh.vertices.size(), idx.data(), n);
    };
    for (const point3& p : b->mesh.vertices)
        box = {{std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)},
               {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)}};
    const point3 mid{(box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2, (box.min.z + box.max.z) / 2};
    const double extent = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
    const point3 camera{mid.x + 0.6 * extent, mid.y + 0.8 * extent, mid.z + 1.9 * extent};
    moved_copy(near ? 0.0 : (box.max.x - box.min.x) / 16);
    (void)intersecting<exact>(*b->pair_scene, *b->moved, b->pairs);
    for (std::size_t i = 0; i < std::max<std::size_t>(set_size, 64); ++i) {
        point3 aim{uni(box.min.x, box.max.x), uni(box.min.y, box.max.y), uni(box.min.z, box.max.z)};
        if (near) aim = b->mesh.vertices[static_cast<std::size_t>(irand(0, static_cast<int>(b->mesh.vertices.size()) - 1))];
        b->rays.push_back(ray3{camera, vec3{aim.x - camera.x, aim.y - camera.y, aim.z - camera.z}});
    }
    return b;
}

// The exact first hit of the scene against the brute force (the least correctly rounded t over
// every triangle, and that triangle's values), on the first 32 rays (8 in a smoke run).
bool exact_matches_brute_force(const bunny& b) {
    for (std::size_t k = 0; k < (set_size < 1024 ? 8u : 32u) && k < b.rays.size(); ++k) {
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

// Every listed pair met (the scalar exact test), the exact list against FCL's.
bool pairs_met(const bunny& b) {
    for (const auto& [i, j] : b.pairs)
        if (!intersects<exact>(b.pair_triangles[i], b.moved_triangles[j])) return false;
    return true;
}
void fcl_counters(const bunny& b, benchmark::State& st) {
    const auto theirs = b.fcl->contacts();
    const std::set<std::pair<std::size_t, std::size_t>> ours(b.pairs.begin(), b.pairs.end()), fcl(theirs.begin(), theirs.end());
    long missed = 0, extra = 0;
    for (const auto& p : ours) missed += !fcl.contains(p);
    for (const auto& p : fcl) extra += !ours.contains(p);
    st.counters["pairs"] = static_cast<double>(ours.size());
    st.counters["fcl_missed"] = static_cast<double>(missed);
    st.counters["fcl_extra"] = static_cast<double>(extra);
}
template <class Tier>
void reg_pairs(const std::string& tier, const std::string& dist, const std::shared_ptr<bunny>& b) {
    benchmark::RegisterBenchmark((tier + "/scene_pairs/bunny_moved/" + dist).c_str(), [b](benchmark::State& st) {
        std::vector<std::pair<std::size_t, std::size_t>> out;
        out.reserve(b->pairs.size() * 2);
        for (auto _ : st) {
            out.clear();
            benchmark::DoNotOptimize(intersecting<Tier>(*b->pair_scene, *b->moved, out));
        }
        st.counters["pairs"] = static_cast<double>(out.size());
    });
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
    if (!pairs_met(*b)) {
        benchmark::RegisterBenchmark(("exact/scene_pairs/bunny_moved/" + dist).c_str(),
                                     [](benchmark::State& st) { st.SkipWithError("a listed pair of triangles does not meet"); });
    } else {
        reg_pairs<exact>("exact", dist, b);
        reg_pairs<conservative>("conservative", dist, b);
        reg_pairs<aggressive>("aggressive", dist, b);
        reg_pairs<approximate>("approximate", dist, b);
        benchmark::RegisterBenchmark(("peer/fcl_collide_all/bunny_moved/" + dist).c_str(), [b](benchmark::State& st) {
            for (auto _ : st) benchmark::DoNotOptimize(b->fcl->contacts());
            fcl_counters(*b, st);
        });
    }
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
