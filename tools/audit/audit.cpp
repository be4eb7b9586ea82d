// incidence-audit: measures, for every query family of incidence::catalog, where each method
// starts to fail (stability), how fast it is for how much accuracy (tradeoff), and what a given
// mesh scene needs (scene); writes audit.json (schema: tools/audit/audit.schema.json) and a
// self-contained HTML report (charts drawn by tools/audit/report.py with matplotlib).
//
//   incidence-audit all [--scene FILE]   stability + tradeoff (+ scene)
//   incidence-audit stability | tradeoff | scene FILE
//   options: --out DIR (default audit-report) --cases N --seed S --reps R --rays N --no-report
#include "testkit/oracle/cgal_oracle.hpp"
#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>
import incidence;
#include "testkit/bounding.hpp"
#include "testkit/generators.hpp"
#include "testkit/json.hpp"
#include "testkit/mesh_io.hpp"
#include "testkit/methods.hpp"
#include "families.hpp"

using namespace incidence;

// --- progress on stderr, only when it is a terminal --------------------------------------------
namespace {
bool tty = false;
} // namespace
void audit_run::progress(const char* fmt, ...) {
    if (!tty) return;
    char buf[256];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    std::fprintf(stderr, "\r\033[K%s", buf);
    std::fflush(stderr);
}
void audit_run::progress_done() {
    if (tty) std::fprintf(stderr, "\r\033[K");
}

