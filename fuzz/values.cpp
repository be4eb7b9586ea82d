// intersection() of every value family of the catalog (the catalog's families whose fuzzer is
// "values": the dispatch is generated from that list), on raw bit patterns: byte 0 picks the family,
// the doubles that follow make its shapes (unchecked aggregates: NaN, infinities, subnormals,
// inverted boxes, negative extents, flat and degenerate shapes all occur). Every tier must finish on
// any bits. Then, where the inputs are finite: an aggressive hit is a sure exact hit, an exact hit
// is a conservative hit, a sure conservative hit is an exact hit, and every exact value lies in the
// conservative and aggressive intervals. Where the shapes are well formed (make() accepts them),
// differential against the exact values over CGAL Epeck (testkit/oracle/cgal_values.cpp): the
// exact tier's hit exists iff the oracle's, and its t is correctly rounded. The distance families
// whose fuzzer is "values" (points, segments, rays, lines, triangles) the same way: every tier on
// any bits; where finite, the exact value in both intervals, in both argument orders, and
// correctly rounded against CGAL's squared_distance over Epeck or the exact QP (a triangle's pairs
// but a point's). Any finding aborts.
#include "testkit/oracle/cgal_oracle.hpp"
#include "replay.hpp"
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string_view>
import incidence;
#include "testkit/linear_objects.hpp"

using namespace incidence;

