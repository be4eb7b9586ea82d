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
#include <type_traits>
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

template <class B>
struct is_kdop : std::false_type {};
template <int M>
struct is_kdop<incidence::kdop<M>> : std::true_type {};

// The k-DOPs of two clouds moved by one transform (nullopt when a bound overflows).
template <int K, int M>
std::optional<std::pair<incidence::kdop<K>, incidence::kdop<M>>> kdops_of(std::vector<incidence::point3>& P,
                                                                          std::vector<incidence::point3>& Q, transform tr) {
    for (auto& p : P) p = moved(p, tr);
    for (auto& p : Q) p = moved(p, tr);
    const auto a = kdop_around<K>(P);
    const auto b = kdop_around<M>(Q);
    if (!a || !b) return std::nullopt;
    return std::pair{*a, *b};
}

// Two k-DOPs (kdop_kdop), near-degenerate: clouds P and Q of small dyadic points. Q starts at X,
// the extreme point of P in a direction d_s, and lies beyond or on P's face there (d_s . (q - X)
// >= 0, X itself left out), so the two touch that face's plane or are separated by it, and
// whether they meet is up to the other slabs; or Q is P moved by the exact offset that lays its
// bottom face on P's top face, plus a slide along that face (faces overlapping, touching at an
// edge or apart); or Q is a cloud around X (interpenetrating). Then one random
// exact-or-nudged scale and translation for both clouds.
template <int K, int M>
std::optional<std::pair<incidence::kdop<K>, incidence::kdop<M>>> kdop_pair_near(rng& r) {
    using namespace incidence;
    const point3 c = small_point(r);
    std::vector<point3> P, Q;
    auto cloud = [&](std::vector<point3>& v, point3 at, int n) {
        for (int i = 0; i < n; ++i)
            v.push_back({at.x + r.integer(-8, 8) * 0.25, at.y + r.integer(-8, 8) * 0.25, at.z + r.integer(-8, 8) * 0.25});
    };
    cloud(P, c, r.integer(4, 8));
    const auto dirs = kdop<26>::directions();
    const direction3 ds = dirs[static_cast<unsigned>(r.integer(0, 12))];
    auto dotd = [&](vec3 p) { return ds.x * p.x + ds.y * p.y + ds.z * p.z; }; // exact: small dyadics
    point3 X = P[0], Y = P[0];
    for (const auto& p : P) {
        if (dotd(p - point3{0, 0, 0}) > dotd(X - point3{0, 0, 0})) X = p;
        if (dotd(p - point3{0, 0, 0}) < dotd(Y - point3{0, 0, 0})) Y = p;
    }
    const int mode = r.integer(0, 2);
    if (mode == 0) {
        const int n = r.integer(3, 7);
        while (static_cast<int>(Q.size()) < n) {
            vec3 o{r.integer(-8, 8) * 0.25, r.integer(-8, 8) * 0.25, r.integer(-8, 8) * 0.25};
            if (r.integer(0, 2) == 0) o = cross(vec3{double(ds.x), double(ds.y), double(ds.z)}, o); // on the face's plane
            if (dotd(o) < 0) o = vec3{-o.x, -o.y, -o.z};
            if (o.x == 0 && o.y == 0 && o.z == 0) continue;
            Q.push_back({X.x + o.x, X.y + o.y, X.z + o.z});
        }
    } else if (mode == 1) {
        vec3 t = X - Y;
        const vec3 slide = cross(vec3{double(ds.x), double(ds.y), double(ds.z)},
                                 vec3{r.integer(-4, 4) * 0.25, r.integer(-4, 4) * 0.25, r.integer(-4, 4) * 0.25});
        t = vec3{t.x + slide.x, t.y + slide.y, t.z + slide.z};
        for (const auto& p : P) Q.push_back({p.x + t.x, p.y + t.y, p.z + t.z});
    } else {
        cloud(Q, X, r.integer(4, 8));
    }
    return kdops_of<K, M>(P, Q, random_transform(r, true, true));
}
// 4 to 8 random points within 0.4 of a centre in [-0.6, 0.6]^3.
inline std::vector<incidence::point3> random_cloud(rng& r) {
    const incidence::point3 c{r.uniform(-0.6, 0.6), r.uniform(-0.6, 0.6), r.uniform(-0.6, 0.6)};
    std::vector<incidence::point3> v;
    for (int i = r.integer(4, 8); i > 0; --i)
        v.push_back({c.x + r.uniform(-0.4, 0.4), c.y + r.uniform(-0.4, 0.4), c.z + r.uniform(-0.4, 0.4)});
    return v;
}
// Two k-DOPs, random: the k-DOPs of two clouds of 4 to 8 random points within 0.4 of centres in
// [-0.6, 0.6]^3, at one random scale.
template <int K, int M>
std::optional<std::pair<incidence::kdop<K>, incidence::kdop<M>>> kdop_pair_random(rng& r) {
    using namespace incidence;
    std::vector<point3> P = random_cloud(r);
    std::vector<point3> Q = random_cloud(r);
    return kdops_of<K, M>(P, Q, random_transform(r, false, true));
}