namespace {
using namespace audit_run;

std::string shape_name(const point3*) { return "point3"; }
std::string shape_name(const sphere3*) { return "sphere3"; }
std::string shape_name(const capsule3*) { return "capsule3"; }
std::string shape_name(const aabb3*) { return "aabb3"; }
std::string shape_name(const ray3*) { return "ray3"; }
std::string shape_name(const segment3*) { return "segment3"; }
std::string shape_name(const triangle3*) { return "triangle3"; }
std::string shape_name(const line3*) { return "line3"; }
std::string shape_name(const plane3*) { return "plane3"; }
std::string shape_name(const obb3*) { return "obb3"; }
std::string shape_name(const tetrahedron3*) { return "tetrahedron3"; }
std::string shape_name(const point2*) { return "point2"; }
std::string shape_name(const segment2*) { return "segment2"; }
std::string shape_name(const ray2*) { return "ray2"; }
std::string shape_name(const line2*) { return "line2"; }
std::string shape_name(const circle2*) { return "circle2"; }
std::string shape_name(const kdop<14>*) { return "kdop<14>"; }
std::string shape_name(const convex_polyhedron3*) { return "convex_polyhedron3"; }
std::string shape_name(const frustum3*) { return "frustum3"; }

void write_methods(audit::json& j, const auto& ms) {
    j.key("methods").array();
    for (const auto& m : ms) j.object().kv("name", m.name).kv("kind", m.kind).kv("source", m.source).end_object();
    j.end_array();
}

// --- stability and tradeoff (the families, in families_part1.cpp .. families_part4.cpp) ------------
long total_violations = 0;

void stability(audit::json& j, const options& o) {
    j.key("stability").object();
    j.kv("cases_per_level_and_setting", o.cases).kv("seed", long(o.seed));
    j.key("levels").array();
    for (int l = 0; l < audit::level_count; ++l) {
        j.object();
        if (l < audit::separation_levels) j.kv("kind", "separation").kv("k", l);
        else j.kv("kind", "ulp").kv("ulps", l - audit::separation_levels);
        j.end_object();
    }
    j.end_array();
    j.key("settings").array();
    for (const auto& s : audit::settings) j.object().kv("offset", s.offset * audit::base_size).kv("scale_exp", s.scale_exp).end_object();
    j.end_array();
    j.key("families").array();
    stability_part<0>(j, o, total_violations);
    stability_part<1>(j, o, total_violations);
    stability_part<2>(j, o, total_violations);
    stability_part<3>(j, o, total_violations);
    j.end_array().end_object();
    progress_done();
}

void tradeoff(audit::json& j, const options& o) {
    j.key("tradeoff").object().kv("repetitions", o.reps).kv("cases", o.tradeoff_cases);
    j.kv("timing", "median over the repetitions of the mean ns per call over the set; every method called "
                   "through a function pointer; methods interleaved within each repetition");
    j.key("families").array();
    tradeoff_part<0>(j, o);
    tradeoff_part<1>(j, o);
    tradeoff_part<2>(j, o);
    tradeoff_part<3>(j, o);
    j.end_array().end_object();
    progress_done();
}

// --- scene -----------------------------------------------------------------------------------
struct workload_result {
    std::string name, description;
    long tests = 0;
    struct row {
        std::string name, kind;
        double ms = 0;
        counts c;
        long holes = 0; // rays that hit no triangle around an edge or vertex while exact hits one
        long uncertain = 0;
    };
    std::vector<row> rows;
    long exact_holes = 0;
    bool holes_apply = false;
};

// Runs every method of `fam` over the pairs; `groups` (optional) partitions the pairs into sets
// whose union must be hit (a ray and the triangles around one edge or vertex).
template <class Family, class A, class B>
workload_result run_workload(const Family& fam, const char* name, const char* description, const std::vector<A>& as,
                             const std::vector<B>& bs, const std::vector<std::size_t>& group_start) {
    const auto ms = audit::methods_of(fam);
    workload_result w;
    w.name = name;
    w.description = description;
    w.tests = long(as.size());
    w.holes_apply = !group_start.empty();
    std::vector<char> truth(as.size()), ok(as.size());
    for (std::size_t i = 0; i < as.size(); ++i) ok[i] = audit::peer_accepts(as[i], bs[i]);
    for (std::size_t m = 0; m < ms.size(); ++m) {
        progress("scene: %s, %s", name, ms[m].name.c_str());
        workload_result::row row;
        row.name = ms[m].name, row.kind = ms[m].kind;
        std::vector<char> ans(as.size(), 0);
        const bool peer = ms[m].kind == "peer";
        const double t0 = now_ns();
        for (std::size_t i = 0; i < as.size(); ++i)
            if (!peer || ok[i]) ans[i] = ms[m].test(as[i], bs[i]);
        row.ms = (now_ns() - t0) * 1e-6;
        if (m == 0) truth = ans;
        for (std::size_t i = 0; i < as.size(); ++i)
            if (!peer || ok[i]) row.c.add(ans[i], truth[i]);
        for (std::size_t g = 0; g < group_start.size(); ++g) {
            const std::size_t lo = group_start[g], hi = g + 1 < group_start.size() ? group_start[g + 1] : as.size();
            bool any_truth = false, any = false;
            for (std::size_t i = lo; i < hi; ++i) any_truth |= truth[i] != 0, any |= ans[i] != 0;
            if (any_truth && !any) ++row.holes;
        }
        w.rows.push_back(row);
    }
    long unc = 0;
    for (std::size_t i = 0; i < as.size(); ++i) unc += classify(as[i], bs[i]) == certainty::uncertain;
    w.rows[0].uncertain = unc;
    return w;
}

// The catalog's family with canonical types (A, B).
template <class A, class B, std::size_t I = 0>
constexpr const auto& family_of() {
    using F = std::tuple_element_t<I, std::decay_t<decltype(catalog::families)>>;
    if constexpr (std::is_same_v<typename F::first_type, A> && std::is_same_v<typename F::second_type, B>)
        return std::get<I>(catalog::families);
    else return family_of<A, B, I + 1>();
}

// A grid of n x n rays from the eye through an image plane at the centre (0.8 sizes across).
std::vector<ray3> camera_rays(int n, point3 eye, point3 centre, vec3 right, vec3 up, double size) {
    std::vector<ray3> rs;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double u = ((x + 0.5) / n - 0.5) * size * 0.8, v = ((y + 0.5) / n - 0.5) * size * 0.8;
            rs.push_back(ray3{eye, centre + right * u + up * v - eye});
        }
    return rs;
}

