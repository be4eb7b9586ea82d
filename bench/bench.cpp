// Google Benchmark: every query x tier x input set, named tier/query/pair/distribution, with CGAL
// Epick and Epeck on the same inputs where CGAL has the query. Before timing, each benchmark
// checks its answers against CGAL Epeck on the whole input set: the exact tier, conservative,
// aggressive and classify must keep their promises (SkipWithError otherwise); approximate
// methods report their wrong answers as the counter `wrong_pct`.
// Run: bench/incidence_bench --benchmark_format=json  (the numbers belong in notes, not tests)
#include <benchmark/benchmark.h>
#include "../tests/oracle/cgal_oracle.hpp"
#include "fcl_peer.hpp"
#include <cmath>
#include <algorithm>
#include <functional>
#include <random>
#include <string>
#include <vector>
import incidence;
#include "../tests/support/testing.hpp"
#include "../tests/support/obb_cases.hpp"
#include "../tests/support/flat_cases.hpp"
#include "../tests/support/mesh_cases.hpp"
#include "../tests/support/polygon_cases.hpp"
#include "../tests/support/kdop_cases.hpp"
#include "../tests/support/lp_shapes.hpp"
#include "../tests/support/polyhedron_cases.hpp"

using namespace incidence;

namespace {
constexpr int set_size = 1024;
std::mt19937_64 gen(20261122);
double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
int irand(int a, int b) { return std::uniform_int_distribution<int>(a, b)(gen); }
double small() { return irand(-16, 16) + irand(0, 3) * 0.25; }
double nudge(double x) {
    const int k = irand(-2, 2);
    for (int i = 0; i < k; ++i) x = std::nextafter(x, INFINITY);
    for (int i = 0; i > k; --i) x = std::nextafter(x, -INFINITY);
    return x;
}
point3 rp() { return {uni(-1, 1), uni(-1, 1), uni(-1, 1)}; }
aabb3 box(point3 a, point3 b) { // the box spanned by two corners in any order
    return {{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}, {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
}
point3 np(double x, double y, double z) { return {nudge(x), nudge(y), nudge(z)}; }
void arr(point3 p, double* o) { o[0] = p.x; o[1] = p.y; o[2] = p.z; }
void arr(vec3 p, double* o) { o[0] = p.x; o[1] = p.y; o[2] = p.z; }

enum class check { exact, conservative, aggressive, classify, approximate };

// Registers one benchmark over a case set: f(case) -> bool (or certainty for classify).
template <class Case, class F>
void reg(const std::string& name, const std::vector<Case>& cases, const std::vector<bool>& truth, check kind, F f) {
    benchmark::RegisterBenchmark(name.c_str(), [cases, truth, kind, f](benchmark::State& st) {
        long wrong = 0, broken = 0;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const auto r = f(cases[i]);
            bool yes;
            if constexpr (std::is_same_v<decltype(r), const certainty>) {
                if (r == certainty::uncertain) continue;
                yes = r == certainty::yes;
                if (yes != truth[i]) ++broken;
                continue;
            } else {
                yes = static_cast<bool>(r);
            }
            if (yes != truth[i]) ++wrong;
            if (kind == check::exact && yes != truth[i]) ++broken;
            if (kind == check::conservative && truth[i] && !yes) ++broken;
            if (kind == check::aggressive && !truth[i] && yes) ++broken;
        }
        if (broken != 0) {
            st.SkipWithError("answer check failed before timing");
            return;
        }
        std::size_t i = 0;
        for (auto _ : st) {
            benchmark::DoNotOptimize(f(cases[i]));
            if (++i == cases.size()) i = 0;
        }
        st.counters["wrong_pct"] = 100.0 * static_cast<double>(wrong) / static_cast<double>(cases.size());
    });
}

struct rt { ray3 r; triangle3 t; };
struct ab { aabb3 b; ray3 r; };
struct o3 { point3 a, b, c, d; };
struct rs { ray3 r; sphere3 s; };
struct ss { sphere3 a, b; };
struct bb { aabb3 a, b; };

std::vector<rt> ray_triangle_set(bool near) {
    std::vector<rt> v;
    while (v.size() < set_size) {
        if (!near) {
            const point3 o = rp();
            const triangle3 t{rp(), rp(), rp()};
            v.push_back({ray3{o, (t.a - o) * 0.4 + (t.b - o) * 0.3 + vec3{uni(-0.5, 0.5), uni(-0.5, 0.5), uni(-0.5, 0.5)}}, t});
        } else { // aimed at a vertex or an edge point, nudged by up to 2 ulps
            const point3 a{small(), small(), small()}, b{small(), small(), small()}, c{small(), small(), small()};
            const double s = irand(0, 4) * 0.25;
            const point3 target{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)};
            const point3 o{small(), small(), small()};
            const vec3 d = target - o;
            v.push_back({ray3{np(o.x, o.y, o.z), d}, triangle3{np(a.x, a.y, a.z), np(b.x, b.y, b.z), np(c.x, c.y, c.z)}});
        }
        double a_[3], b_[3], c_[3];
        arr(v.back().t.a, a_); arr(v.back().t.b, b_); arr(v.back().t.c, c_);
        if (oracle::triangle_is_degenerate(a_, b_, c_) || v.back().r.direction == vec3{0, 0, 0}) v.pop_back();
    }
    return v;
}
std::vector<ab> aabb_ray_set(bool near) {
    std::vector<ab> v;
    while (v.size() < set_size) {
        if (!near) {
            v.push_back({box(rp(), rp()), ray3{point3{uni(-3, 3), uni(-3, 3), uni(-3, 3)}, vec3{uni(-1, 1), uni(-1, 1), uni(-1, 1)}}});
        } else { // aimed at a face, an edge or a corner
            const point3 lo{small(), small(), small()};
            const point3 hi{lo.x + irand(1, 6) * 0.5, lo.y + irand(1, 6) * 0.5, lo.z + irand(1, 6) * 0.5};
            const point3 target{irand(0, 1) ? lo.x : hi.x, irand(0, 1) ? lo.y : hi.y, irand(0, 2) ? lo.z : (lo.z + hi.z) / 2};
            const point3 o{small(), small(), small()};
            v.push_back({aabb3{np(lo.x, lo.y, lo.z), np(hi.x, hi.y, hi.z)}, ray3{np(o.x, o.y, o.z), target - o}});
            if (v.back().b.min.x > v.back().b.max.x || v.back().b.min.y > v.back().b.max.y || v.back().b.min.z > v.back().b.max.z) v.pop_back();
        }
        if (!v.empty() && v.back().r.direction == vec3{0, 0, 0}) v.pop_back();
    }
    return v;
}
std::vector<o3> orient3d_set(bool near) {
    std::vector<o3> v;
    while (v.size() < set_size) {
        if (!near) {
            v.push_back({rp(), rp(), rp(), rp()});
        } else { // coplanar by construction, then nudged
            const point3 a{small(), small(), small()}, b{small(), small(), small()}, c{small(), small(), small()};
            const double s = irand(-4, 4) * 0.5, t = irand(-4, 4) * 0.5;
            const point3 d{a.x + s * (b.x - a.x) + t * (c.x - a.x), a.y + s * (b.y - a.y) + t * (c.y - a.y), a.z + s * (b.z - a.z) + t * (c.z - a.z)};
            v.push_back({np(a.x * 0.1, a.y * 0.1, a.z * 0.1), np(b.x * 0.1, b.y * 0.1, b.z * 0.1), np(c.x * 0.1, c.y * 0.1, c.z * 0.1),
                         np(d.x * 0.1, d.y * 0.1, d.z * 0.1)});
        }
    }
    return v;
}
std::vector<rs> ray_sphere_set(bool near) {
    std::vector<rs> v;
    while (v.size() < set_size) {
        if (!near) {
            v.push_back({ray3{rp(), vec3{uni(-1, 1), uni(-1, 1), uni(-1, 1)}}, sphere3{rp(), uni(0, 0.7)}});
        } else { // tangent rays: origin (c.x + r, c.y - k, c.z), direction +y
            const point3 c{small(), small(), small()};
            const double r = irand(1, 8) * 0.5;
            v.push_back({ray3{np(c.x + r, c.y - irand(1, 8), c.z), vec3{0, 1, 0}}, sphere3{np(c.x, c.y, c.z), r}});
        }
    }
    return v;
}
std::vector<ss> sphere_sphere_set(bool near) {
    std::vector<ss> v;
    while (v.size() < set_size) {
        if (!near) v.push_back({sphere3{rp(), uni(0, 0.7)}, sphere3{rp(), uni(0, 0.7)}});
        else {
            const point3 c{small(), small(), small()};
            const double r1 = irand(1, 8) * 0.5, r2 = irand(1, 8) * 0.5;
            v.push_back({sphere3{np(c.x, c.y, c.z), r1}, sphere3{np(c.x + 2 * (r1 + r2) * 0.5, c.y, c.z), r2}});
        }
    }
    return v;
}
std::vector<bb> aabb_aabb_set(bool near) {
    std::vector<bb> v;
    while (v.size() < set_size) {
        const point3 c{small(), small(), small()};
        const aabb3 a = near ? box(c, point3{c.x + 1, c.y + 1, c.z + 1}) : box(rp(), rp());
        // touching faces when near
        const aabb3 b = near ? box(point3{a.max.x, a.min.y, a.min.z}, point3{a.max.x + 1, a.max.y, a.max.z}) : box(rp(), rp());
        v.push_back({a, b});
    }
    return v;
}

template <class Case, class Truth, class Tiered>
void tiers(const std::string& pair, const std::string& dist, const std::vector<Case>& cs, Truth truth_of, Tiered f) {
    std::vector<bool> truth;
    for (const auto& c : cs) truth.push_back(truth_of(c));
    reg("exact/intersects/" + pair + "/" + dist, cs, truth, check::exact, [f](const Case& c) { return f(exact{}, c); });
    reg("conservative/intersects/" + pair + "/" + dist, cs, truth, check::conservative, [f](const Case& c) { return f(conservative{}, c); });
    reg("aggressive/intersects/" + pair + "/" + dist, cs, truth, check::aggressive, [f](const Case& c) { return f(aggressive{}, c); });
    reg("approximate/intersects/" + pair + "/" + dist, cs, truth, check::approximate, [f](const Case& c) { return f(approximate{}, c); });
}

// An OBB pair on the tests' generators (tests/support/obb_cases.hpp), the LP oracle as truth.
template <class A, class B>
std::vector<std::pair<A, B>> obb_tiers(const std::string& pair, bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r(20261122 + (near ? 1 : 0));
    std::vector<std::pair<A, B>> cs;
    // at scale 1, like the other sets (the tests add scales 2^-500 .. 2^500)
    while (cs.size() < set_size) cs.push_back(near ? support::obb_case<A, B>::near(r, false) : support::obb_case<A, B>::random(r, false));
    auto truth = [](const std::pair<A, B>& c) { return oracle::lp_intersect(support::lp(c.first), support::lp(c.second)); };
    tiers(pair, dist, cs, truth, [](auto tier, const std::pair<A, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
    return cs;
}
// A flat pair (points, lines, rays, segments, planes, triangles) on the tests' generators
// (tests/support/flat_cases.hpp) at scale 1, CGAL Epeck as truth, and CGAL Epick's do_intersect.
template <class A, class B>
void flat_tiers(const std::string& pair, bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r(20261122 + (near ? 1 : 0));
    std::vector<std::pair<A, B>> cs;
    while (cs.size() < set_size) cs.push_back(near ? support::flat_near<A, B>(r, false) : support::flat_random<A, B>(r, false));
    auto truth = [](const std::pair<A, B>& c) { return support::flat_truth(c.first, c.second); };
    tiers(pair, dist, cs, truth, [](auto tier, const std::pair<A, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
    std::vector<bool> t;
    for (const auto& c : cs) t.push_back(truth(c));
    reg("cgal_epick/intersects/" + pair + "/" + dist, cs, t, check::approximate, [](const std::pair<A, B>& c) {
        return oracle::flat_intersect_epick(support::to_flat(c.first), support::to_flat(c.second));
    });
}
// A pair of a mesh or a polygon (a view of arrays a store owns) on the tests' generators, its
// oracle as truth: make_case(rng, store, other, near) returns the partner (for a view, other's view).
template <class Store, class B, class Gen, class Truth>
void view_tiers(const std::string& pair, bool near, Gen make_case, Truth truth_of) {
    struct view_case {
        Store m, other;
        B b{};
        B partner() const {
            if constexpr (std::is_same_v<B, decltype(Store{}.view())>) return other.view();
            else return b;
        }
    };
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r(20261122 + (near ? 1 : 0));
    std::vector<view_case> cs;
    while (cs.size() < set_size) {
        view_case c;
        c.b = make_case(r, c.m, c.other, near);
        cs.push_back(std::move(c));
    }
    auto truth = [&](const view_case& c) { return truth_of(c.m.view(), c.partner()); };
    tiers(pair, dist, cs, truth, [](auto tier, const view_case& c) { return intersects<decltype(tier)>(c.m.view(), c.partner()); });
}
// A mesh pair (tests/support/mesh_cases.hpp: closed non-convex star meshes of 12 or 48
// triangles, at every scale the tests use), the mesh oracle as truth.
template <class B>
void mesh_tiers(const std::string& pair, bool near) {
    view_tiers<support::mesh_store, B>(
        pair, near,
        [](support::rng& r, support::mesh_store& m, support::mesh_store& o, bool nr) {
            return nr ? support::mesh_near<B>(r, m, o) : support::mesh_random<B>(r, m, o);
        },
        [](const mesh3& m, const B& b) { return support::mesh_truth(m, b); });
}
// A polygon pair (tests/support/polygon_cases.hpp: simple non-convex star polygons of 8 to 24
// vertices, half with a hole of 8, at every scale the tests use), the polygon oracle as truth.
template <class B>
void polygon_tiers(const std::string& pair, bool near) {
    view_tiers<support::polygon_store, B>(
        pair, near,
        [](support::rng& r, support::polygon_store& g, support::polygon_store& o, bool nr) {
            return nr ? support::polygon_near<B>(r, g, o) : support::polygon_random<B>(r, g, o);
        },
        [](const polygon2& g, const B& b) { return support::polygon_truth(g, b); });
}
// A k-DOP pair (tests/support/kdop_cases.hpp: the k-DOP of a few points, at every scale the
// tests use), the LP oracle as truth.
template <int K, class B>
void kdop_tiers(const std::string& pair, bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r(20261122 + (near ? 1 : 0));
    std::vector<std::pair<kdop<K>, B>> cs;
    while (cs.size() < set_size)
        if (const auto c = near ? support::kdop_near<K, B>(r) : support::kdop_random<K, B>(r)) cs.push_back(*c);
    auto truth = [](const std::pair<kdop<K>, B>& c) { return oracle::lp_intersect(support::lp(c.first), support::lp(c.second)); };
    tiers(pair + "_" + std::to_string(K), dist, cs, truth, [](auto tier, const std::pair<kdop<K>, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
}
// A half-space pair (tests/support/polyhedron_cases.hpp: supporting half-spaces of a cloud, or a
// camera frustum; near-degenerate: integer normals through boundary points), the LP as truth.
template <class P, class B>
void halfspace_tiers(const std::string& pair, bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r(20261122 + (near ? 1 : 0));
    std::vector<std::pair<P, B>> cs;
    while (cs.size() < set_size)
        if (const auto c = near ? support::halfspace_near<P, B>(r) : support::halfspace_random<P, B>(r)) cs.push_back(*c);
    auto truth = [](const std::pair<P, B>& c) { return oracle::lp_intersect(support::lp(c.first), support::lp(c.second)); };
    tiers(pair, dist, cs, truth, [](auto tier, const std::pair<P, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
}
void obb_arrays(const obb3& b, double* c, double* a, double* h) {
    arr(b.center, c);
    for (unsigned i = 0; i < 3; ++i) arr(b.axes[i], a + 3 * i), h[i] = b.half_extents[i];
}

void register_all() {
    for (const bool near : {false, true}) {
        const std::string dist = near ? "near_degenerate" : "random";
        {
            const auto cs = obb_tiers<obb3, obb3>("obb_obb", near);
            std::vector<bool> t;
            for (const auto& c : cs) t.push_back(oracle::lp_intersect(support::lp(c.first), support::lp(c.second)));
            reg("gottschalk/intersects/obb_obb/" + dist, cs, t, check::approximate,
                [](const std::pair<obb3, obb3>& c) { return method::obb_obb_gottschalk(c.first, c.second); });
            reg("fcl/intersects/obb_obb/" + dist, cs, t, check::approximate, [](const std::pair<obb3, obb3>& c) {
                double ca[3], aa[9], ha[3], cb[3], ab[9], hb[3];
                obb_arrays(c.first, ca, aa, ha), obb_arrays(c.second, cb, ab, hb);
                return fcl_peer::obb_obb(ca, aa, ha, cb, ab, hb);
            });
            (void)obb_tiers<aabb3, obb3>("aabb_obb", near);
            (void)obb_tiers<obb3, point3>("obb_point", near);
            (void)obb_tiers<obb3, segment3>("obb_segment", near);
            (void)obb_tiers<obb3, ray3>("obb_ray", near);
            (void)obb_tiers<line3, obb3>("line_obb", near);
            (void)obb_tiers<obb3, triangle3>("obb_triangle", near);
            (void)obb_tiers<obb3, plane3>("obb_plane", near);
            (void)obb_tiers<obb3, tetrahedron3>("obb_tetrahedron", near);
            mesh_tiers<obb3>("mesh_obb", near);
        }
        flat_tiers<segment3, segment3>("segment_segment", near);
        flat_tiers<line3, line3>("line_line", near);
        flat_tiers<line3, point3>("line_point", near);
        flat_tiers<line3, ray3>("line_ray", near);
        flat_tiers<line3, segment3>("line_segment", near);
        flat_tiers<point3, point3>("point_point", near);
        flat_tiers<point3, ray3>("point_ray", near);
        flat_tiers<point3, segment3>("point_segment", near);
        flat_tiers<ray3, ray3>("ray_ray", near);
        flat_tiers<ray3, segment3>("ray_segment", near);
        flat_tiers<line3, triangle3>("line_triangle", near);
        flat_tiers<point3, triangle3>("point_triangle", near);
        flat_tiers<plane3, point3>("plane_point", near);
        flat_tiers<line3, plane3>("line_plane", near);
        flat_tiers<plane3, ray3>("plane_ray", near);
        flat_tiers<plane3, plane3>("plane_plane", near);
        flat_tiers<point3, tetrahedron3>("point_tetrahedron", near);
        flat_tiers<segment3, tetrahedron3>("segment_tetrahedron", near);
        flat_tiers<ray3, tetrahedron3>("ray_tetrahedron", near);
        flat_tiers<line3, tetrahedron3>("line_tetrahedron", near);
        flat_tiers<plane3, tetrahedron3>("plane_tetrahedron", near);
        flat_tiers<tetrahedron3, triangle3>("tetrahedron_triangle", near);
        flat_tiers<tetrahedron3, tetrahedron3>("tetrahedron_tetrahedron", near);
        flat_tiers<aabb3, tetrahedron3>("aabb_tetrahedron", near);
        mesh_tiers<point3>("mesh_point", near);
        mesh_tiers<segment3>("mesh_segment", near);
        mesh_tiers<ray3>("mesh_ray", near);
        mesh_tiers<line3>("line_mesh", near);
        mesh_tiers<plane3>("mesh_plane", near);
        mesh_tiers<triangle3>("mesh_triangle", near);
        mesh_tiers<tetrahedron3>("mesh_tetrahedron", near);
        mesh_tiers<aabb3>("aabb_mesh", near);
        mesh_tiers<mesh3>("mesh_mesh", near);
        flat_tiers<segment2, segment2>("segment2_segment2", near);
        flat_tiers<line2, line2>("line2_line2", near);
        flat_tiers<line2, point2>("line2_point2", near);
        flat_tiers<line2, ray2>("line2_ray2", near);
        flat_tiers<line2, segment2>("line2_segment2", near);
        flat_tiers<point2, point2>("point2_point2", near);
        flat_tiers<point2, ray2>("point2_ray2", near);
        flat_tiers<point2, segment2>("point2_segment2", near);
        flat_tiers<ray2, ray2>("ray2_ray2", near);
        flat_tiers<ray2, segment2>("ray2_segment2", near);
        polygon_tiers<point2>("point2_polygon2", near);
        polygon_tiers<segment2>("polygon2_segment2", near);
        polygon_tiers<ray2>("polygon2_ray2", near);
        polygon_tiers<line2>("line2_polygon2", near);
        polygon_tiers<polygon2>("polygon2_polygon2", near);
        kdop_tiers<14, point3>("kdop_point", near);
        kdop_tiers<14, segment3>("kdop_segment", near);
        kdop_tiers<14, ray3>("kdop_ray", near);
        kdop_tiers<14, line3>("kdop_line", near);
        kdop_tiers<26, ray3>("kdop_ray", near);
        kdop_tiers<14, kdop<14>>("kdop_kdop", near);
        kdop_tiers<26, kdop<26>>("kdop_kdop", near);
        kdop_tiers<14, aabb3>("aabb_kdop", near);
        halfspace_tiers<convex_polyhedron3, point3>("convex_polyhedron_point", near);
        halfspace_tiers<convex_polyhedron3, segment3>("convex_polyhedron_segment", near);
        halfspace_tiers<convex_polyhedron3, ray3>("convex_polyhedron_ray", near);
        halfspace_tiers<convex_polyhedron3, line3>("convex_polyhedron_line", near);
        halfspace_tiers<frustum3, point3>("frustum_point", near);
        halfspace_tiers<frustum3, segment3>("frustum_segment", near);
        halfspace_tiers<frustum3, ray3>("frustum_ray", near);
        halfspace_tiers<frustum3, line3>("frustum_line", near);
        {
            const auto cs = ray_triangle_set(near);
            auto truth = [](const rt& c) {
                double o[3], d[3], a[3], b[3], cc[3];
                arr(c.r.origin, o); arr(c.r.direction, d); arr(c.t.a, a); arr(c.t.b, b); arr(c.t.c, cc);
                return oracle::ray_triangle(o, d, a, b, cc);
            };
            tiers("ray_triangle", dist, cs, truth, [](auto tier, const rt& c) { return intersects<decltype(tier)>(c.r, c.t); });
            std::vector<bool> t;
            for (const auto& c : cs) t.push_back(truth(c));
            reg("classify/intersects/ray_triangle/" + dist, cs, t, check::classify, [](const rt& c) { return classify(c.r, c.t); });
            reg("moller_trumbore/intersects/ray_triangle/" + dist, cs, t, check::approximate,
                [](const rt& c) { return method::ray_triangle_moller_trumbore(c.r, c.t).has_value(); });
            reg("sign_algorithm_double/intersects/ray_triangle/" + dist, cs, t, check::approximate, [](const rt& c) {
                arith::approx_kernel k;
                return pair::intersects(k, c.r, c.t);
            });
            reg("exact/intersection/ray_triangle/" + dist, cs, t, check::exact, [](const rt& c) { return intersection(c.r, c.t).has_value(); });
            // Epick builds Ray_3(point, vector) by rounding point + vector: not exact for such rays.
            reg("cgal_epick/intersects/ray_triangle/" + dist, cs, t, check::approximate, [](const rt& c) {
                double o[3], d[3], a[3], b[3], cc[3];
                arr(c.r.origin, o); arr(c.r.direction, d); arr(c.t.a, a); arr(c.t.b, b); arr(c.t.c, cc);
                return oracle::ray_triangle_epick(o, d, a, b, cc);
            });
            reg("cgal_epeck/intersects/ray_triangle/" + dist, cs, t, check::exact, truth);
        }
        {
            const auto cs = aabb_ray_set(near);
            auto truth = [](const ab& c) {
                double o[3], d[3], mn[3], mx[3];
                arr(c.r.origin, o); arr(c.r.direction, d); arr(c.b.min, mn); arr(c.b.max, mx);
                return oracle::ray_box(o, d, mn, mx);
            };
            tiers("aabb_ray", dist, cs, truth, [](auto tier, const ab& c) { return intersects<decltype(tier)>(c.b, c.r); });
            std::vector<bool> t;
            for (const auto& c : cs) t.push_back(truth(c));
            reg("woo/intersects/aabb_ray/" + dist, cs, t, check::approximate, [](const ab& c) { return method::aabb_ray_woo(c.b, c.r); });
            reg("sign_algorithm_double/intersects/aabb_ray/" + dist, cs, t, check::approximate, [](const ab& c) {
                arith::approx_kernel k;
                return pair::intersects(k, c.b, c.r);
            });
            reg("cgal_epick/intersects/aabb_ray/" + dist, cs, t, check::approximate, [](const ab& c) {
                double o[3], d[3], mn[3], mx[3];
                arr(c.r.origin, o); arr(c.r.direction, d); arr(c.b.min, mn); arr(c.b.max, mx);
                return oracle::ray_box_epick(o, d, mn, mx);
            });
            reg("cgal_epeck/intersects/aabb_ray/" + dist, cs, t, check::exact, truth);
        }
        {
            const auto cs = orient3d_set(near);
            std::vector<bool> t; // "truth" for orient3d: sign > 0 (the full sign is checked below)
            std::vector<int> sgn;
            for (const auto& c : cs) {
                double a[3], b[3], cc[3], d[3];
                arr(c.a, a); arr(c.b, b); arr(c.c, cc); arr(c.d, d);
                sgn.push_back(oracle::orient3d(a, b, cc, d));
                t.push_back(sgn.back() > 0);
            }
            reg("exact/orient3d/points/" + dist, cs, t, check::exact, [](const o3& c) { return orient3d(c.a, c.b, c.c, c.d) == sign::positive; });
            reg("approximate/orient3d/points/" + dist, cs, t, check::approximate,
                [](const o3& c) { return orient3d<approximate>(c.a, c.b, c.c, c.d) == sign::positive; });
            reg("cgal_epick/orient3d/points/" + dist, cs, t, check::exact, [](const o3& c) {
                double a[3], b[3], cc[3], d[3];
                arr(c.a, a); arr(c.b, b); arr(c.c, cc); arr(c.d, d);
                return oracle::orient3d_epick(a, b, cc, d) > 0;
            });
        }
        {
            const auto cs = ray_sphere_set(near);
            auto truth = [](const rs& c) {
                double o[3], d[3], cc[3];
                arr(c.r.origin, o); arr(c.r.direction, d); arr(c.s.center, cc);
                return oracle::ray_ball(o, d, cc, c.s.radius);
            };
            tiers("ray_sphere", dist, cs, truth, [](auto tier, const rs& c) { return intersects<decltype(tier)>(c.r, c.s); });
            std::vector<bool> t;
            for (const auto& c : cs) t.push_back(truth(c));
            reg("algebraic/intersects/ray_sphere/" + dist, cs, t, check::approximate, [](const rs& c) { return method::ray_sphere_algebraic(c.r, c.s).has_value(); });
            reg("cgal_epeck/intersects/ray_sphere/" + dist, cs, t, check::exact, truth);
        }
        {
            const auto cs = sphere_sphere_set(near);
            auto truth = [](const ss& c) {
                double a[3], b[3];
                arr(c.a.center, a); arr(c.b.center, b);
                return oracle::ball_ball(a, c.a.radius, b, c.b.radius);
            };
            tiers("sphere_sphere", dist, cs, truth, [](auto tier, const ss& c) { return intersects<decltype(tier)>(c.a, c.b); });
        }
        {
            // point x sphere: random points and balls; near: points on the sphere (3-4-5 and
            // 1-2-2 triples scaled), nudged by up to 2 ulps.
            struct ps { point3 p; sphere3 s; };
            std::vector<ps> cs;
            while (cs.size() < set_size) {
                if (!near) cs.push_back({rp(), sphere3{rp(), uni(0, 1)}});
                else {
                    const point3 c{small(), small(), small()};
                    const bool t = irand(0, 1) == 1;
                    const double k = irand(1, 4);
                    cs.push_back({np(c.x + k * (t ? 1 : 0), c.y + k * (t ? 2 : 3), c.z + k * (t ? 2 : 4)), sphere3{c, k * (t ? 3 : 5)}});
                }
            }
            auto truth = [](const ps& c) {
                double p[3], cc[3];
                arr(c.p, p); arr(c.s.center, cc);
                return oracle::point_in_ball(p, cc, c.s.radius);
            };
            tiers("point_sphere", dist, cs, truth, [](auto tier, const ps& c) { return intersects<decltype(tier)>(c.p, c.s); });
        }
        {
            struct bp { aabb3 b; point3 p; };
            std::vector<bp> cs;
            while (cs.size() < set_size) {
                const aabb3 b = box(rp(), rp());
                cs.push_back({b, near ? point3{b.max.x, b.min.y, (b.min.z + b.max.z) / 2} : rp()}); // on an edge when near
            }
            auto truth = [](const bp& c) {
                double p[3], mn[3], mx[3];
                arr(c.p, p); arr(c.b.min, mn); arr(c.b.max, mx);
                return oracle::point_in_box(p, mn, mx);
            };
            tiers("aabb_point", dist, cs, truth, [](auto tier, const bp& c) { return intersects<decltype(tier)>(c.b, c.p); });
        }
        {
            // segment x triangle: the ray sets, with the segment ending at origin + 1.5 direction
            struct st { segment3 s; triangle3 t; };
            std::vector<st> cs;
            for (const auto& c : ray_triangle_set(near)) cs.push_back({segment3{c.r.origin, c.r.at(near ? 1.0 : 1.5)}, c.t});
            auto truth = [](const st& c) {
                double p[3], q[3], a[3], b[3], cc[3];
                arr(c.s.a, p); arr(c.s.b, q); arr(c.t.a, a); arr(c.t.b, b); arr(c.t.c, cc);
                return oracle::segment_triangle(p, q, a, b, cc);
            };
            tiers("segment_triangle", dist, cs, truth, [](auto tier, const st& c) { return intersects<decltype(tier)>(c.s, c.t); });
        }
        {
            // triangle x triangle: the second triangle has the segment above as an edge (so on the
            // near set it ends on the first triangle's edge or vertex); CGAL needs both non-degenerate.
            struct tt { triangle3 p, q; };
            std::vector<tt> cs;
            for (const auto& c : ray_triangle_set(near)) {
                const triangle3 q{c.r.origin, c.r.at(near ? 1.0 : 1.5), c.r.origin + vec3{0.5, -0.25, 0.125}};
                double a[3], b[3], cc[3];
                arr(q.a, a); arr(q.b, b); arr(q.c, cc);
                if (!oracle::triangle_is_degenerate(a, b, cc)) cs.push_back({c.t, q});
            }
            auto truth = [](const tt& c) {
                double a[3], b[3], cc[3], d[3], e[3], f[3];
                arr(c.p.a, a); arr(c.p.b, b); arr(c.p.c, cc); arr(c.q.a, d); arr(c.q.b, e); arr(c.q.c, f);
                return oracle::triangle_triangle(a, b, cc, d, e, f);
            };
            tiers("triangle_triangle", dist, cs, truth, [](auto tier, const tt& c) { return intersects<decltype(tier)>(c.p, c.q); });
            std::vector<bool> t;
            for (const auto& c : cs) t.push_back(truth(c));
            reg("sat/intersects/triangle_triangle/" + dist, cs, t, check::approximate,
                [](const tt& c) { return method::triangle_triangle_sat(c.p, c.q); });
            reg("cgal_epick/intersects/triangle_triangle/" + dist, cs, t, check::approximate, [](const tt& c) {
                double a[3], b[3], cc[3], d[3], e[3], f[3];
                arr(c.p.a, a); arr(c.p.b, b); arr(c.p.c, cc); arr(c.q.a, d); arr(c.q.b, e); arr(c.q.c, f);
                return oracle::triangle_triangle_epick(a, b, cc, d, e, f);
            });
            reg("fcl/intersects/triangle_triangle/" + dist, cs, t, check::approximate, [](const tt& c) {
                double a[3], b[3], cc[3], d[3], e[3], f[3];
                arr(c.p.a, a); arr(c.p.b, b); arr(c.p.c, cc); arr(c.q.a, d); arr(c.q.b, e); arr(c.q.c, f);
                return fcl_peer::triangle_triangle(a, b, cc, d, e, f);
            });
        }
        {
            // box x triangle: near cases touch the unit box at its corner, along a face, or with
            // the triangle's plane through the corner; random cases are random boxes and triangles
            struct bt { aabb3 b; triangle3 t; };
            std::vector<bt> cs;
            while (cs.size() < set_size) {
                const point3 c{small(), small(), small()};
                const aabb3 b = near ? box(c, point3{c.x + 1, c.y + 1, c.z + 1}) : box(rp(), rp());
                const point3 m = b.max;
                triangle3 t{rp(), rp(), rp()};
                if (near) {
                    const int kind = int(cs.size() % 3);
                    const vec3 u{1 + 0.25 * double(cs.size() % 4), 0.5, 2}, w{0.5, 1.5, 1 + 0.125 * double(cs.size() % 5)};
                    if (kind == 0) t = {m, m + u, m + w};                                      // the corner
                    else if (kind == 1) t = {m + vec3{0.5, -0.5, 0}, m + vec3{-0.5, 0.5, 0}, m + u}; // across the top corner
                    else t = {m + vec3{2, -1, -1}, m + vec3{-1, 2, -1}, m + vec3{-1, -1, 2}}; // plane x+y+z through the corner
                }
                double a[3], bb3[3], cc[3];
                arr(t.a, a); arr(t.b, bb3); arr(t.c, cc);
                if (!oracle::triangle_is_degenerate(a, bb3, cc)) cs.push_back({b, t});
            }
            auto truth = [](const bt& c) {
                double mn[3], mx[3], a[3], b[3], cc[3];
                arr(c.b.min, mn); arr(c.b.max, mx); arr(c.t.a, a); arr(c.t.b, b); arr(c.t.c, cc);
                return oracle::box_triangle(mn, mx, a, b, cc);
            };
            tiers("aabb_triangle", dist, cs, truth, [](auto tier, const bt& c) { return intersects<decltype(tier)>(c.b, c.t); });
            std::vector<bool> t;
            for (const auto& c : cs) t.push_back(truth(c));
            reg("sign_algorithm_double/intersects/aabb_triangle/" + dist, cs, t, check::approximate, [](const bt& c) {
                arith::approx_kernel k;
                return pair::intersects(k, c.b, c.t);
            });
            reg("cgal_epick/intersects/aabb_triangle/" + dist, cs, t, check::approximate, [](const bt& c) {
                double mn[3], mx[3], a[3], b[3], cc[3];
                arr(c.b.min, mn); arr(c.b.max, mx); arr(c.t.a, a); arr(c.t.b, b); arr(c.t.c, cc);
                return oracle::box_triangle_epick(mn, mx, a, b, cc);
            });
        }
        {
            // box x segment and box x line: the ray cases, the segment ending at origin + direction
            struct bs { aabb3 b; segment3 s; line3 l; };
            std::vector<bs> cs;
            for (const auto& c : aabb_ray_set(near)) cs.push_back({c.b, segment3{c.r.origin, c.r.at(1.0)}, line3{c.r.origin, c.r.direction}});
            auto seg_truth = [](const bs& c) {
                double p[3], q[3], mn[3], mx[3];
                arr(c.s.a, p); arr(c.s.b, q); arr(c.b.min, mn); arr(c.b.max, mx);
                return oracle::box_segment(mn, mx, p, q);
            };
            auto line_truth = [](const bs& c) {
                double p[3], d[3], mn[3], mx[3];
                arr(c.l.origin, p); arr(c.l.direction, d); arr(c.b.min, mn); arr(c.b.max, mx);
                return oracle::box_line(mn, mx, p, d);
            };
            tiers("aabb_segment", dist, cs, seg_truth, [](auto tier, const bs& c) { return intersects<decltype(tier)>(c.b, c.s); });
            tiers("aabb_line", dist, cs, line_truth, [](auto tier, const bs& c) { return intersects<decltype(tier)>(c.b, c.l); });
            std::vector<bool> ts, tl;
            for (const auto& c : cs) ts.push_back(seg_truth(c)), tl.push_back(line_truth(c));
            reg("cgal_epick/intersects/aabb_segment/" + dist, cs, ts, check::approximate, [](const bs& c) {
                double p[3], q[3], mn[3], mx[3];
                arr(c.s.a, p); arr(c.s.b, q); arr(c.b.min, mn); arr(c.b.max, mx);
                return oracle::box_segment_epick(mn, mx, p, q);
            });
            reg("cgal_epick/intersects/aabb_line/" + dist, cs, tl, check::approximate, [](const bs& c) {
                double p[3], d[3], mn[3], mx[3];
                arr(c.l.origin, p); arr(c.l.direction, d); arr(c.b.min, mn); arr(c.b.max, mx);
                return oracle::box_line_epick(mn, mx, p, d);
            });
        }
        {
            // planes: through the box's extreme corner / a segment end / a triangle vertex when near
            struct pc { aabb3 b; segment3 s; triangle3 t; plane3 p; };
            std::vector<pc> cs;
            for (const auto& c : ray_triangle_set(near)) {
                const aabb3 bx = box(c.t.a, c.t.b);
                const vec3 n = near ? vec3{double(irand(-3, 3)), double(irand(-3, 3)), 1} : vec3{uni(-1, 1), uni(-1, 1), uni(-1, 1)};
                const point3 q = near ? c.t.a : rp();
                cs.push_back({bx, segment3{c.r.origin, c.t.a}, c.t, plane3{n, dot(n, q - point3{0, 0, 0})}});
            }
            auto n3 = [](const pc& c, double* n) { arr(c.p.normal, n); };
            auto tb = [&](const pc& c) { double mn[3], mx[3], n[3]; arr(c.b.min, mn); arr(c.b.max, mx); n3(c, n); return oracle::box_plane(mn, mx, n, c.p.offset); };
            auto ts = [&](const pc& c) { double a[3], q[3], n[3]; arr(c.s.a, a); arr(c.s.b, q); n3(c, n); return oracle::plane_segment(n, c.p.offset, a, q); };
            auto tt3 = [&](const pc& c) { double a[3], q[3], w[3], n[3]; arr(c.t.a, a); arr(c.t.b, q); arr(c.t.c, w); n3(c, n); return oracle::plane_triangle(n, c.p.offset, a, q, w); };
            tiers("aabb_plane", dist, cs, tb, [](auto tier, const pc& c) { return intersects<decltype(tier)>(c.b, c.p); });
            tiers("plane_segment", dist, cs, ts, [](auto tier, const pc& c) { return intersects<decltype(tier)>(c.p, c.s); });
            tiers("plane_triangle", dist, cs, tt3, [](auto tier, const pc& c) { return intersects<decltype(tier)>(c.p, c.t); });
            std::vector<bool> t1, t2, t3;
            for (const auto& c : cs) t1.push_back(tb(c)), t2.push_back(ts(c)), t3.push_back(tt3(c));
            reg("cgal_epick/intersects/aabb_plane/" + dist, cs, t1, check::approximate, [n3](const pc& c) {
                double mn[3], mx[3], n[3]; arr(c.b.min, mn); arr(c.b.max, mx); n3(c, n); return oracle::box_plane_epick(mn, mx, n, c.p.offset); });
            reg("cgal_epick/intersects/plane_segment/" + dist, cs, t2, check::approximate, [n3](const pc& c) {
                double a[3], q[3], n[3]; arr(c.s.a, a); arr(c.s.b, q); n3(c, n); return oracle::plane_segment_epick(n, c.p.offset, a, q); });
            reg("cgal_epick/intersects/plane_triangle/" + dist, cs, t3, check::approximate, [n3](const pc& c) {
                double a[3], q[3], w[3], n[3]; arr(c.t.a, a); arr(c.t.b, q); arr(c.t.c, w); n3(c, n); return oracle::plane_triangle_epick(n, c.p.offset, a, q, w); });
        }
        {
            const auto cs = aabb_aabb_set(near);
            auto truth = [](const bb& c) {
                double a0[3], a1[3], b0[3], b1[3];
                arr(c.a.min, a0); arr(c.a.max, a1); arr(c.b.min, b0); arr(c.b.max, b1);
                return oracle::box_box(a0, a1, b0, b1);
            };
            tiers("aabb_aabb", dist, cs, truth, [](auto tier, const bb& c) { return intersects<decltype(tier)>(c.a, c.b); });
        }
    }
}
} // namespace

int main(int argc, char** argv) {
    register_all();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
