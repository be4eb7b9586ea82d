// The scene's contract in the harnesses: intersects<Tier>(x, scene) against the brute force over the
// scene's triangles (exact and aggressive equal to it, conservative between the exact answer and
// it, approximate between the plain-double answers of the triangles whose boxes x meets and it),
// and the exact first hit: the least correctly
// rounded parameter of the scalar intersection<exact>(x, triangle), with that triangle's values bit
// for bit; the interval tiers name the same triangle, and their t is within an ulp of the exact tier's.
// solid_scene_contracts: a solid against the scene, and the scene against a second scene of two
// triangles, as sets of triangles (pairs) met, against the brute force in the same one-sided way.
// A scene refuses non-finite triangles (make); any other difference aborts. Include after
// `import incidence;`.
#pragma once
#include <cmath>
#include <cstdlib>
#include <optional>
#include <set>
#include <type_traits>
#include <utility>
#include <span>
#include <vector>
#include "testkit/scene_cases.hpp"

template <class Tier, class S>
bool brute_any(const S& x, std::span<const incidence::triangle3> ts) {
    bool met = false;
    for (const auto& t : ts) met = met || incidence::intersects<Tier>(x, t);
    return met;
}

template <class S>
void scene_contracts(const S& x, std::span<const incidence::triangle3> ts) {
    using namespace incidence;
    const auto made = scene3::make(ts);
    bool finite = true;
    for (const triangle3& t : ts)
        for (const point3 p : {t.a, t.b, t.c}) finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    if (made.has_value() != finite) std::abort();
    if (!made) {
        if (made.error().code != errc::not_finite) std::abort();
        return;
    }
    const scene3& sc = made.value();
    const bool truth = brute_any<exact>(x, ts);
    if (intersects<exact>(x, sc) != truth || intersects<exact>(sc, x) != truth) std::abort();
    if (intersects<aggressive>(x, sc) != brute_any<aggressive>(x, ts)) std::abort();
    const bool c = intersects<conservative>(x, sc);
    if ((truth && !c) || (c && !brute_any<conservative>(x, ts))) std::abort();
    // approximate: the plain-double answers of the triangles whose boxes x may meet (at least those
    // whose boxes it meets exactly)
    bool in_met_boxes = false;
    for (const triangle3& t : ts) {
        const aabb3 box{{std::fmin(std::fmin(t.a.x, t.b.x), t.c.x), std::fmin(std::fmin(t.a.y, t.b.y), t.c.y),
                         std::fmin(std::fmin(t.a.z, t.b.z), t.c.z)},
                        {std::fmax(std::fmax(t.a.x, t.b.x), t.c.x), std::fmax(std::fmax(t.a.y, t.b.y), t.c.y),
                         std::fmax(std::fmax(t.a.z, t.b.z), t.c.z)}};
        in_met_boxes = in_met_boxes || (intersects<exact>(x, box) && intersects<approximate>(x, t));
    }
    const bool a = intersects<approximate>(x, sc);
    if ((a && !brute_any<approximate>(x, ts)) || (!a && in_met_boxes)) std::abort();
    std::optional<double> least;
    for (const triangle3& t : ts)
        if (const auto h = intersection<exact>(x, t); h && (!least || h->t < *least)) least = h->t;
    const auto h = intersection<exact>(x, sc);
    if (h.has_value() != least.has_value()) std::abort();
    if (!h) return;
    const auto one = intersection<exact>(x, ts[h->triangle]);
    if (h->t != *least || !one || one->t != h->t || one->point != h->point || one->normal != h->normal || one->u != h->u ||
        one->v != h->v || one->w != h->w)
        std::abort();
    // an interval that contains the exact t meets the doubles either side of its correct rounding
    const double below = std::nextafter(h->t, -INFINITY), above = std::nextafter(h->t, INFINITY);
    for (const auto& hi : {intersection<conservative>(x, sc), intersection<aggressive>(sc, x)})
        if (!hi || hi->triangle != h->triangle || hi->exists != certainty::yes || !(hi->t.lo <= above && below <= hi->t.hi)) std::abort();
}

template <class Tier, class S>
void solid_scene_tier(const S& shape, const incidence::scene3& sc, std::span<const incidence::triangle3> ts,
                      const std::set<std::size_t>& truth) {
    std::set<std::size_t> brute;
    for (std::size_t i = 0; i < ts.size(); ++i)
        if (incidence::intersects<Tier>(shape, ts[i])) brute.insert(i);
    std::vector<std::size_t> out;
    const std::size_t n = incidence::intersecting<Tier>(shape, sc, out);
    const std::set<std::size_t> listed(out.begin(), out.end());
    if (n != out.size() || listed.size() != n || incidence::intersects<Tier>(shape, sc) != (n > 0)) std::abort();
    if (!support::set_contract<Tier>(listed, brute, truth, {})) std::abort();
}
template <class Tier>
void scene_pairs_tier(const incidence::scene3& a, const incidence::scene3& b, std::span<const incidence::triangle3> ta,
                      std::span<const incidence::triangle3> tb, const std::set<std::pair<std::size_t, std::size_t>>& truth) {
    std::set<std::pair<std::size_t, std::size_t>> brute;
    for (std::size_t i = 0; i < ta.size(); ++i)
        for (std::size_t j = 0; j < tb.size(); ++j)
            if (incidence::intersects<Tier>(ta[i], tb[j])) brute.insert({i, j});
    std::vector<std::pair<std::size_t, std::size_t>> out;
    const std::size_t n = incidence::intersecting<Tier>(a, b, out);
    const std::set<std::pair<std::size_t, std::size_t>> listed(out.begin(), out.end());
    if (n != out.size() || listed.size() != n || incidence::intersects<Tier>(a, b) != (n > 0)) std::abort();
    if (!support::set_contract<Tier>(listed, brute, truth, {})) std::abort();
}

template <class S>
void solid_scene_contracts(const S& shape, std::span<const incidence::triangle3> ts, std::span<const incidence::triangle3> others) {
    using namespace incidence;
    const auto made = scene3::make(ts), other = scene3::make(others);
    if (!made || !other) return; // non-finite: scene_contracts checks the refusal
    std::set<std::size_t> truth;
    for (std::size_t i = 0; i < ts.size(); ++i)
        if (intersects<exact>(shape, ts[i])) truth.insert(i);
    solid_scene_tier<exact>(shape, made.value(), ts, truth);
    solid_scene_tier<conservative>(shape, made.value(), ts, truth);
    solid_scene_tier<aggressive>(shape, made.value(), ts, truth);
    solid_scene_tier<approximate>(shape, made.value(), ts, truth);
    std::set<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < ts.size(); ++i)
        for (std::size_t j = 0; j < others.size(); ++j)
            if (intersects<exact>(ts[i], others[j])) pairs.insert({i, j});
    scene_pairs_tier<exact>(made.value(), other.value(), ts, others, pairs);
    scene_pairs_tier<conservative>(made.value(), other.value(), ts, others, pairs);
    scene_pairs_tier<aggressive>(made.value(), other.value(), ts, others, pairs);
    scene_pairs_tier<approximate>(made.value(), other.value(), ts, others, pairs);
}