// Does each ray hit the mesh: intersects<Tier>(ray, scene) (kind "scene") and batch::intersects<Tier>
// over every triangle (kind "batch"), each tier; the truth is the exact tier's. uncertain: the rays
// where the conservative and aggressive scene answers differ (a triangle the filter left open).
workload_result scene_workload(const scene3& sc, const std::vector<triangle3>& tris, const std::vector<ray3>& rays) {
    workload_result w;
    w.name = "scene_rays";
    w.description = std::string("the camera rays against the whole mesh at once (does the ray hit it?): through scene3, a "
                                "hierarchy of axis-aligned boxes, and through the SIMD batches (") +
                    batch::simd_target() + "), one ray against every triangle";
    w.tests = long(rays.size());
    std::vector<char> truth(rays.size());
    std::vector<std::uint8_t> lanes(tris.size());
    auto run = [&](const std::string& name, const char* kind, auto answer) {
        progress("scene: scene_rays, %s", name.c_str());
        workload_result::row row;
        row.name = name, row.kind = kind;
        std::vector<char> ans(rays.size());
        const double t0 = now_ns();
        for (std::size_t i = 0; i < rays.size(); ++i) ans[i] = answer(rays[i]);
        row.ms = (now_ns() - t0) * 1e-6;
        if (w.rows.empty()) truth = ans;
        for (std::size_t i = 0; i < rays.size(); ++i) row.c.add(ans[i], truth[i]);
        w.rows.push_back(row);
    };
    for (const ray3& r : rays) (void)intersects<approximate>(r, sc); // the hierarchy into the cache before the first timing
    auto tiers = [&]<class Tier>(const char* name) { run(name, "tier", [&](const ray3& r) { return intersects<Tier>(r, sc); }); };
    tiers.template operator()<exact>("exact");
    tiers.template operator()<conservative>("conservative");
    tiers.template operator()<aggressive>("aggressive");
    tiers.template operator()<approximate>("approximate");
    auto batches = [&]<class Tier>(const std::string& name) {
        run(name + " (batch)", "batch", [&](const ray3& r) {
            const auto met = batch::intersects<Tier>(r, std::span<const triangle3>(tris), lanes);
            return met && met.value() > 0;
        });
    };
    batches.template operator()<exact>("exact");
    batches.template operator()<conservative>("conservative");
    batches.template operator()<aggressive>("aggressive");
    batches.template operator()<approximate>("approximate");
    long unc = 0;
    for (const ray3& r : rays) unc += intersects<conservative>(r, sc) != intersects<aggressive>(r, sc);
    w.rows[0].uncertain = unc;
    return w;
}

