// Benchmarks of intersection(): every linear object (ray, segment, line) against every set, on the
// random and near-degenerate cases of the pair's tests at scale 1, in the exact, conservative and
// approximate tiers, and the exact yes/no answer on the same cases (exact/intersection_yes_no/...):
// the ratio of the two exact times is what a value costs beside the answer. Before timing, the
// exact tier's hits are checked against the exact yes/no answer of the oracle. Each timed call
// returns the whole hit, so its values are computed, not optimised away.
#include "bench.hpp"
#include "testkit/box_linear_cases.hpp"
#include "testkit/mesh_cases.hpp"
#include "testkit/polygon3_cases.hpp"
#include "value_floor.hpp"

namespace bench {
namespace {

template <class S, class X>
struct sx {
    S s;
    X x;
};

template <class S, class X>
void values(const std::string& pair, const std::string& dist, const std::vector<sx<S, X>>& cs) {
    std::vector<bool> truth; // the exact tier, checked against the oracle in the tests
    for (const auto& c : cs) truth.push_back(intersection<exact>(c.s, c.x).has_value());
    if constexpr (has_pair<S, X>)
        reg("exact/intersection_yes_no/" + pair + "/" + dist, cs, truth, check::exact,
            [](const sx<S, X>& c) { return intersects<exact>(c.s, c.x); });
    reg("exact/intersection/" + pair + "/" + dist, cs, truth, check::exact,
        [](const sx<S, X>& c) { return intersection<exact>(c.s, c.x); });
    reg("conservative/intersection/" + pair + "/" + dist, cs, truth, check::conservative,
        [](const sx<S, X>& c) { return intersection<conservative>(c.s, c.x); });
    reg("approximate/intersection/" + pair + "/" + dist, cs, truth, check::approximate,
        [](const sx<S, X>& c) { return intersection<approximate>(c.s, c.x); });
    if constexpr (value_floor::has_floor<S, X>) { // value_floor.hpp: what correct rounding cannot go below
        reg("floor/intersection/" + pair + "/" + dist, cs, truth, check::approximate,
            [](const sx<S, X>& c) { return value_floor::with_dekker(c.s, c.x); });
        if (__builtin_cpu_supports("fma"))
            reg("floor_fma/intersection/" + pair + "/" + dist, cs, truth, check::approximate,
                [](const sx<S, X>& c) { return value_floor::with_fma(c.s, c.x); });
    }
}

template <class X>
const char* linear_name() {
    if constexpr (std::is_same_v<X, ray3>) return "ray";
    else if constexpr (std::is_same_v<X, segment3>) return "segment";
    else return "line";
}
// The pair's name: the two shape names in lexicographic order.
inline std::string pair_name(const std::string& a, const std::string& b) { return a < b ? a + "_" + b : b + "_" + a; }

template <class S, class X, class Gen>
std::vector<sx<S, X>> collect(Gen gen) {
    std::vector<sx<S, X>> v;
    for (int guard = 0; v.size() < set_size && guard < 100000; ++guard)
        if (const auto c = gen()) v.push_back(*c);
    return v;
}
template <class S, class X, class P>
std::optional<sx<S, X>> of_pair(const P& p) {
    if constexpr (std::is_same_v<typename P::first_type, S>) return sx<S, X>{p.first, p.second};
    else return sx<S, X>{p.second, p.first};
}

template <class X>
void register_linear(bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    const std::string lin = linear_name<X>();
    {
        support::rng r = set_rng(near);
        values(pair_name("aabb", lin), dist, collect<aabb3, X>([&]() -> std::optional<sx<aabb3, X>> {
                   const auto c = near ? support::box_linear_near(r) : support::box_linear_random(r);
                   if constexpr (std::is_same_v<X, segment3>) return sx<aabb3, X>{c.box, {c.point(0), c.point(1)}};
                   else return sx<aabb3, X>{c.box, {c.point(0), c.direction()}};
               }));
    }
    {
        support::rng r = set_rng(near);
        values(pair_name("plane", lin), dist, collect<plane3, X>([&] {
                   if constexpr (std::is_same_v<X, line3>)
                       return of_pair<plane3, X>(near ? support::flat_near<line3, plane3>(r) : support::flat_random<line3, plane3>(r));
                   else return of_pair<plane3, X>(near ? support::flat_near<plane3, X>(r) : support::flat_random<plane3, X>(r));
               }));
    }
    {
        support::rng r = set_rng(near);
        values(pair_name("triangle", lin), dist, collect<triangle3, X>([&] {
                   return of_pair<triangle3, X>(near ? support::flat_near<X, triangle3>(r) : support::flat_random<X, triangle3>(r));
               }));
    }
    {
        support::rng r = set_rng(near);
        values(pair_name("tetrahedron", lin), dist, collect<tetrahedron3, X>([&] {
                   return of_pair<tetrahedron3, X>(near ? support::flat_near<X, tetrahedron3>(r)
                                                        : support::flat_random<X, tetrahedron3>(r));
               }));
    }
    {
        support::rng r = set_rng(near);
        values(pair_name("obb", lin), dist, collect<obb3, X>([&] {
                   if constexpr (std::is_same_v<X, line3>)
                       return of_pair<obb3, X>(near ? support::obb_case<line3, obb3>::near(r) : support::obb_case<line3, obb3>::random(r));
                   else return of_pair<obb3, X>(near ? support::obb_case<obb3, X>::near(r) : support::obb_case<obb3, X>::random(r));
               }));
    }
    {
        support::rng r = set_rng(near);
        values(pair_name("kdop", lin), dist, collect<kdop<14>, X>([&]() -> std::optional<sx<kdop<14>, X>> {
                   const auto p = near ? support::kdop_near<14, X>(r) : support::kdop_random<14, X>(r);
                   if (!p) return std::nullopt;
                   return sx<kdop<14>, X>{p->first, p->second};
               }));
    }
    {
        support::rng r = set_rng(near);
        values(pair_name("convex_polyhedron", lin), dist, collect<convex_polyhedron3, X>([&]() -> std::optional<sx<convex_polyhedron3, X>> {
                   const auto p =
                       near ? support::halfspace_near<convex_polyhedron3, X>(r) : support::halfspace_random<convex_polyhedron3, X>(r);
                   if (!p) return std::nullopt;
                   return sx<convex_polyhedron3, X>{p->first, p->second};
               }));
    }
    {
        support::rng r = set_rng(near);
        values(pair_name("frustum", lin), dist, collect<frustum3, X>([&]() -> std::optional<sx<frustum3, X>> {
                   const auto p = near ? support::halfspace_near<frustum3, X>(r) : support::halfspace_random<frustum3, X>(r);
                   if (!p) return std::nullopt;
                   return sx<frustum3, X>{p->first, p->second};
               }));
    }
    {
        support::rng r = set_rng(near);
        values(pair_name("sphere", lin), dist, collect<sphere3, X>([&]() -> std::optional<sx<sphere3, X>> {
                   const point3 c{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
                   const point3 o{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)},
                       e{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
                   const double radius = near ? 0.5 : r.uniform(0, 0.7);
                   if constexpr (std::is_same_v<X, segment3>) return sx<sphere3, X>{{c, radius}, {o, e}};
                   else return sx<sphere3, X>{{c, radius}, {o, e - o}};
               }));
    }
}

// A polygon or a mesh (a view of arrays a store owns) against X, on the tests' generators.
template <class Store, class X, class Gen>
void view_values(const std::string& pair, bool near, Gen make_case) {
    struct view_case {
        Store g;
        X x{};
    };
    const std::string dist = near ? "near_degenerate" : "random";
    support::rng r = set_rng(near);
    std::vector<view_case> cs;
    for (int guard = 0; cs.size() < set_size && guard < 100000; ++guard) {
        view_case c;
        if (const auto x = make_case(r, c.g, near)) {
            c.x = *x;
            cs.push_back(std::move(c));
        }
    }
    std::vector<bool> truth; // the exact tier, checked against the oracle in the tests
    for (const auto& c : cs) truth.push_back(intersection<exact>(c.g.view(), c.x).has_value());
    reg("exact/intersection_yes_no/" + pair + "/" + dist, cs, truth, check::exact,
        [](const view_case& c) { return intersects<exact>(c.g.view(), c.x); });
    reg("exact/intersection/" + pair + "/" + dist, cs, truth, check::exact,
        [](const view_case& c) { return intersection<exact>(c.g.view(), c.x); });
    reg("conservative/intersection/" + pair + "/" + dist, cs, truth, check::conservative,
        [](const view_case& c) { return intersection<conservative>(c.g.view(), c.x); });
    reg("approximate/intersection/" + pair + "/" + dist, cs, truth, check::approximate,
        [](const view_case& c) { return intersection<approximate>(c.g.view(), c.x); });
}

template <class X>
void register_views(bool near) {
    const std::string lin = linear_name<X>();
    view_values<support::polygon3_store, X>(pair_name("polygon", lin), near, [](support::rng& r, support::polygon3_store& g, bool nr) {
        support::polygon3_store other;
        support::mesh_store mesh;
        return nr ? support::polygon3_near<X>(r, g, other, mesh) : support::polygon3_random<X>(r, g, other, mesh);
    });
    view_values<support::mesh_store, X>(pair_name("mesh", lin), near, [](support::rng& r, support::mesh_store& m, bool nr) {
        support::mesh_store other;
        return std::optional<X>(nr ? support::mesh_near<X>(r, m, other) : support::mesh_random<X>(r, m, other));
    });
}

} // namespace

void register_intersection(bool near) {
    register_linear<ray3>(near);
    register_linear<segment3>(near);
    register_linear<line3>(near);
    register_views<ray3>(near);
    register_views<segment3>(near);
    register_views<line3>(near);
}

} // namespace bench
