// The scene's contract in the harnesses: intersects<Tier>(x, scene) against the brute force over the
// scene's triangles (exact and aggressive equal to it, conservative between the exact answer and
// it, approximate between the plain-double answers of the triangles whose boxes x meets and it),
// and the exact first hit: the least correctly
// rounded parameter of the scalar intersection<exact>(x, triangle), with that triangle's values bit
// for bit; the interval tiers name the same triangle, and their t is within an ulp of the exact tier's.
// A scene refuses non-finite triangles (make); any other difference aborts. Include after
// `import incidence;`.
#pragma once
#include <cmath>
#include <cstdlib>
#include <optional>
#include <span>
#include <vector>

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