void scene(audit::json& j, const options& o) {
    const audit::mesh mesh = audit::read_mesh(o.scene);
    std::vector<triangle3> tris;
    for (const auto& f : mesh.faces) tris.push_back({mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]});
    point3 lo = mesh.vertices[0], hi = lo;
    for (const auto& p : mesh.vertices) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    const point3 centre{0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z)};
    const vec3 diag = hi - lo;
    const double size = std::sqrt(dot(diag, diag));
    // A camera on a diagonal, 2 sizes away, looking at the centre; an image plane through the centre.
    const vec3 view = vec3{0.6, 0.48, 0.64};
    const point3 eye = centre + view * (2.0 * size);
    vec3 right = cross(view, vec3{0, 1, 0});
    right = right * (1.0 / std::sqrt(dot(right, right)));
    vec3 up = cross(right, view);
    up = up * (1.0 / std::sqrt(dot(up, up)));

    const auto& rt = family_of<ray3, triangle3>();
    const auto& tt = family_of<triangle3, triangle3>();
    std::vector<workload_result> results;
    { // camera rays against every triangle
        std::vector<ray3> rs;
        std::vector<triangle3> ts;
        const long n = long(o.rays) * o.rays * long(tris.size());
        rs.reserve(std::size_t(n)), ts.reserve(std::size_t(n));
        for (const ray3& ray : camera_rays(o.rays, eye, centre, right, up, size))
            for (const auto& t : tris) rs.push_back(ray), ts.push_back(t);
        results.push_back(run_workload(rt, "camera_rays", "a grid of camera rays against every triangle", rs, ts, {}));
    }
    // the same camera rays against the whole mesh at once: through scene3 (its hierarchy of boxes) and
    // through the SIMD batches (one ray against every triangle); the answer is whether the ray hits the
    // mesh, the truth the exact tier's
    const auto built = scene3::make(tris);
    if (!built) throw std::runtime_error("the scene's triangles: " + built.error().what());
    const scene3& sc = built.value();
    double scene_build_ms = 0;
    {
        const double t0 = now_ns();
        (void)scene3::make(tris);
        scene_build_ms = (now_ns() - t0) * 1e-6;
    }
    results.push_back(scene_workload(sc, tris, camera_rays(o.rays, eye, centre, right, up, size)));
    // Edge and vertex adjacency.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges;
    std::vector<std::vector<std::uint32_t>> around(mesh.vertices.size());
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.faces[f][std::size_t(k)], b = mesh.faces[f][std::size_t((k + 1) % 3)];
            edges[{std::min(a, b), std::max(a, b)}].push_back(f);
            around[a].push_back(f);
        }
    { // rays from the eye through every edge midpoint and every vertex, against the triangles there
        std::vector<ray3> rs;
        std::vector<triangle3> ts;
        std::vector<std::size_t> groups;
        for (const auto& [e, fs] : edges) {
            const point3 a = mesh.vertices[e.first], b = mesh.vertices[e.second];
            const point3 mid{0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)};
            groups.push_back(rs.size());
            for (auto f : fs) rs.push_back(ray3{eye, mid - eye}), ts.push_back(tris[f]);
        }
        results.push_back(run_workload(rt, "edge_rays",
                                       "a ray from the eye through each edge's midpoint, against the "
                                       "triangles sharing that edge",
                                       rs, ts, groups));
        rs.clear(), ts.clear(), groups.clear();
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            if (around[v].empty()) continue;
            groups.push_back(rs.size());
            for (auto f : around[v]) rs.push_back(ray3{eye, mesh.vertices[v] - eye}), ts.push_back(tris[f]);
        }
        results.push_back(run_workload(rt, "vertex_rays",
                                       "a ray from the eye through each vertex, against the "
                                       "triangles around it",
                                       rs, ts, groups));
    }
    { // the mesh's own triangle pairs: adjacent ones touch exactly; near ones (two rings) mostly miss
        std::vector<triangle3> as, bs, na, nb;
        std::set<std::pair<std::uint32_t, std::uint32_t>> adjacent;
        for (const auto& fs : around)
            for (auto f : fs)
                for (auto g : fs)
                    if (f < g) adjacent.insert({f, g});
        for (const auto& [f, g] : adjacent) as.push_back(tris[f]), bs.push_back(tris[g]);
        results.push_back(run_workload(tt, "adjacent_pairs",
                                       "pairs of the mesh's triangles sharing a vertex or an edge "
                                       "(all touch exactly)",
                                       as, bs, {}));
        audit::rng r(o.seed);
        const long want = o.pairs;
        long tries = 0;
        std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
        while (long(na.size()) < want && tries++ < want * 20) {
            const auto f = std::uint32_t(r.integer(0, int(mesh.faces.size()) - 1));
            const auto v = mesh.faces[f][std::size_t(r.integer(0, 2))];
            const auto& ring = around[v];
            const auto g0 = ring[std::size_t(r.integer(0, int(ring.size()) - 1))];
            const auto w = mesh.faces[g0][std::size_t(r.integer(0, 2))];
            const auto& ring2 = around[w];
            const auto g = ring2[std::size_t(r.integer(0, int(ring2.size()) - 1))];
            bool shares = false;
            for (auto x : mesh.faces[f])
                for (auto y : mesh.faces[g]) shares |= x == y;
            if (shares || !seen.insert({std::min(f, g), std::max(f, g)}).second) continue;
            na.push_back(tris[f]), nb.push_back(tris[g]);
        }
        results.push_back(run_workload(tt, "near_pairs",
                                       "pairs of the mesh's triangles two rings apart that share no "
                                       "vertex (near misses)",
                                       na, nb, {}));
    }
    progress_done();

    // Advice: the cheapest tier without a wrong answer on every workload, by total time.
    struct tally {
        double ms = 0;
        long wrong = 0, tests = 0;
    };
    std::map<std::string, tally> tiers;
    for (const auto& w : results)
        for (const auto& row : w.rows)
            if (row.kind == "tier") {
                auto& t = tiers[row.name];
                t.ms += row.ms, t.wrong += row.c.wrong, t.tests += row.c.cases;
            }
    std::string best;
    for (const auto& [name, t] : tiers)
        if (t.wrong == 0 && (best.empty() || t.ms < tiers[best].ms)) best = name;
    long uncertain = 0, tests = 0;
    for (const auto& w : results) uncertain += w.rows[0].uncertain, tests += w.tests;

    j.key("scene").object();
    j.kv("file", o.scene).kv("vertices", mesh.vertices.size()).kv("triangles", tris.size()).kv("camera_rays", long(o.rays) * o.rays);
    j.key("workloads").array();
    for (const auto& w : results) {
        j.object().kv("name", w.name).kv("description", w.description).kv("tests", w.tests).kv("holes_apply", w.holes_apply);
        j.kv("uncertain", w.rows[0].uncertain);
        j.key("methods").array();
        for (const auto& row : w.rows)
            j.object()
                .kv("name", row.name)
                .kv("kind", row.kind)
                .kv("ms", row.ms)
                .kv("wrong", row.c.wrong)
                .kv("false_positive", row.c.false_positive)
                .kv("false_negative", row.c.false_negative)
                .kv("tests", row.c.cases)
                .kv("holes", row.holes)
                .end_object();
        j.end_array().end_object();
    }
    j.end_array();
    j.key("tiers").array();
    for (const char* name : {"approximate", "aggressive", "conservative", "exact"}) {
        const auto& t = tiers[name];
        j.object().kv("name", name).kv("ms", t.ms).kv("wrong", t.wrong).kv("tests", t.tests).end_object();
    }
    j.end_array();
    std::string text;
    char buf[512];
    const double exact_ms = tiers["exact"].ms;
    if (best == "exact") {
        std::snprintf(buf, sizeof buf,
                      "Only the exact tier made no mistake on this scene's %ld tests (%.0f ms). The filter "
                      "could not decide %ld of them (%.2f%%): that is how close this scene comes to the "
                      "decision boundaries.",
                      tests, exact_ms, uncertain, 100.0 * double(uncertain) / double(tests));
    } else {
        std::snprintf(buf, sizeof buf,
                      "The %s tier made no mistake on this scene's %ld tests and took %.0f ms against %.0f ms for "
                      "exact (%.2fx). Margin: the filter could not certify %ld of the tests (%.3f%%); %s answered "
                      "every one of them right here, but a scene with more such contacts can differ.",
                      best.c_str(), tests, tiers[best].ms, exact_ms, exact_ms / std::max(tiers[best].ms, 1e-9), uncertain,
                      100.0 * double(uncertain) / double(tests), best.c_str());
    }
    text = buf;
    for (const char* name : {"approximate", "aggressive", "conservative"}) {
        const auto& t = tiers[name];
        if (t.wrong == 0 || t.ms >= tiers[best].ms) continue;
        std::snprintf(buf, sizeof buf, " The %s tier (%.0f ms) gave %ld wrong answers.", name, t.ms, t.wrong);
        text += buf;
    }
    // The paths that replace the loop over every triangle: the cheapest scene and batch tiers that
    // made no mistake on the camera rays.
    const workload_result& sr = *std::find_if(results.begin(), results.end(), [](const auto& w) { return w.name == "scene_rays"; });
    const workload_result& cr = *std::find_if(results.begin(), results.end(), [](const auto& w) { return w.name == "camera_rays"; });
    const workload_result::row *scene_best = nullptr, *batch_best = nullptr;
    for (const auto& row : sr.rows) {
        if (row.c.wrong != 0) continue;
        auto& slot = row.kind == "tier" ? scene_best : batch_best;
        if (slot == nullptr || row.ms < slot->ms) slot = &row;
    }
    const std::string target = batch::simd_target();
    const int lanes = target.rfind("AVX3", 0) == 0 ? 8 : (target == "AVX2" ? 4 : (target == "SCALAR" ? 1 : 2));
    if (scene_best != nullptr) {
        double brute_ms = 0;
        for (const auto& row : cr.rows)
            if (row.name == scene_best->name) brute_ms = row.ms;
        std::snprintf(buf, sizeof buf,
                      " Through scene3 (a bounding volume hierarchy; node volume: the axis-aligned box, built in %.0f ms) the %s tier "
                      "answered the %ld camera rays in %.1f ms, against %.1f ms over every triangle.",
                      scene_build_ms, scene_best->name.c_str(), sr.tests, scene_best->ms, brute_ms);
        text += buf;
    }
    if (batch_best != nullptr) {
        std::snprintf(buf, sizeof buf, " Batches (%s, %d doubles a vector): %s took %.1f ms for every ray against every triangle.",
                      target.c_str(), lanes, batch_best->name.c_str(), batch_best->ms);
        text += buf;
    }
    progress("scene: bounding volumes");
    const auto bv = audit::measure_bounding_volumes(std::span<const point3>(mesh.vertices), o.reps);
    progress_done();
    j.key("advice").object().kv("tier", best).kv("uncertain", uncertain).kv("tests", tests).kv("text", text);
    j.kv("scene_tier", scene_best != nullptr ? scene_best->name : std::string("none")).kv("node_volume", "aabb");
    j.kv("batch_tier", batch_best != nullptr ? batch_best->name : std::string("none")).kv("batch_target", target).kv("batch_lanes", lanes);
    j.kv("bounding_volume", bv.advice).end_object();
    j.key("bounding_volumes").object().kv("hull_volume", bv.hull_volume).kv("hull_area", bv.hull_area);
    j.kv("hull_vertices", long(bv.hull_vertices)).kv("tightness_rule", bv.tightness_rule).key("rows").array();
    for (const auto& r : bv.rows) {
        j.object().kv("kind", r.kind).kv("source", r.source).kv("ours", r.ours).kv("build_ms", r.build_ms);
        j.kv("volume_ratio", r.volume_ratio)
            .kv("area_ratio", r.area_ratio)
            .kv("test_ns", r.test_ns)
            .kv("contains_all", r.contains_all)
            .end_object();
        if (r.ours && !r.contains_all) ++total_violations;
    }
    j.end_array().end_object();
    j.end_object();
    std::printf("scene %s: %zu triangles; advice: %s\nbounding volume: %s\n", o.scene.c_str(), tris.size(), text.c_str(),
                bv.advice.c_str());
}