namespace {

struct bits {
    double v[30] = {};
    [[nodiscard]] point3 p(int i) const { return {v[i], v[i + 1], v[i + 2]}; }
    [[nodiscard]] vec3 d(int i) const { return {v[i], v[i + 1], v[i + 2]}; }
};

// Storage for the views (a mesh: a tetrahedron's four faces; a polygon: four vertices).
struct views {
    std::array<point3, 4> vertices;
    std::array<std::array<std::uint32_t, 3>, 4> faces{{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
};

template <class S>
S set_of(const bits& b, views& w) {
    if constexpr (std::is_same_v<S, aabb3>) return {b.p(6), b.p(9)};
    else if constexpr (std::is_same_v<S, plane3>) return {b.d(6), b.v[9]};
    else if constexpr (std::is_same_v<S, obb3>) return {b.p(6), {b.d(9), b.d(12), b.d(15)}, {b.v[18], b.v[19], b.v[20]}};
    else if constexpr (std::is_same_v<S, kdop<14>>) {
        kdop<14> k{};
        for (unsigned i = 0; i < 7; ++i) k.min[i] = b.v[6 + i], k.max[i] = b.v[13 + i];
        return k;
    } else if constexpr (std::is_same_v<S, convex_polyhedron3>) {
        convex_polyhedron3 c{};
        c.count = 5;
        for (unsigned i = 0; i < 5; ++i) c.planes[i] = plane3{b.d(6 + 4 * i), b.v[9 + 4 * i]};
        return c;
    } else if constexpr (std::is_same_v<S, frustum3>) {
        frustum3 f{};
        for (unsigned i = 0; i < 6; ++i) f.planes[i] = plane3{b.d(6 + 4 * (i % 5)), b.v[9 + 4 * (i % 5)] + i};
        return f;
    } else if constexpr (std::is_same_v<S, tetrahedron3>) return {b.p(6), b.p(9), b.p(12), b.p(15)};
    else if constexpr (std::is_same_v<S, sphere3>) return {b.p(6), b.v[9]};
    else if constexpr (std::is_same_v<S, triangle3>) return {b.p(6), b.p(9), b.p(12)};
    else if constexpr (std::is_same_v<S, mesh3>) {
        w.vertices = {b.p(6), b.p(9), b.p(12), b.p(15)};
        return mesh3{w.vertices, w.faces};
    } else { // polygon3: a parallelogram, planar by construction where the sums are exact
        w.vertices = {b.p(6), b.p(9), b.p(9) + (b.p(12) - b.p(6)), b.p(12)};
        return polygon3{w.vertices, {}, {0, 1, 3}, 2};
    }
}
template <class X>
X linear_of(const bits& b) {
    if constexpr (std::is_same_v<X, segment3>) return {b.p(0), b.p(3)};
    else return {b.p(0), b.d(3)};
}
bool finite(const bits& b) {
    for (double x : b.v)
        if (!std::isfinite(x)) return false;
    return true;
}
template <class H>
double t_of(const H& h) {
    if constexpr (requires { h.t_enter; }) return h.t_enter;
    else return h.t;
}
template <class H>
interval ti_of(const H& h) {
    if constexpr (requires { h.t_enter; }) return h.t_enter;
    else return h.t;
}

using support::object_of;
void arr(point3 p, double* o) { o[0] = p.x, o[1] = p.y, o[2] = p.z; }

// The oracle where the shape is well formed; nullopt elsewhere.
template <class S, class X>
std::optional<oracle::exact_hit> exact_of(const S& s, const X& x) {
    const oracle::linear_object o = object_of(x);
    if constexpr (std::is_same_v<S, aabb3>) {
        if (!(s.min.x <= s.max.x && s.min.y <= s.max.y && s.min.z <= s.max.z)) return std::nullopt;
        double mn[3], mx[3];
        arr(s.min, mn), arr(s.max, mx);
        return oracle::exact_box(o, mn, mx);
    } else if constexpr (std::is_same_v<S, plane3>) {
        const double n[3] = {s.normal.x, s.normal.y, s.normal.z};
        return oracle::exact_plane(o, n, s.offset);
    } else if constexpr (std::is_same_v<S, sphere3>) {
        if (!(s.radius >= 0)) return std::nullopt;
        double c[3];
        arr(s.center, c);
        return oracle::exact_ball(o, c, s.radius);
    } else if constexpr (std::is_same_v<S, triangle3>) {
        double a[3], b[3], c[3];
        arr(s.a, a), arr(s.b, b), arr(s.c, c);
        return oracle::exact_triangle(o, a, b, c);
    } else if constexpr (std::is_same_v<S, tetrahedron3>) {
        double v[12];
        arr(s.a, v), arr(s.b, v + 3), arr(s.c, v + 6), arr(s.d, v + 9);
        return oracle::exact_tetrahedron(o, v);
    } else if constexpr (std::is_same_v<S, convex_polyhedron3> || std::is_same_v<S, frustum3>) {
        std::vector<std::array<double, 4>> planes;
        const int m = [&] {
            if constexpr (std::is_same_v<S, frustum3>) return 6;
            else return s.count;
        }();
        for (int i = 0; i < m; ++i) {
            const plane3 p = s.planes[static_cast<unsigned>(i)];
            planes.push_back({p.normal.x, p.normal.y, p.normal.z, p.offset});
        }
        return oracle::exact_halfspaces(o, planes);
    } else if constexpr (std::is_same_v<S, kdop<14>>) {
        std::vector<std::array<double, 3>> dirs;
        for (const auto& d : kdop<14>::directions()) dirs.push_back({double(d.x), double(d.y), double(d.z)});
        return oracle::exact_kdop(o, dirs, s.min.data(), s.max.data());
    } else if constexpr (std::is_same_v<S, obb3>) {
        for (double h : s.half_extents)
            if (!(h >= 0)) return std::nullopt;
        double c[3], axes[9];
        arr(s.center, c);
        for (unsigned i = 0; i < 3; ++i) axes[3 * i] = s.axes[i].x, axes[3 * i + 1] = s.axes[i].y, axes[3 * i + 2] = s.axes[i].z;
        auto h = oracle::exact_obb(o, c, axes, s.half_extents.data());
        if (h.declined) return std::nullopt;
        return h;
    } else {
        return std::nullopt; // views: the survival and tier checks only (their oracles need a closed mesh, a planar polygon)
    }
}

template <class F>
void run(const F& fam, const bits& b, bool check) {
    using S = typename F::first_type;
    using X = typename F::second_type;
    views w;
    const S s = set_of<S>(b, w);
    const X x = linear_of<X>(b);
    const auto e = intersection<exact>(s, x);
    const auto c = intersection<conservative>(x, s);
    const auto a = intersection<aggressive>(s, x);
    (void)intersection<approximate>(s, x);
    if (!check) return;
    if (a && (!e || a->exists != certainty::yes)) std::abort();
    if (e && !c) std::abort();
    if (c && c->exists == certainty::yes && !e) std::abort();
    if (e && c && !ti_of(*c).contains(t_of(*e))) std::abort();
    if (e && a && !ti_of(*a).contains(t_of(*e))) std::abort();
    if (const auto o = exact_of(s, x)) {
        if (o->exists() != e.has_value()) std::abort();
        if (e && !o->rounds_to(oracle::quantity::t_enter, t_of(*e))) std::abort();
    }
    (void)fam;
}

// A point, segment, ray, line or triangle from the doubles at offset i.
template <class X>
X part_of(const bits& b, int i) {
    if constexpr (std::is_same_v<X, point3>) return b.p(i);
    else if constexpr (std::is_same_v<X, segment3>) return {b.p(i), b.p(i + 3)};
    else if constexpr (std::is_same_v<X, triangle3>) return {b.p(i), b.p(i + 3), b.p(i + 6)};
    else return {b.p(i), b.d(i + 3)};
}
oracle::flat flat_of(const point3& p) { return {oracle::flat::point, {p.x, p.y, p.z}}; }
oracle::flat flat_of(const segment3& s) { return {oracle::flat::segment, {s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z}}; }
oracle::flat flat_of(const triangle3& t) {
    return {oracle::flat::triangle, {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z}};
}
template <class X>
oracle::flat flat_of(const X& x) {
    return {std::is_same_v<X, ray3> ? oracle::flat::ray : oracle::flat::line,
            {x.origin.x, x.origin.y, x.origin.z, x.direction.x, x.direction.y, x.direction.z}};
}

template <class A, class B>
void run_flat_distance(const bits& b, bool check);

// A distance family: every tier on any bits; where finite, the exact value in both intervals, the
// same in both argument orders, and correctly rounded against CGAL's.
template <class F>
void run_distance(const F&, const bits& b, bool check) {
    using A = typename F::first_type;
    using B = typename F::second_type;
    if constexpr (flat_distance_shape<A> && flat_distance_shape<B>) run_flat_distance<A, B>(b, check);
}
template <class A, class B>
void run_flat_distance(const bits& b, bool check) {
    const A x = part_of<A>(b, 0);
    const B y = part_of<B>(b, 12);
    for (const bool squared : {false, true}) {
        const double e = squared ? squared_distance(x, y) : distance(x, y);
        const interval c = squared ? squared_distance<conservative>(y, x) : distance<conservative>(y, x);
        const interval a = squared ? squared_distance<aggressive>(x, y) : distance<aggressive>(x, y);
        const double p = squared ? squared_distance<approximate>(x, y) : distance<approximate>(x, y);
        if (!check) continue;
        const double er = squared ? squared_distance(y, x) : distance(y, x);
        if (std::memcmp(&e, &er, sizeof e) != 0) std::abort();
        if (!c.contains(e) || !a.contains(e)) std::abort();
        const auto k = oracle::check_flat_distance(flat_of(x), flat_of(y), squared, e, c.lo, c.hi, p);
        if (k.known && (!k.rounded || !k.enclosed)) std::abort(); // known: the exact QP may decline
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    bits b;
    std::memcpy(b.v, data + 1, size - 1 < sizeof b.v ? size - 1 : sizeof b.v);
    std::size_t count = 0;
    catalog::for_each_value_family([&](const auto& f) { count += std::string_view(f.fuzzer) == "values"; });
    catalog::for_each_distance([&](const auto& f) { count += std::string_view(f.fuzzer) == "values"; });
    const std::size_t pick = data[0] % (count == 0 ? 1 : count);
    std::size_t i = 0;
    const bool check = finite(b);
    catalog::for_each_value_family([&](const auto& f) {
        if (std::string_view(f.fuzzer) != "values") return;
        if (i++ == pick) run(f, b, check);
    });
    catalog::for_each_distance([&](const auto& f) {
        if (std::string_view(f.fuzzer) != "values") return;
        if (i++ == pick) run_distance(f, b, check);
    });
    return 0;
}