template <int K, class B>
std::optional<std::pair<incidence::kdop<K>, B>> kdop_near(rng& r) {
    using namespace incidence;
    if constexpr (is_kdop<B>::value) return kdop_pair_near<K, B::slabs * 2>(r);
    else {
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
        auto b = place<B>(r, X, d, r.coin());
        if constexpr (std::is_same_v<B, plane3>) // the face's own plane through X, either orientation: touching
            if (r.integer(0, 2) == 0) b = {r.coin() ? nd : -nd, X};
        if constexpr (std::is_same_v<B, tetrahedron3>)
            if (r.integer(0, 2) == 0) b = tetrahedron_around(r, X, top ? nd : -nd);
        transform tr = random_transform(r, true, true);
        for (auto& p : pts) p = moved(p, tr);
        const auto kd = kdop_around<K>(pts);
        if (!kd) return std::nullopt;
        return std::pair{*kd, realise(b, tr)};
    }
}
template <int K, class B>
std::optional<std::pair<incidence::kdop<K>, B>> kdop_random(rng& r) {
    using namespace incidence;
    if constexpr (is_kdop<B>::value) return kdop_pair_random<K, B::slabs * 2>(r);
    else {
        const point3 c{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
        std::vector<point3> pts;
        const int n = r.integer(4, 8);
        for (int i = 0; i < n; ++i)
            pts.push_back({c.x + r.uniform(-0.25, 0.25), c.y + r.uniform(-0.25, 0.25), c.z + r.uniform(-0.25, 0.25)});
        transform tr = random_transform(r, false, true);
        for (auto& p : pts) p = moved(p, tr);
        const auto kd = kdop_around<K>(pts);
        if (!kd) return std::nullopt;
        return std::pair{*kd, realise(random_shape<B>(r, false, 0.0), tr)};
    }
}
template <int K>
std::vector<incidence::kdop<K>> same_set(const incidence::kdop<K>& b) {
    return {b};
}
template <int K>
bool finite_shape(const incidence::kdop<K>& b) {
    for (unsigned i = 0; i < b.min.size(); ++i)
        if (!std::isfinite(b.min[i]) || !std::isfinite(b.max[i])) return false;
    return true;
}

// contains(kdop, B) cases where B lies inside or just pokes out: the k-DOP of a cloud that has
// B's vertices among its points (so B touches the boundary), B then nudged by one ulp outward at
// one coordinate or not.
template <int K, class B>
std::optional<std::pair<incidence::kdop<K>, B>> kdop_inside_case(rng& r) {
    using namespace incidence;
    const point3 c = small_point(r);
    auto pt = [&] { return point3{c.x + r.integer(-8, 8) * 0.25, c.y + r.integer(-8, 8) * 0.25, c.z + r.integer(-8, 8) * 0.25}; };
    std::vector<point3> pts;
    for (int i = r.integer(0, 5); i > 0; --i) pts.push_back(pt());
    transform tr = random_transform(r, true, true);
    for (auto& p : pts) p = moved(p, tr);
    B b{}; // moved first (a nudged transform rounds each call its own way), then its vertices join the cloud
    if constexpr (std::is_same_v<B, aabb3>) {
        b = realise(aabb3{pt(), pt()}, tr);
        for (int i = 0; i < 8; ++i) pts.push_back({(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z});
        if (r.coin()) b.max.z = std::nextafter(b.max.z, 1e308);
    } else if constexpr (std::is_same_v<B, triangle3>) {
        b = realise(triangle3{pt(), pt(), pt()}, tr);
        pts.push_back(b.a), pts.push_back(b.b), pts.push_back(b.c);
        if (r.coin()) b.c.y = std::nextafter(b.c.y, r.coin() ? 1e308 : -1e308);
    } else if constexpr (std::is_same_v<B, tetrahedron3>) {
        b = realise(tetrahedron3{pt(), pt(), pt(), pt()}, tr);
        pts.push_back(b.a), pts.push_back(b.b), pts.push_back(b.c), pts.push_back(b.d);
        if (r.coin()) b.d.z = std::nextafter(b.d.z, r.coin() ? 1e308 : -1e308);
    } else if constexpr (std::is_same_v<B, obb3>) { // its corners are not doubles: a box about the segment between two points
        b = obb_between(r, realise(segment3{pt(), pt()}, tr));
        pts.push_back(b.center);
    } else {
        b = realise(segment3{pt(), pt()}, tr);
        pts.push_back(b.a), pts.push_back(b.b);
        if (r.coin()) b.b.x = std::nextafter(b.b.x, r.coin() ? 1e308 : -1e308);
    }
    const auto kd = kdop_around<K>(pts);
    if (!kd) return std::nullopt;
    return std::pair{*kd, b};
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