// --- main ------------------------------------------------------------------------------------
[[noreturn]] void usage(const char* why) {
    std::fprintf(stderr,
                 "incidence-audit: %s\n"
                 "usage: incidence-audit [all | stability | tradeoff | scene FILE] [--scene FILE] [--out DIR]\n"
                 "       [--cases N] [--tradeoff-cases N] [--seed S] [--reps R] [--rays N] [--pairs N] [--no-report]\n",
                 why);
    std::exit(2);
}
long positive(const char* flag, const char* v) {
    char* end = nullptr;
    const long x = std::strtol(v, &end, 10);
    if (!end || *end || x <= 0) usage((std::string(flag) + " needs a positive integer").c_str());
    return x;
}

options parse(int argc, char** argv) {
    options o;
    int i = 1;
    if (i < argc && argv[i][0] != '-') o.command = argv[i++];
    if (o.command == "scene") {
        if (i >= argc) usage("scene needs a mesh file (OFF, OBJ, PLY or STL)");
        o.scene = argv[i++];
    } else if (o.command != "all" && o.command != "stability" && o.command != "tradeoff") {
        usage(("unknown command '" + o.command + "'").c_str());
    }
    for (; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) usage((a + " needs a value").c_str());
            return argv[++i];
        };
        if (a == "--out") o.out = value();
        else if (a == "--scene") o.scene = value();
        else if (a == "--cases") o.cases = positive("--cases", value());
        else if (a == "--tradeoff-cases") o.tradeoff_cases = positive("--tradeoff-cases", value());
        else if (a == "--seed") o.seed = std::uint64_t(positive("--seed", value()));
        else if (a == "--reps") o.reps = int(positive("--reps", value()));
        else if (a == "--rays") o.rays = int(positive("--rays", value()));
        else if (a == "--pairs") o.pairs = positive("--pairs", value());
        else if (a == "--no-report") o.report = false;
        else usage(("unknown option '" + a + "'").c_str());
    }
    return o;
}

} // namespace

