// Benchmarks: contains(a, b) in every tier, on random pairs (mostly not contained, as in use) and on
// near-degenerate ones: b inside a, on its boundary from inside, or just beyond it (the tests'
// holding generators: tests/support/contain_cases.hpp, inside_case in flat_cases.hpp,
// kdop_inside_case, halfspace_inside_case), the tests' exact rational truth (contains_truth,
// flat_contains_truth, contained_truth by the LP; the mesh and polygon oracles for a mesh or a
// polygon around a segment or a triangle).
#include "bench.hpp"
#include <optional>
#include <stdexcept>
#include "testkit/contain_cases.hpp"
#include "testkit/generators.hpp"

namespace bench {
namespace {

// gen(rng, near) returns a pair or std::nullopt (a case the generator declined).
template <class A, class B, class Gen, class Truth>
[[gnu::noinline]] void contains_tiers(const std::string& pair, bool near, Gen gen, Truth truth) {
    support::rng r = set_rng(near);
    std::vector<std::pair<A, B>> cs;
    while (cs.size() < set_size)
        if (const std::optional<std::pair<A, B>> c = gen(r, near)) cs.push_back(*c);
    tiers(
        pair, near ? "near_degenerate" : "random", cs, [truth](const std::pair<A, B>& c) { return truth(c.first, c.second); },
        [](auto tier, const std::pair<A, B>& c) { return contains<decltype(tier)>(c.first, c.second); }, "contains");
}

// The boxes and the ball: the pair's random cases, or the holding generator.
template <class A, class B, class Random, class Holding>
void box_contains(const std::string& pair, bool near, Random random, Holding holding) {
    contains_tiers<A, B>(
        pair, near, [random, holding](support::rng& r, bool nr) { return std::optional{nr ? holding(r) : random(r)}; },
        [](const A& a, const B& b) { return support::contains_truth(a, b); });
}
template <class S>
void capsule_contains(const std::string& pair, bool near) {
    contains_tiers<capsule3, S>(
        pair, near,
        [](support::rng& r, bool nr) { return std::optional{nr ? support::capsule_holding<S>(r) : support::capsule_random_around<S>(r)}; },
        [](const capsule3& c, const S& s) { return support::capsule_holds(c, s); });
}
template <class X>
void capsule_contained(const std::string& pair, bool near) {
    contains_tiers<X, capsule3>(
        pair, near,
        [](support::rng& r, bool nr) { return std::optional{nr ? support::capsule_inside<X>(r) : support::capsule_random_in<X>(r)}; },
        [](const X& x, const capsule3& c) { return support::holds_capsule(x, c); });
}
template <class B>
void obb_contains(const std::string& pair, bool near) {
    box_contains<obb3, B>(
        pair, near, [](support::rng& r) { return support::obb_case<obb3, B>::random(r, false); }, support::obb_holding<B>);
}
// contains(polygon3, B) for B a segment or a triangle of points_in_polygon3 (a case the generator
// declines is drawn again).
template <class B, class Truth>
void polygon3_contains(const std::string& pair, bool near, Truth truth) {
    view_tiers<support::polygon3_store, B, true>(
        pair, near,
        [](support::rng& r, support::polygon3_store& g, support::polygon3_store&, bool nr) {
            for (;;)
                if (const auto p = support::points_in_polygon3(r, g, nr)) {
                    if constexpr (std::is_same_v<B, segment3>) return segment3{(*p)[0], (*p)[1]};
                    else return triangle3{(*p)[0], (*p)[1], (*p)[2]};
                }
        },
        truth);
}
// as the tests' random cases, at scale 1 like the other sets
std::pair<aabb3, sphere3> random_aabb_ball(support::rng& r) {
    const auto tr = support::random_transform(r, false, false);
    return {support::random_aabb(r, tr), support::random_ball(r, tr)};
}
std::pair<obb3, sphere3> random_obb_ball(support::rng& r) {
    const auto tr = support::random_transform(r, false, false);
    return {support::random_obb(r, tr), support::random_ball(r, tr)};
}
template <class A, class B>
void flat_contains(const std::string& pair, bool near) {
    contains_tiers<A, B>(
        pair, near,
        [](support::rng& r, bool nr) { return std::optional{nr ? support::inside_case<A, B>(r) : support::flat_random<A, B>(r, false)}; },
        [](const A& a, const B& b) { return support::flat_contains_truth(a, b); });
}
template <int K, class B>
void kdop_contains(const std::string& pair, bool near) {
    contains_tiers<kdop<K>, B>(
        pair + "_" + std::to_string(K), near,
        [](support::rng& r, bool nr) -> std::optional<std::pair<kdop<K>, B>> {
            const auto c = nr ? support::kdop_inside_case<K, B>(r) : support::kdop_random<K, B>(r);
            if (!c || !support::finite_shape(c->second)) return std::nullopt;
            return c;
        },
        [](const kdop<K>& a, const B& b) { return support::contained_truth(a, b); });
}
template <class P, class B>
void halfspace_contains(const std::string& pair, bool near) {
    contains_tiers<P, B>(
        pair, near,
        [](support::rng& r, bool nr) -> std::optional<std::pair<P, B>> {
            std::optional<std::pair<P, B>> c;
            if (!nr) c = support::halfspace_random<P, B>(r);
            else if constexpr (std::is_same_v<B, point3>) {
                if (const auto s = support::halfspace_inside_case<P>(r)) c = std::pair{s->first, s->second.b};
            } else c = support::halfspace_inside_case<P, B>(r);
            if (!c || !support::finite_shape(c->second)) return std::nullopt;
            return c;
        },
        [](const P& a, const B& b) { return support::contained_truth(a, b); });
}

// contains(P, ball) on testkit/ball_halfspace_cases.hpp's cases, the ball in every row (rationals) as truth.
template <class P>
void ball_contains(const std::string& pair, bool near) {
    contains_tiers<P, sphere3>(
        pair, near, [](support::rng& r, bool nr) { return nr ? support::ball_near<P>(r) : support::ball_random<P>(r); },
        [](const P& a, const sphere3& s) { return oracle::ball_in_rows(support::lp(a), support::a3(s.center), s.radius); });
}

// contains(a, b) on the audit's cases of the pair (A, B) or (B, A) (testkit/generators.hpp): random
// at separation 2^0 (b moved by the objects' size from touching), near-degenerate at 1 ulp. The
// truth is the exact tier, checked against the oracle by the pair's test.
template <class A, class B>
void audit_contains(const std::string& pair, bool near) {
    constexpr bool swapped = !requires(audit::rng& r) { audit::near_boundary<A, B>::touching(r); };
    audit::rng r(near ? 7 : 3);
    std::vector<std::pair<A, B>> cs;
    while (cs.size() < set_size) {
        const int level = near ? audit::separation_levels + 1 : 0;
        if constexpr (swapped) {
            const auto [b, a] = audit::make_case<B, A>(r, level, audit::settings[0]);
            cs.emplace_back(a, b);
        } else {
            cs.push_back(audit::make_case<A, B>(r, level, audit::settings[0]));
        }
    }
    tiers(
        pair, near ? "near_degenerate" : "random", cs, [](const std::pair<A, B>& c) { return contains<exact>(c.first, c.second); },
        [](auto tier, const std::pair<A, B>& c) { return contains<decltype(tier)>(c.first, c.second); }, "contains");
}
// contains(a view, a point): the intersects cases of the pair, the oracle as truth.

} // namespace

void register_contains(bool near) {
    audit_contains<aabb3, aabb3>("aabb_aabb", near);
    audit_contains<aabb3, point3>("aabb_point", near);
    audit_contains<aabb3, segment3>("aabb_segment", near);
    audit_contains<aabb3, triangle3>("aabb_triangle", near);
    audit_contains<obb3, aabb3>("obb_aabb", near);
    audit_contains<sphere3, point3>("sphere_point", near);
    audit_contains<sphere3, sphere3>("sphere_sphere", near);
    audit_contains<kdop<14>, obb3>("kdop_obb_14", near);
    audit_contains<kdop<14>, point3>("kdop_point_14", near);
    audit_contains<kdop<14>, segment3>("kdop_segment_14", near);
    audit_contains<convex_polyhedron3, aabb3>("convex_polyhedron_aabb", near);
    audit_contains<convex_polyhedron3, obb3>("convex_polyhedron_obb", near);
    audit_contains<convex_polyhedron3, point3>("convex_polyhedron_point", near);
    audit_contains<convex_polyhedron3, triangle3>("convex_polyhedron_triangle", near);
    audit_contains<frustum3, aabb3>("frustum_aabb", near);
    audit_contains<frustum3, obb3>("frustum_obb", near);
    audit_contains<frustum3, segment3>("frustum_segment", near);
    audit_contains<frustum3, tetrahedron3>("frustum_tetrahedron", near);
    view_tiers<support::mesh_store, point3, true>(
        "mesh_point", near,
        [](support::rng& r, support::mesh_store& m, support::mesh_store& o, bool nr) {
            return nr ? support::mesh_near<point3>(r, m, o) : support::mesh_random<point3>(r, m, o);
        },
        [](const mesh3& m, const point3& p) { return support::mesh_truth(m, p); });
    view_tiers<support::polygon_store, point2, true>(
        "polygon2_point2", near,
        [](support::rng& r, support::polygon_store& g, support::polygon_store& o, bool nr) {
            return nr ? support::polygon_near<point2>(r, g, o) : support::polygon_random<point2>(r, g, o);
        },
        [](const polygon2& g, const point2& p) { return support::polygon_truth(g, p); });
    view_tiers<support::polygon3_store, point3, true>(
        "polygon_point", near,
        [](support::rng& r, support::polygon3_store& g, support::polygon3_store& o, bool nr) {
            support::mesh_store unused;
            for (;;)
                if (const auto p = nr ? support::polygon3_near<point3>(r, g, o, unused) : support::polygon3_random<point3>(r, g, o, unused);
                    p && support::finite_partner(*p))
                    return *p;
        },
        [](const polygon3& g, const point3& p) { return support::polygon3_truth(g, p); });
    obb_contains<point3>("obb_point", near);
    obb_contains<segment3>("obb_segment", near);
    obb_contains<triangle3>("obb_triangle", near);
    obb_contains<tetrahedron3>("obb_tetrahedron", near);
    obb_contains<obb3>("obb_obb", near);
    box_contains<aabb3, obb3>(
        "aabb_obb", near, [](support::rng& r) { return support::obb_case<aabb3, obb3>::random(r, false); }, support::aabb_holding_obb);
    box_contains<obb3, sphere3>("obb_sphere", near, random_obb_ball, support::obb_holding_ball);
    box_contains<sphere3, obb3>(
        "sphere_obb", near,
        [](support::rng& r) {
            const auto [b, s] = random_obb_ball(r);
            return std::pair{s, b};
        },
        support::ball_holding_obb);
    box_contains<aabb3, sphere3>("aabb_sphere", near, random_aabb_ball, support::aabb_holding_ball);
    box_contains<sphere3, aabb3>(
        "sphere_aabb", near,
        [](support::rng& r) {
            const auto [b, s] = random_aabb_ball(r);
            return std::pair{s, b};
        },
        support::ball_holding_aabb);
    box_contains<tetrahedron3, obb3>(
        "tetrahedron_obb", near,
        [](support::rng& r) {
            const auto [b, t] = support::obb_case<obb3, tetrahedron3>::random(r, false);
            return std::pair{t, b};
        },
        support::tetrahedron_holding_obb);
    flat_contains<tetrahedron3, point3>("tetrahedron_point", near);
    flat_contains<tetrahedron3, segment3>("tetrahedron_segment", near);
    flat_contains<tetrahedron3, triangle3>("tetrahedron_triangle", near);
    flat_contains<tetrahedron3, tetrahedron3>("tetrahedron_tetrahedron", near);
    flat_contains<tetrahedron3, aabb3>("tetrahedron_aabb", near);
    flat_contains<aabb3, tetrahedron3>("aabb_tetrahedron", near);
    kdop_contains<14, aabb3>("kdop_aabb", near);
    kdop_contains<14, triangle3>("kdop_triangle", near);
    kdop_contains<26, tetrahedron3>("kdop_tetrahedron", near);
    halfspace_contains<frustum3, point3>("frustum_point", near);
    ball_contains<frustum3>("frustum_sphere", near);
    // the ball around a segment, a triangle, a tetrahedron; the capsule around them, a box, a ball
    // and a capsule; a box, a ball, a capsule and the half-space sets around a capsule
    // (testkit/capsule_cases.hpp)
    box_contains<sphere3, segment3>("sphere_segment", near, support::sphere_random_around<segment3>, support::sphere_holding<segment3>);
    box_contains<sphere3, triangle3>("sphere_triangle", near, support::sphere_random_around<triangle3>, support::sphere_holding<triangle3>);
    box_contains<sphere3, tetrahedron3>("sphere_tetrahedron", near, support::sphere_random_around<tetrahedron3>,
                                        support::sphere_holding<tetrahedron3>);
    capsule_contains<point3>("capsule_point", near);
    capsule_contains<segment3>("capsule_segment", near);
    capsule_contains<triangle3>("capsule_triangle", near);
    capsule_contains<tetrahedron3>("capsule_tetrahedron", near);
    capsule_contains<aabb3>("capsule_aabb", near);
    capsule_contains<obb3>("capsule_obb", near);
    capsule_contains<sphere3>("capsule_sphere", near);
    capsule_contains<capsule3>("capsule_capsule", near);
    capsule_contained<aabb3>("aabb_capsule", near);
    capsule_contained<obb3>("obb_capsule", near);
    capsule_contained<sphere3>("sphere_capsule", near);
    capsule_contained<convex_polyhedron3>("convex_polyhedron_capsule", near);
    capsule_contained<frustum3>("frustum_capsule", near);
    capsule_contained<kdop<14>>("kdop_capsule_14", near);
    ball_contains<convex_polyhedron3>("convex_polyhedron_sphere", near);
    ball_contains<kdop<14>>("kdop_sphere_14", near);
    halfspace_contains<frustum3, triangle3>("frustum_triangle", near);
    halfspace_contains<convex_polyhedron3, segment3>("convex_polyhedron_segment", near);
    halfspace_contains<convex_polyhedron3, tetrahedron3>("convex_polyhedron_tetrahedron", near);
    // the mesh around a segment: tests/support/mesh_cases.hpp's segment_in_mesh_{random,near}, the
    // mesh oracle's exact breakpoints and midpoints as truth (a case it declines is drawn again)
    view_tiers<support::mesh_store, segment3, true>(
        "mesh_segment", near,
        [](support::rng& r, support::mesh_store& m, support::mesh_store&, bool nr) {
            for (;;) {
                const segment3 s = nr ? support::segment_in_mesh_near(r, m) : support::segment_in_mesh_random(r, m);
                try {
                    (void)support::segment_in_mesh_truth(m.view(), s);
                    return s;
                } catch (const std::runtime_error&) {}
            }
        },
        [](const mesh3& m, const segment3& s) { return support::segment_in_mesh_truth(m, s); });
    // the mesh around a triangle: triangle_in_mesh_{random,near}, the oracle's chords as truth
    view_tiers<support::mesh_store, triangle3, true>(
        "mesh_triangle", near,
        [](support::rng& r, support::mesh_store& m, support::mesh_store&, bool nr) {
            for (;;) {
                const triangle3 t = nr ? support::triangle_in_mesh_near(r, m) : support::triangle_in_mesh_random(r, m);
                try {
                    (void)support::triangle_in_mesh_truth(m.view(), t);
                    return t;
                } catch (const std::runtime_error&) {}
            }
        },
        [](const mesh3& m, const triangle3& t) { return support::triangle_in_mesh_truth(m, t); });
    // the mesh around a box: box_in_mesh_{random,near}, the box oracle's cells of each plane as truth
    view_tiers<support::mesh_store, aabb3, true>(
        "mesh_aabb", near,
        [](support::rng& r, support::mesh_store& m, support::mesh_store&, bool nr) {
            for (;;) {
                const aabb3 b = nr ? support::box_in_mesh_near(r, m) : support::box_in_mesh_random(r, m);
                try {
                    (void)support::box_in_mesh_truth(m.view(), b);
                    return b;
                } catch (const std::runtime_error&) {}
            }
        },
        [](const mesh3& m, const aabb3& b) { return support::box_in_mesh_truth(m, b); });
    // the polygon around a segment (2D and 3D) or a triangle (3D): polygon_cases.hpp's
    // segment_in_polygon_{random,near}, polygon3_cases.hpp's points_in_polygon3, the polygon
    // oracles' exact breakpoints and clipped areas as truth
    view_tiers<support::polygon_store, segment2, true>(
        "polygon2_segment2", near,
        [](support::rng& r, support::polygon_store& g, support::polygon_store&, bool nr) {
            return nr ? support::segment_in_polygon_near(r, g) : support::segment_in_polygon_random(r, g);
        },
        [](const polygon2& g, const segment2& s) { return support::segment_in_polygon_truth(g, s); });
    polygon3_contains<segment3>("polygon_segment", near,
                                [](const polygon3& g, const segment3& s) { return support::segment_in_polygon3_truth(g, s); });
    polygon3_contains<triangle3>("polygon_triangle", near,
                                 [](const polygon3& g, const triangle3& t) { return support::triangle_in_polygon3_truth(g, t); });
}
} // namespace bench
