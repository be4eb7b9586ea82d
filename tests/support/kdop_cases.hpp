// Cases for the k-DOP linear pairs. Include after flat_cases.hpp and lp_shapes.hpp.
//
// Near-degenerate: the k-DOP of 4 to 8 points of small dyadic coordinates (so every bound is
// exactly d . p of a point: those points lie on its boundary), the other shape placed as in
// flat_cases.hpp at X (one of those extreme points, or the cloud's first point, maybe inside)
// along a random direction, or along the face of an extreme direction d_i (perpendicular to
// it); then a random exact-or-nudged scale 2^-500..2^500 and translation applied to the points
// and the shape, and the k-DOP of the moved points (bounds rounded outward where d . p is not a
// double). Random: the k-DOP of 4 to 8 random points around a random centre in [-1, 1]^3 at
// size about 1/2, and a random shape of flat_cases.hpp, at a random scale.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace support {

template <int K>
std::string shape_str(const incidence::kdop<K>& b) {
    std::string s = std::to_string(K) + "-dop";
    for (unsigned i = 0; i < b.min.size(); ++i) s += " [" + hex(b.min[i]) + "," + hex(b.max[i]) + "]";
    return s;
}

template <int K>
std::optional<incidence::kdop<K>> kdop_around(const std::vector<incidence::point3>& pts) {
    const auto k = incidence::bound::kdop_of<K>(std::span<const incidence::point3>(pts));
    if (!k.has_value()) return std::nullopt; // a bound overflowed
    return k.value();
}

template <int K, class B>
std::optional<std::pair<incidence::kdop<K>, B>> kdop_near(rng& r) {
    using namespace incidence;
    const point3 c = small_point(r);
    std::vector<point3> pts;
    const int n = r.integer(4, 8);
    for (int i = 0; i < n; ++i)
        pts.push_back({c.x + r.integer(-8, 8) * 0.25, c.y + r.integer(-8, 8) * 0.25, c.z + r.integer(-8, 8) * 0.25});
    const auto dirs = kdop<K>::directions();
    const unsigned slab = static_cast<unsigned>(r.integer(0, K / 2 - 1));
    const direction3 ds = dirs[slab];
    const bool top = r.coin();
    point3 X = pts[0];
    auto dotd = [&](point3 p) { return ds.x * p.x + ds.y * p.y + ds.z * p.z; }; // exact: small dyadics
    for (const auto& p : pts)
        if (top ? dotd(p) > dotd(X) : dotd(p) < dotd(X)) X = p;
    if (r.integer(0, 5) == 0) X = pts[0];
    const vec3 nd{double(ds.x), double(ds.y), double(ds.z)};
    vec3 d = small_dir(r);
    if (r.coin()) { // along the face of the extreme direction
        d = cross(nd, d);
        if (d.x == 0 && d.y == 0 && d.z == 0) d = cross(nd, vec3{1, 2, 3});
    }
    const auto b = place<B>(r, X, d, r.coin());
    transform tr = random_transform(r, true, true);
    for (auto& p : pts) p = moved(p, tr);
    const auto kd = kdop_around<K>(pts);
    if (!kd) return std::nullopt;
    return std::pair{*kd, realise(b, tr)};
}
template <int K, class B>
std::optional<std::pair<incidence::kdop<K>, B>> kdop_random(rng& r) {
    using namespace incidence;
    const point3 c{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
    std::vector<point3> pts;
    const int n = r.integer(4, 8);
    for (int i = 0; i < n; ++i) pts.push_back({c.x + r.uniform(-0.25, 0.25), c.y + r.uniform(-0.25, 0.25), c.z + r.uniform(-0.25, 0.25)});
    transform tr = random_transform(r, false, true);
    for (auto& p : pts) p = moved(p, tr);
    const auto kd = kdop_around<K>(pts);
    if (!kd) return std::nullopt;
    return std::pair{*kd, realise(random_shape<B>(r, false, 0.0), tr)};
}

// Exact translation of a k-DOP by v (small dyadic components): every bound moved by d . v when
// that sum is exact.
template <int K>
std::optional<incidence::kdop<K>> translated(const incidence::kdop<K>& b, incidence::vec3 v) {
    const auto dirs = incidence::kdop<K>::directions();
    incidence::kdop<K> out = b;
    auto add = [](double x, double y) -> std::optional<double> {
        const double s = x + y, z = s - x;
        if ((x - (s - z)) + (y - z) != 0.0 || !std::isfinite(s)) return std::nullopt;
        return s;
    };
    for (unsigned i = 0; i < dirs.size(); ++i) {
        const double dv = dirs[i].x * v.x + dirs[i].y * v.y + dirs[i].z * v.z; // exact: small dyadics
        const auto lo = add(b.min[i], dv), hi = add(b.max[i], dv);
        if (!lo || !hi) return std::nullopt;
        out.min[i] = *lo, out.max[i] = *hi;
    }
    return out;
}

} // namespace support