int main(int argc, char** argv) {
    tty = isatty(2) != 0;
    const options o = parse(argc, argv);
    const double t0 = now_ns();
    audit::json j;
    j.object().kv("schema", "incidence-audit/1").kv("command", o.command);
    std::string cmdline;
    for (int i = 0; i < argc; ++i) cmdline += (i ? " " : "") + std::string(argv[i]);
    j.kv("command_line", cmdline);
    j.key("families").array();
    catalog::for_each_family([&](const auto& fam) {
        using F = std::decay_t<decltype(fam)>;
        j.object().kv("name", fam.name).kv("first", shape_name(static_cast<const typename F::first_type*>(nullptr)));
        j.kv("second", shape_name(static_cast<const typename F::second_type*>(nullptr))).kv("approximate_method", fam.approximate_method);
        write_methods(j, audit::methods_of<false>(fam)); // names only: the parts run them
        j.end_object();
    });
    j.end_array();
    try {
        if (o.command == "all" || o.command == "stability") stability(j, o);
        if (o.command == "all" || o.command == "tradeoff") tradeoff(j, o);
        if (o.command == "scene" || (o.command == "all" && !o.scene.empty())) scene(j, o);
    } catch (const std::exception& e) {
        progress_done();
        std::fprintf(stderr, "incidence-audit: %s\n", e.what());
        return 1;
    }
    j.kv("seconds", (now_ns() - t0) * 1e-9).kv("contract_violations", total_violations).end_object();
    std::filesystem::create_directories(o.out);
    const std::string json_path = o.out + "/audit.json", html_path = o.out + "/report.html";
    {
        std::ofstream f(json_path);
        f << j.text() << '\n';
        if (!f) {
            std::fprintf(stderr, "incidence-audit: cannot write %s\n", json_path.c_str());
            return 1;
        }
    }
    std::printf("audit data: %s\n", json_path.c_str());
    if (o.report) {
        const std::string cmd = "'" INCIDENCE_PYTHON "' '" INCIDENCE_AUDIT_REPORT_PY "' '" + json_path + "' '" + html_path + "'";
        if (std::system(cmd.c_str()) != 0) {
            std::fprintf(stderr, "incidence-audit: the report could not be drawn (%s)\n", cmd.c_str());
            return 1;
        }
        std::printf("report: %s\n", std::filesystem::absolute(html_path).c_str());
    }
    if (total_violations) {
        std::fprintf(stderr, "incidence-audit: %ld contract violations (see audit.json)\n", total_violations);
        return 3;
    }
    return 0;
}
