// The shared part of the benchmarks (bench/*.cpp): the case sets, the answer check before timing
// (reg), and one registration helper per pair family. Every benchmark is named
// tier/query/pair/distribution, with CGAL Epick and Epeck on the same inputs where CGAL has the
// query. Before timing, each benchmark checks its answers against the oracle on the whole input set:
// the exact tier, conservative, aggressive and classify must keep their promises (SkipWithError
// otherwise); approximate methods report their wrong answers as the counter `wrong_pct`.
#pragma once
#include <benchmark/benchmark.h>
#include "testkit/oracle/cgal_oracle.hpp"
#include "fcl_peer.hpp"
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <functional>
#include <random>
#include <string>
#include <vector>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/flat_cases.hpp"
#include "testkit/mesh_cases.hpp"
#include "testkit/polygon_cases.hpp"
#include "testkit/kdop_cases.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/polyhedron_cases.hpp"
#include "testkit/polygon3_cases.hpp"
#include "testkit/ball_halfspace_cases.hpp"
#include "testkit/capsule_cases.hpp"
#include "testkit/ball_view_cases.hpp"

using namespace incidence;

namespace bench {
// Cases per set: 1024, or INCIDENCE_BENCH_CASES (the smoke test in ctest uses a few, since the
// answer check computes the exact truth of every case before timing).
inline const std::size_t set_size = [] {
    const char* v = std::getenv("INCIDENCE_BENCH_CASES");
    const long n = v != nullptr ? std::atol(v) : 0;
    return n > 0 ? static_cast<std::size_t>(n) : std::size_t{1024};
}();
inline std::mt19937_64 gen(20261122);
inline double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
inline int irand(int a, int b) { return std::uniform_int_distribution<int>(a, b)(gen); }
inline double small() { return irand(-16, 16) + irand(0, 3) * 0.25; }
inline double nudge(double x) {
    const int k = irand(-2, 2);
    for (int i = 0; i < k; ++i) x = std::nextafter(x, INFINITY);
    for (int i = 0; i > k; --i) x = std::nextafter(x, -INFINITY);
    return x;
}
inline point3 rp() { return {uni(-1, 1), uni(-1, 1), uni(-1, 1)}; }
inline aabb3 box(point3 a, point3 b) { // the box spanned by two corners in any order
    return {{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}, {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
}
inline point3 np(double x, double y, double z) { return {nudge(x), nudge(y), nudge(z)}; }
inline void arr(point3 p, double* o) {
    o[0] = p.x;
    o[1] = p.y;
    o[2] = p.z;
}
inline void arr(vec3 p, double* o) {
    o[0] = p.x;
    o[1] = p.y;
    o[2] = p.z;
}

// The seeded source of one case set. Every set is at scale 1 near the origin (the tests cover
// 2^-500..2^500 and far translations), so that sets of different families measure the same thing.
inline support::rng set_rng(bool near) {
    support::rng r(20261122 + (near ? 1 : 0));
    r.at_scale_one = true;
    return r;
}

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

struct rt {
    ray3 r;
    triangle3 t;
};
struct ab {
    aabb3 b;
    ray3 r;
};
struct o3 {
    point3 a, b, c, d;
};
struct rs {
    ray3 r;
    sphere3 s;
};
struct ss {
    sphere3 a, b;
};
struct bb {
    aabb3 a, b;
};

inline std::vector<rt> ray_triangle_set(bool near) {
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
        arr(v.back().t.a, a_);
        arr(v.back().t.b, b_);
        arr(v.back().t.c, c_);
        if (oracle::triangle_is_degenerate(a_, b_, c_) || v.back().r.direction == vec3{0, 0, 0}) v.pop_back();
    }
    return v;
}
inline std::vector<ab> aabb_ray_set(bool near) {
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
            if (v.back().b.min.x > v.back().b.max.x || v.back().b.min.y > v.back().b.max.y || v.back().b.min.z > v.back().b.max.z)
                v.pop_back();
        }
        if (!v.empty() && v.back().r.direction == vec3{0, 0, 0}) v.pop_back();
    }
    return v;
}
inline std::vector<o3> orient3d_set(bool near) {
    std::vector<o3> v;
    while (v.size() < set_size) {
        if (!near) {
            v.push_back({rp(), rp(), rp(), rp()});
        } else { // coplanar by construction, then nudged
            const point3 a{small(), small(), small()}, b{small(), small(), small()}, c{small(), small(), small()};
            const double s = irand(-4, 4) * 0.5, t = irand(-4, 4) * 0.5;
            const point3 d{a.x + s * (b.x - a.x) + t * (c.x - a.x), a.y + s * (b.y - a.y) + t * (c.y - a.y),
                           a.z + s * (b.z - a.z) + t * (c.z - a.z)};
            v.push_back({np(a.x * 0.1, a.y * 0.1, a.z * 0.1), np(b.x * 0.1, b.y * 0.1, b.z * 0.1), np(c.x * 0.1, c.y * 0.1, c.z * 0.1),
                         np(d.x * 0.1, d.y * 0.1, d.z * 0.1)});
        }
    }
    return v;
}
inline std::vector<rs> ray_sphere_set(bool near) {
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
inline std::vector<ss> sphere_sphere_set(bool near) {
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
inline std::vector<bb> aabb_aabb_set(bool near) {
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

// The registering functions below are not inlined: each bench file calls many of them once, and
// inlined they made one function per file that took most of its compile time. The timed loops
// are the registered lambdas, not these.
// query: "intersects" or "contains" (the name's second part).
template <class Case, class Truth, class Tiered>
[[gnu::noinline]] void tiers(const std::string& pair, const std::string& dist, const std::vector<Case>& cs, Truth truth_of, Tiered f,
                             const std::string& query = "intersects") {
    std::vector<bool> truth;
    for (const auto& c : cs) truth.push_back(truth_of(c));
    const std::string tail = "/" + query + "/" + pair + "/" + dist;
    reg("exact" + tail, cs, truth, check::exact, [f](const Case& c) { return f(exact{}, c); });
    reg("conservative" + tail, cs, truth, check::conservative, [f](const Case& c) { return f(conservative{}, c); });
    reg("aggressive" + tail, cs, truth, check::aggressive, [f](const Case& c) { return f(aggressive{}, c); });
    reg("approximate" + tail, cs, truth, check::approximate, [f](const Case& c) { return f(approximate{}, c); });
}

// An OBB pair on the tests' generators (tests/support/obb_cases.hpp), the LP oracle as truth.
template <class A, class B>
[[gnu::noinline]] std::vector<std::pair<A, B>> obb_tiers(const std::string& pair, bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r = set_rng(near);
    std::vector<std::pair<A, B>> cs;
    // at scale 1, like the other sets (the tests add scales 2^-500 .. 2^500)
    while (cs.size() < set_size) cs.push_back(near ? support::obb_case<A, B>::near(r, false) : support::obb_case<A, B>::random(r, false));
    auto truth = [](const std::pair<A, B>& c) { return oracle::lp_intersect(support::lp(c.first), support::lp(c.second)); };
    tiers(pair, dist, cs, truth, [](auto tier, const std::pair<A, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
    return cs;
}
// A flat pair (points, lines, rays, segments, planes, triangles) on the tests' generators
// (tests/support/flat_cases.hpp) at scale 1, CGAL Epeck as truth, and CGAL Epick's do_intersect.
// Three sets: random (coordinates in [-1, 1]^3, general position), in_plane (every shape in one
// plane z = c: exactly coplanar, the tests' other half of random cases) and near_degenerate.
template <class A, class B>
[[gnu::noinline]] void flat_set(const std::string& pair, const std::string& dist, support::rng& r, bool near, bool in_plane) {
    std::vector<std::pair<A, B>> cs;
    while (cs.size() < set_size) cs.push_back(near ? support::flat_near<A, B>(r, false) : support::flat_random<A, B>(r, false, in_plane));
    auto truth = [](const std::pair<A, B>& c) { return support::flat_truth(c.first, c.second); };
    tiers(pair, dist, cs, truth, [](auto tier, const std::pair<A, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
    std::vector<bool> t;
    for (const auto& c : cs) t.push_back(truth(c));
    reg("cgal_epick/intersects/" + pair + "/" + dist, cs, t, check::approximate,
        [](const std::pair<A, B>& c) { return oracle::flat_intersect_epick(support::to_flat(c.first), support::to_flat(c.second)); });
}
template <class A, class B>
void flat_tiers(const std::string& pair, bool near) {
    support::rng r = set_rng(near);
    if (near) return flat_set<A, B>(pair, "near_degenerate", r, true, false);
    flat_set<A, B>(pair, "random", r, false, false);
    if constexpr (!support::flat2_shape<A>) flat_set<A, B>(pair, "in_plane", r, false, true);
}
// A pair of a mesh or a polygon (a view of arrays a store owns) on the tests' generators, its
// oracle as truth: make_case(rng, store, other, near) returns the partner (for a view, other's view).
// Contains: contains(store's view, partner) instead of intersects.
template <class Store, class B, bool Contains = false, class Gen, class Truth>
[[gnu::noinline]] void view_tiers(const std::string& pair, bool near, Gen make_case, Truth truth_of) {
    struct view_case {
        Store m, other;
        B b{};
        B partner() const {
            if constexpr (std::is_same_v<B, decltype(Store{}.view())>) return other.view();
            else return b;
        }
    };
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r = set_rng(near);
    std::vector<view_case> cs;
    while (cs.size() < set_size) {
        view_case c;
        c.b = make_case(r, c.m, c.other, near);
        cs.push_back(std::move(c));
    }
    auto truth = [&](const view_case& c) { return truth_of(c.m.view(), c.partner()); };
    tiers(
        pair, dist, cs, truth,
        [](auto tier, const view_case& c) {
            if constexpr (Contains) return contains<decltype(tier)>(c.m.view(), c.partner());
            else return intersects<decltype(tier)>(c.m.view(), c.partner());
        },
        Contains ? "contains" : "intersects");
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
// A 3D polygon pair (tests/support/polygon3_cases.hpp: exactly planar star polygons of 8 to 24
// vertices in space, half with a hole of 8, at every scale the tests use), the triangulation
// oracle as truth. (The mesh partner, a view of a third store: mesh_polygon3_tiers.)
template <class B>
void polygon3_tiers(const std::string& pair, bool near) {
    view_tiers<support::polygon3_store, B>(
        pair, near,
        [](support::rng& r, support::polygon3_store& g, support::polygon3_store& o, bool nr) {
            support::mesh_store unused;
            for (;;) {
                const auto b = nr ? support::polygon3_near<B>(r, g, o, unused) : support::polygon3_random<B>(r, g, o, unused);
                if (b && support::finite_partner(*b)) return *b;
            }
        },
        [](const polygon3& g, const B& b) { return support::polygon3_truth(g, b); });
}
// mesh3 x polygon3 on the same generators (the mesh: tests/support/mesh_cases.hpp), the
// triangulation against the mesh oracle as truth.
[[gnu::noinline]] inline void mesh_polygon3_tiers(const std::string& pair, bool near) {
    struct stores {
        support::polygon3_store g, unused;
        support::mesh_store m;
    };
    support::rng r = set_rng(near);
    std::vector<stores> cs;
    while (cs.size() < set_size) {
        stores c;
        const auto b = near ? support::polygon3_near<mesh3>(r, c.g, c.unused, c.m) : support::polygon3_random<mesh3>(r, c.g, c.unused, c.m);
        if (b) cs.push_back(std::move(c)); // the views are taken again from the moved stores
    }
    auto truth = [](const stores& c) { return support::polygon3_truth(c.g.view(), c.m.view()); };
    tiers(pair, near ? "near_degenerate" : "random", cs, truth,
          [](auto tier, const stores& c) { return intersects<decltype(tier)>(c.m.view(), c.g.view()); });
}
// A k-DOP pair (tests/support/kdop_cases.hpp: the k-DOP of a few points, at every scale the
// tests use), the LP oracle as truth.
template <int K, class B>
[[gnu::noinline]] void kdop_tiers(const std::string& pair, bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r = set_rng(near);
    std::vector<std::pair<kdop<K>, B>> cs;
    while (cs.size() < set_size)
        if (const auto c = near ? support::kdop_near<K, B>(r) : support::kdop_random<K, B>(r)) cs.push_back(*c);
    auto truth = [](const std::pair<kdop<K>, B>& c) { return oracle::lp_intersect(support::lp(c.first), support::lp(c.second)); };
    tiers(pair + "_" + std::to_string(K), dist, cs, truth,
          [](auto tier, const std::pair<kdop<K>, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
}
// A half-space pair (tests/support/polyhedron_cases.hpp: supporting half-spaces of a cloud, or a
// camera frustum; near-degenerate: integer normals through boundary points), the LP as truth.
template <class P, class B>
[[gnu::noinline]] std::vector<std::pair<P, B>> halfspace_tiers(const std::string& pair, bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r = set_rng(near);
    std::vector<std::pair<P, B>> cs;
    while (cs.size() < set_size)
        if (const auto c = near ? support::halfspace_near<P, B>(r) : support::halfspace_random<P, B>(r)) cs.push_back(*c);
    auto truth = [](const std::pair<P, B>& c) { return oracle::lp_intersect(support::lp(c.first), support::lp(c.second)); };
    tiers(pair, dist, cs, truth, [](auto tier, const std::pair<P, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
    return cs;
}
// A ball against a half-space set (testkit/ball_halfspace_cases.hpp: a ball tangent at a face, an
// edge or a vertex, or random), the exact QP as truth (a case it declines is drawn again).
template <class P>
[[gnu::noinline]] std::vector<std::pair<P, sphere3>> ball_tiers(const std::string& pair, bool near) {
    support::rng r = set_rng(near);
    std::vector<std::pair<P, sphere3>> cs;
    std::vector<bool> truth;
    while (cs.size() < set_size)
        if (const auto c = near ? support::ball_near<P>(r) : support::ball_random<P>(r))
            if (const auto t = oracle::qp_ball_meets(support::lp(c->first), support::a3(c->second.center), c->second.radius))
                cs.push_back(*c), truth.push_back(*t);
    std::size_t i = 0; // the truths in the order tiers() asks for them
    tiers(
        pair, near ? "near_degenerate" : "random", cs, [&](const std::pair<P, sphere3>&) { return bool(truth[i++]); },
        [](auto tier, const std::pair<P, sphere3>& c) { return intersects<decltype(tier)>(c.first, c.second); });
    return cs;
}
// A ball against a flat shape or a tetrahedron, as ball_tiers, and CGAL Epick's do_intersect(Sphere_3, X).
template <class S>
void ball_flat_tiers(const std::string& pair, bool near) {
    const auto cs = ball_tiers<S>(pair, near);
    std::vector<bool> t;
    for (const auto& c : cs) t.push_back(intersects(c.first, c.second)); // the exact tier, checked against the QP in ball_tiers
    reg("cgal_epick/intersects/" + pair + "/" + (near ? "near_degenerate" : "random"), cs, t, check::approximate,
        [](const std::pair<S, sphere3>& c) {
            return oracle::ball_flat_epick(support::to_flat(c.first), support::a3(c.second.center), c.second.radius);
        });
}
// A capsule against a partner (testkit/capsule_cases.hpp: grown from a touching ball, or random),
// the exact QP between the cores as truth (a case it declines is drawn again).
template <class B>
struct capsule_set {
    std::vector<std::pair<capsule3, B>> cases;
    std::vector<bool> truth;
};
template <class B>
[[gnu::noinline]] capsule_set<B> capsule_tiers(const std::string& pair, bool near) {
    support::rng r = set_rng(near);
    std::vector<std::pair<capsule3, B>> cs;
    std::vector<bool> truth;
    while (cs.size() < set_size)
        if (const auto c = near ? support::capsule_near<B>(r) : support::capsule_random<B>(r)) {
            const auto [core, rb] = support::core_of(c->second);
            if (const auto t = oracle::qp_sets_within(support::lp(segment3{c->first.a, c->first.b}), core, c->first.radius, rb))
                cs.push_back(*c), truth.push_back(*t);
        }
    std::size_t i = 0; // the truths in the order tiers() asks for them
    tiers(
        pair, near ? "near_degenerate" : "random", cs, [&](const std::pair<capsule3, B>&) { return bool(truth[i++]); },
        [](auto tier, const std::pair<capsule3, B>& c) { return intersects<decltype(tier)>(c.first, c.second); });
    return {cs, truth};
}
// A ball or a capsule against a polygon or a solid mesh (testkit/ball_view_cases.hpp: touching star
// polygons with holes or closed star meshes, or random), ball_view_truth.hpp's oracle as truth (a
// case it declines is drawn again).
template <class V, class Round>
[[gnu::noinline]] void round_view_tiers(const std::string& pair, bool near) {
    struct stored {
        support::view_store s;
        Round x;
        [[nodiscard]] V view() const {
            if constexpr (std::is_same_v<V, polygon3>) return s.polygon.view();
            else return s.mesh.view();
        }
    };
    support::rng r = set_rng(near);
    std::vector<stored> cs;
    std::vector<bool> truth;
    while (cs.size() < set_size) {
        stored c;
        std::optional<Round> x;
        if constexpr (std::is_same_v<V, polygon3>)
            x = near ? support::round_near_polygon<Round>(r, c.s) : support::round_random_polygon<Round>(r, c.s);
        else x = near ? support::round_near_mesh<Round>(r, c.s) : support::round_random_mesh<Round>(r, c.s);
        if (!x) continue;
        c.x = *x;
        std::optional<bool> t;
        if constexpr (std::is_same_v<V, polygon3>) t = support::round_polygon_truth(c.view(), c.x);
        else t = support::round_mesh_truth(c.view(), c.x);
        if (t) cs.push_back(std::move(c)), truth.push_back(*t); // the views are taken again from the moved stores
    }
    std::size_t i = 0; // the truths in the order tiers() asks for them
    tiers(
        pair, near ? "near_degenerate" : "random", cs, [&](const stored&) { return bool(truth[i++]); },
        [](auto tier, const stored& c) { return intersects<decltype(tier)>(c.view(), c.x); });
}
inline void obb_arrays(const obb3& b, double* c, double* a, double* h) {
    arr(b.center, c);
    for (unsigned i = 0; i < 3; ++i) arr(b.axes[i], a + 3 * i), h[i] = b.half_extents[i];
}

} // namespace bench
