// What intersection<Tier>(a, b) returns (docs/DESIGN.md, "Values"). Every hit is about the linear
// object of the pair (a ray o + t d, t >= 0; a segment a + t (b - a), 0 <= t <= 1; a line, every t):
// its parameters and points, whichever argument order the query was asked in.
// V is the tier's value type: double for exact (each value correctly rounded) and approximate
// (plain double, with the pair's stated bound); interval for conservative and aggressive (each
// interval contains the exact value). A point or a vector is then an interval3.
module;
#include <cstddef>
#include <type_traits>
export module incidence.core:hits;
import :vec;
import :tier;

export namespace incidence {

template <class V>
using point_of = std::conditional_t<std::is_same_v<V, interval>, interval3, point3>;
template <class V>
using vec_of = std::conditional_t<std::is_same_v<V, interval>, interval3, vec3>;

// exists: yes when the hit surely exists (exact and aggressive always; conservative when its filter
// proved it); uncertain when conservative reports a hit it could not exclude (its values then
// enclose the hit's values in case it exists), and for the approximate tier, which proves nothing.

// The part of the linear object inside a closed convex set (a plane, a box, an oriented box, a
// k-DOP, a frustum, a convex polyhedron, a tetrahedron, a ball): t_enter <= t_exit, both within
// the object's own parameter range; t_enter = t_exit where it crosses a plane. A line that lies
// in a plane, or meets an unbounded set along an unbounded part, has an infinite end.
template <class V = double>
struct span_hit {
    V t_enter;
    V t_exit;
    point_of<V> point; // at t_enter; where t_enter is -infinity, at the span's parameter nearest 0
    certainty exists = certainty::yes;
};

// The first contact of the linear object with a closed triangle: its least parameter there.
template <class V = double>
struct triangle_hit {
    V t;
    point_of<V> point;
    vec_of<V> normal; // (b - a) x (c - a), not normalised: its orientation tells the side hit
    V u, v, w;        // barycentrics of a, b, c (point = u a + v b + w c); 0 for a degenerate triangle
    certainty exists = certainty::yes;
};

// The first contact of the linear object with a closed mesh's solid: its least parameter there,
// on a triangle, or at the object's start when that lies inside the solid (triangle == inside; a
// line with a zero direction is its origin, hit inside at t = 0).
template <class V = double>
struct mesh_hit {
    static constexpr std::size_t inside = static_cast<std::size_t>(-1);
    static constexpr std::size_t unknown = static_cast<std::size_t>(-2); // an uncertain hit's triangle
    V t;
    point_of<V> point;
    vec_of<V> normal;     // of the triangle hit (zero when inside)
    V u, v, w;            // its barycentrics (0 when inside)
    std::size_t triangle; // the triangle hit, inside, or (an uncertain hit) unknown
    certainty exists = certainty::yes;
};

// The first contact of the linear object with a closed planar polygon (possibly with holes).
template <class V = double>
struct polygon_hit {
    V t;
    point_of<V> point;
    certainty exists = certainty::yes;
};

} // namespace incidence
