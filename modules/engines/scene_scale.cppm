// A pair of shapes scaled together by one power of two about the origin, for the filter's second
// try. The filter trusts a permanent only within [2^-900, 2^1000): in a scene near 2^-500 or
// 2^500 a sign of degree 3 or more leaves that range, and the filter gives up on inputs it would
// decide at once near scale 1. Every intersection and containment answer is invariant under
// x -> 2^s x, and so is the meaning of each shape with its lengths scaled and its directions kept:
// a ray {o, d} becomes {2^s o, d}, a plane {n, c} becomes {n, 2^s c}, an oriented box keeps its
// axes and scales its centre and half extents, a k-DOP scales its slab bounds. The scaling is
// exact when every scaled length stays normal and finite, which is checked value by value; a pair
// that would lose a bit is not scaled. Views (mesh3, polygon2, polygon3) would need a copy of
// their vertices, so they are not scaled: for a pair with a view, every input (directions too) is
// scaled by one power of two as the filter lifts it instead (arith::scaled_filter_kernel).
module;
#include <array>
#include <concepts>
#include <optional>
#include <type_traits>
export module incidence.detail:engines.scene_scale;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::detail::scene {

// lengths(shape, v): v(x) for every length x of the shape (a coordinate, an offset, a radius, a
// half extent, a slab bound), as a double& for a shape to scale, a const double& for one to scan.
template <class S, class T>
concept shape_of = std::same_as<std::remove_const_t<S>, T>;
template <class S>
concept kdop_shape = requires { std::remove_const_t<S>::slabs; } && shape_of<S, kdop<std::remove_const_t<S>::slabs * 2>>;

template <class S, class V>
requires shape_of<S, point3>
constexpr void lengths(S& p, V& v) {
    v(p.x), v(p.y), v(p.z);
}
template <class S, class V>
requires shape_of<S, point2>
constexpr void lengths(S& p, V& v) {
    v(p.x), v(p.y);
}
template <class S, class V>
requires shape_of<S, segment3> || shape_of<S, segment2>
constexpr void lengths(S& s, V& v) {
    lengths(s.a, v), lengths(s.b, v);
}
template <class S, class V>
requires shape_of<S, ray3> || shape_of<S, line3> || shape_of<S, ray2> || shape_of<S, line2>
constexpr void lengths(S& r, V& v) {
    lengths(r.origin, v);
} // directions are kept
template <class S, class V>
requires shape_of<S, plane3>
constexpr void lengths(S& p, V& v) {
    v(p.offset);
} // the normal is kept
template <class S, class V>
requires shape_of<S, triangle3>
constexpr void lengths(S& t, V& v) {
    lengths(t.a, v), lengths(t.b, v), lengths(t.c, v);
}
template <class S, class V>
requires shape_of<S, tetrahedron3>
constexpr void lengths(S& t, V& v) {
    lengths(t.a, v), lengths(t.b, v), lengths(t.c, v), lengths(t.d, v);
}
template <class S, class V>
requires shape_of<S, aabb3>
constexpr void lengths(S& b, V& v) {
    lengths(b.min, v), lengths(b.max, v);
}
template <class S, class V>
requires shape_of<S, obb3>
constexpr void lengths(S& b, V& v) { // the axes are kept
    lengths(b.center, v);
    for (auto& h : b.half_extents) v(h);
}
template <class S, class V>
requires shape_of<S, sphere3> || shape_of<S, circle2>
constexpr void lengths(S& s, V& v) {
    lengths(s.center, v), v(s.radius);
}
template <class S, class V>
requires kdop_shape<S>
constexpr void lengths(S& k, V& v) {
    for (auto& x : k.min) v(x);
    for (auto& x : k.max) v(x);
}
template <class S, class V>
requires shape_of<S, frustum3>
constexpr void lengths(S& f, V& v) {
    for (auto& p : f.planes) lengths(p, v);
}
template <class S, class V>
requires shape_of<S, convex_polyhedron3>
constexpr void lengths(S& c, V& v) { // a count outside [0, capacity] is no set: left as it is
    for (int i = 0; i < c.count && i < convex_polyhedron3::capacity; ++i) lengths(c.planes[static_cast<unsigned>(i)], v);
}

struct exponent_scan { // the largest exponent of a nonzero length; whether all are finite
    int top = -(1 << 20);
    bool finite = true;
    constexpr void operator()(const double& x) {
        if (!is_finite(x)) finite = false;
        else if (x != 0.0 && arith::exponent_of(x) > top) top = arith::exponent_of(x);
    }
};
struct scaling { // x * 2^s, and whether every product was exact (it scales back to x)
    double factor, inverse;
    bool exact = true;
    constexpr void operator()(double& x) {
        const double y = x * factor;
        if (!(y * inverse == x)) exact = false;
        x = y;
    }
};

template <class S>
concept scalable = requires(S& s, scaling& v) { lengths(s, v); };

// inputs(shape, v): v(x) for every double the shape's signs lift, read only, for the shapes whose
// signs take every input to the same power in a scene: the views of vertices (which are not copied
// to be scaled) and points, segments, triangles, tetrahedra, boxes, rays and lines (whose
// directions a scene at 2^500 has at 2^500 too). For the filter pass that scales every input by
// one power of two (arith::scaled_filter_kernel). Shapes with unit normals or axes (planes,
// oriented boxes, k-DOPs, frustums, convex polyhedra, spheres' radii aside) mix magnitudes that one
// factor for all cannot bring together: measured slower, so they have no inputs() here.
template <class S, class V>
requires shape_of<S, point3> || shape_of<S, point2> || shape_of<S, segment3> || shape_of<S, segment2> || shape_of<S, triangle3> ||
         shape_of<S, tetrahedron3> || shape_of<S, aabb3>
constexpr void inputs(const S& s, V& v) {
    lengths(s, v);
}
template <class S, class V>
requires shape_of<S, ray3> || shape_of<S, line3>
constexpr void inputs(const S& r, V& v) {
    lengths(r.origin, v), v(r.direction.x), v(r.direction.y), v(r.direction.z);
}
template <class S, class V>
requires shape_of<S, ray2> || shape_of<S, line2>
constexpr void inputs(const S& r, V& v) {
    lengths(r.origin, v), v(r.direction.x), v(r.direction.y);
}
template <class S>
concept view_shape = shape_of<S, polygon2> || shape_of<S, polygon3> || shape_of<S, mesh3>;
template <class S, class V>
requires view_shape<S>
constexpr void inputs(const S& s, V& v) {
    for (const auto& p : s.vertices) lengths(p, v);
}
template <class S>
concept scannable = requires(const S& s, exponent_scan& v) { inputs(s, v); };
// Whether a largest exponent lies 2^60 or more, or below 2^-60, from scale 1: nearer, the filter's
// range is not what failed, and scaling cannot help.
[[nodiscard]] constexpr bool far_from_one(int top) { return top <= -60 || top >= 60; }
// A view's first vertex, any other shape's every input: a glance at the scene's scale in O(1).
template <scannable S, class V>
constexpr void first_inputs(const S& s, V& v) {
    if constexpr (view_shape<S>) {
        if (!s.vertices.empty()) lengths(s.vertices[0], v);
    } else {
        inputs(s, v);
    }
}
// Whether that glance puts the pair 2^60 or more, or below 2^-60, from scale 1.
template <scannable A, scannable B>
[[nodiscard]] constexpr bool looks_far(const A& a, const B& b) {
    exponent_scan e;
    first_inputs(a, e), first_inputs(b, e);
    return e.finite && e.top > -(1 << 20) && far_from_one(e.top);
}

// The exponent of the pair's largest input (directions included) when it is 2^60 or more, or
// below 2^-60, every input is finite and 2^-top is a double; 0 otherwise.
template <scannable A, scannable B>
[[nodiscard]] constexpr int far_input_exponent(const A& a, const B& b) {
    exponent_scan e;
    inputs(a, e), inputs(b, e);
    if (!e.finite || e.top < -1022 || e.top > 1022 || !far_from_one(e.top)) return 0;
    return e.top;
}

template <class A, class B>
struct scaled_pair {
    A a;
    B b;
};

// The exponent of the pair's largest length when it is 2^60 or more, or below 2^-60 (nearer scale
// 1 the filter's range is not what failed), and every length is finite; 0 otherwise.
template <scalable A, scalable B>
[[nodiscard]] constexpr int far_exponent(const A& a, const B& b) {
    exponent_scan e;
    lengths(a, e), lengths(b, e);
    if (!e.finite || e.top < -1074 || !far_from_one(e.top)) return 0;
    return e.top;
}
// The pair scaled by 2^-top (top = far_exponent(a, b), nonzero), so that its largest length lies
// in [1, 2), when every scaled length is exact; std::nullopt when a bit would be lost.
template <scalable A, scalable B>
[[nodiscard, gnu::noinline]] constexpr std::optional<scaled_pair<A, B>> normalized(const A& a, const B& b, int top) {
    scaled_pair<A, B> p{a, b};
    const int s = -top; // in [-1023, 1074]: in two steps where 2^s is not a double
    const int first = s > 1000 || s < -1000 ? s / 2 : s;
    scaling v{arith::power_of_two(first), arith::power_of_two(-first)};
    lengths(p.a, v), lengths(p.b, v);
    if (first != s) {
        scaling rest{arith::power_of_two(s - first), arith::power_of_two(first - s)};
        lengths(p.a, rest), lengths(p.b, rest);
        if (!rest.exact) return std::nullopt;
    }
    if (!v.exact) return std::nullopt;
    return p;
}
// Both steps: the pair scaled towards scale 1, or std::nullopt (near scale 1 already, a value not
// finite, all lengths zero, or a bit would be lost).
template <scalable A, scalable B>
[[nodiscard]] constexpr std::optional<scaled_pair<A, B>> normalized(const A& a, const B& b) {
    const int top = far_exponent(a, b);
    if (top == 0) return std::nullopt;
    return normalized(a, b, top);
}

} // namespace incidence::detail::scene
