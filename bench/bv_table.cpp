// incidence-bv-table: the bounding-volume trade-off table on real meshes. For every mesh and
// every construction of incidence.bound: build time (median of --reps runs), volume and surface
// area relative to the convex hull, cost of one overlap test, exact containment of every vertex;
// CGAL's minimum sphere and convex hull side by side. Writes DIR/bv-table.md and DIR/bv-table.json.
//   incidence-bv-table [--out DIR] [--reps N] [MESH ...]   (default: the meshes run.sh unpacks)
#include "testkit/oracle/cgal_oracle.hpp"
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <random>
#include <string>
#include <vector>
import incidence;
#include "testkit/bounding.hpp"
#include "testkit/json.hpp"
#include "testkit/mesh_io.hpp"

int main(int argc, char** argv) {
    std::string out = "bv-table";
    int reps = 5;
    std::vector<std::string> meshes;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--out" && i + 1 < argc) out = argv[++i];
        else if (a == "--reps" && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
        else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "usage: incidence-bv-table [--out DIR] [--reps N] [MESH ...]\n");
            return 2;
        } else meshes.push_back(a);
    }
    if (meshes.empty())
        for (const char* m : {"bunny00", "armadillo", "elephant", "fandisk", "ChineseDragon-10kv"})
            meshes.push_back(std::string(INCIDENCE_SOURCE_DIR) + "/build/data/meshes/" + m + ".off");
    std::filesystem::create_directories(out);
    std::string md = "# Bounding volumes on real meshes\n\nVolume and area are relative to the convex hull (CGAL convex_hull_3). "
                     "Build: median of " +
                     std::to_string(reps) +
                     " runs. Test: one overlap test between two volumes of the kind "
                     "(exact tier for boxes and spheres, slab overlap for k-DOPs). Every volume of ours is checked to contain every "
                     "vertex exactly.\n";
    audit::json j;
    j.object().kv("reps", reps).key("meshes").array();
    int bad = 0;
    for (const auto& file : meshes) {
        audit::mesh m;
        try {
            m = audit::read_mesh(file);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "incidence-bv-table: %s\n", e.what());
            return 1;
        }
        const auto rep = audit::measure_bounding_volumes(std::span<const incidence::point3>(m.vertices), reps);
        const std::string name = std::filesystem::path(file).stem().string();
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      "\n## %s (%zu vertices; hull: %lu vertices, built by CGAL in %.2f ms)\n\n"
                      "| volume | build ms | volume / hull | area / hull | test ns | contains all | hull vertices |\n"
                      "|---|---:|---:|---:|---:|---|---:|\n",
                      name.c_str(), m.vertices.size(), rep.hull_vertices, rep.hull_ms);
        md += buf;
        j.object().kv("name", name).kv("vertices", m.vertices.size()).kv("hull_vertices", long(rep.hull_vertices));
        j.kv("hull_ms", rep.hull_ms).kv("advice", rep.advice).key("rows").array();
        for (const auto& r : rep.rows) {
            std::snprintf(buf, sizeof buf, "| %s | %.4f | %.3f | %.3f | %s | %s | %s |\n", r.kind.c_str(), r.build_ms, r.volume_ratio,
                          r.area_ratio, r.ours && r.test_ns > 0 ? std::to_string(r.test_ns).substr(0, 5).c_str() : "",
                          r.ours ? (r.contains_all ? "yes" : "**NO**") : "",
                          r.failed ? "error" : (r.vertices ? std::to_string(r.vertices).c_str() : ""));
            md += buf;
            if (r.ours && !r.contains_all) ++bad;
            j.object().kv("kind", r.kind).kv("source", r.source).kv("ours", r.ours).kv("build_ms", r.build_ms);
            j.kv("vertices", long(r.vertices))
                .kv("failed", r.failed)
                .kv("volume_ratio", r.volume_ratio)
                .kv("area_ratio", r.area_ratio)
                .kv("test_ns", r.test_ns)
                .kv("contains_all", r.contains_all)
                .end_object();
        }
        j.end_array().end_object();
        md += "\nAdvice: " + rep.advice + "\n";
        std::printf("%s: %s\n", name.c_str(), rep.advice.c_str());
    }
    j.end_array();
    // Degenerate inputs: our hull's dimension and vertex count against qhull's default run.
    md += "\n## Degenerate inputs: convex hull\n\n| input | points | ours: dimension, vertices | qhull |\n|---|---:|---|---|\n";
    j.key("degenerate").array();
    std::mt19937_64 g(11);
    std::uniform_int_distribution<int> small(-50, 50);
    auto add = [&](const char* what, std::vector<incidence::point3> pts) {
        const auto h = incidence::bound::convex_hull(std::span<const incidence::point3>(pts));
        std::vector<double> xyz;
        for (const auto& p : pts) xyz.insert(xyz.end(), {p.x, p.y, p.z});
        const auto q = oracle::qhull_hull(xyz.data(), pts.size());
        char line[300];
        std::snprintf(line, sizeof line, "| %s | %zu | %d, %zu | %s |\n", what, pts.size(), h ? h.value().dimension : -1,
                      h ? h.value().vertices.size() : 0,
                      q.error ? "error (precision or flat input)" : (std::to_string(q.vertices) + " vertices").c_str());
        md += line;
        j.object().kv("input", what).kv("points", pts.size()).kv("dimension", h ? h.value().dimension : -1);
        j.kv("vertices", h ? h.value().vertices.size() : std::size_t{0})
            .kv("qhull_error", q.error)
            .kv("qhull_vertices", long(q.vertices))
            .end_object();
    };
    std::vector<incidence::point3> pts;
    for (int i = 0; i < 1000; ++i) {
        const double x = small(g), y = small(g);
        pts.push_back({x, y, x - 2 * y});
    }
    add("coplanar (z = x - 2y, integers)", pts);
    pts.clear();
    for (int i = 0; i < 1000; ++i) {
        const double t = small(g);
        pts.push_back({t, 2 * t, -t});
    }
    add("collinear", pts);
    pts.clear();
    for (int i = 0; i < 1000; ++i)
        pts.push_back({std::nextafter(1.0, 1.0 + small(g)), std::nextafter(2.0, 2.0 + small(g)), std::nextafter(3.0, 3.0 + small(g))});
    add("1000 points within 1 ulp of (1, 2, 3)", pts);
    pts.clear();
    for (int i = 0; i < 1000; ++i) pts.push_back({double(small(g) % 3), double(small(g) % 3), double(small(g) % 3)});
    add("5 x 5 x 5 integer grid, repeated", pts);
    pts.assign(1000, {0.25, 0.5, 0.75});
    add("one point repeated", pts);
    j.end_array().end_object();
    std::ofstream(out + "/bv-table.md") << md;
    std::ofstream(out + "/bv-table.json") << j.text() << '\n';
    std::printf("table: %s/bv-table.md\n", out.c_str());
    if (bad) std::fprintf(stderr, "incidence-bv-table: %d volumes do not contain every vertex\n", bad);
    return bad ? 1 : 0;
}
