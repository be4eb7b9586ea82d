// convex_polyhedron3 against obb3, contains(convex_polyhedron3, obb3), and the test of a box
// against any half-space set that frustum_obb and kdop_obb share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded) and the closed box { c + s0 a0 + s1 a1 + s2 a2 : |s_j| <= h_j }, its axes read exactly
// as given (the parallelepiped they span; a zero extent or dependent axes give a flat box).
// Touching at a face, an edge or a corner counts. contains: the whole box in the set.
// Method (exact tiers): the set read in the box's own coordinates s, where the box is the cube
// |s_j| <= h_j and the plane n . x <= d is sum_j (n . a_j) s_j <= d - n . c, every coefficient a
// polynomial of the inputs, not a rounded double. First, a plane with the whole box beyond it
// (d - n . c + sum_j h_j |n . a_j| < 0) says no, and the centre inside every plane says yes. Then
// the box's six faces and the set's planes in s bound a polytope, which is not empty iff it has a
// vertex: three rows with independent normals meeting at a point inside every row (the vertex
// search of aabb_convex_polyhedron.cppm on these rows): homogeneous signs of degree <= 9.
// contains: for every plane, d - n . c - sum_j h_j |n . a_j| >= 0 (degree 3).
// Source: vertex enumeration for LP feasibility (Schrijver, Theory of Linear and Integer
// Programming, 1986, section 8.5), after the exact affine change of coordinates to the box's frame.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_obb.cpp).
module;
#include <array>
export module incidence.query:convex_polyhedron_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :separating_axes;
import :obb_tetrahedron;
import :convex_polyhedron_point;
import :aabb_convex_polyhedron;

export namespace incidence::pair {

namespace polyq {

// The box's six faces and the m planes of a set, read in the box's own coordinates s: row x < 6
// is the face +-s_(x/2) <= h_(x/2) (through the identity frame), row 6 + i is plane i of the set,
// sum_j (n . a_j) s_j <= d - n . c. Every normal is of degree 2 and every offset of degree 3 (its
// terms balanced with a lifted 1), written as one expression for both kinds of rows.
struct frame_rows {
    const plane3* p;
    unsigned m;
    const obb3* b;
    sign axes; // sign(det A), A: the box's axes as columns (triple_sign)
    [[nodiscard]] constexpr unsigned size() const { return m + 6; }
    [[nodiscard]] constexpr bool zero(unsigned x) const { return x >= 6 && zero_normal(p, x - 6); }
    [[nodiscard]] constexpr bool parallel(unsigned x, unsigned y) const {
        if (x < 6 && y < 6) return x / 2 == y / 2;
        return x >= 6 && y >= 6 && parallel_normals(p, x - 6, y - 6);
    }
    struct row {
        vec3 n, a0, a1, a2;
        point3 c;
        double d;
    };
    [[nodiscard]] constexpr row at(unsigned x) const {
        if (x >= 6) return {p[x - 6].normal, b->axes[0], b->axes[1], b->axes[2], b->center, p[x - 6].offset};
        const double s = (x & 1u) ? -1.0 : 1.0;
        const unsigned j = x / 2;
        const vec3 n{j == 0 ? s : 0.0, j == 1 ? s : 0.0, j == 2 ? s : 0.0};
        return {n, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}, b->half_extents[j]};
    }
    template <class L>
    [[nodiscard]] constexpr auto normal(L l, unsigned x) const {
        const row r = at(x);
        const auto n = arith::lift(l, r.n);
        using T = decltype(arith::dot(n, arith::lift(l, r.a0)));
        return arith::v3<T>{arith::dot(n, arith::lift(l, r.a0)), arith::dot(n, arith::lift(l, r.a1)), arith::dot(n, arith::lift(l, r.a2))};
    }
    template <class L>
    [[nodiscard]] constexpr auto offset(L l, unsigned x) const {
        const row r = at(x);
        return (l(r.d) * l(1.0) - arith::dot(arith::lift(l, r.n), arith::lift(l, r.c))) * l(1.0);
    }
    // The sign of det(A^T n_i, A^T n_j, A^T n_l) for three planes of the set (A: the axes as
    // columns) is sign(det A) sign(det(n_i, n_j, n_l)), exactly (the determinant is
    // multiplicative): dependent normals, such as a k-DOP's (1, 0, 0), (0, 1, 0) and (1, 1, 0),
    // give an exact zero that the cheap stages settle on the normals alone, where the product with
    // the axes rounds. Rows with a box face: the lifted det.
    template <class K, class Det>
    [[nodiscard]] constexpr sign triple_sign(K& k, unsigned i, unsigned j, unsigned l, const Det& det) const {
        if (i < 6 || j < 6 || l < 6) return settled(k, det);
        const vec3 a = p[i - 6].normal, c = p[j - 6].normal, e = p[l - 6].normal;
        const sign n = settled(k, [=](auto L) { return arith::det3(arith::lift(L, a), arith::lift(L, c), arith::lift(L, e)); });
        return axes == sign::positive ? n : axes == sign::negative ? -n : sign::zero;
    }
    // The decided sign of c_h D - n_h . V (vertex_of_rows) for four planes of the set is sign(det A)
    // times the same sign on the planes as given: it is the 4 x 4 determinant of the rows, and the
    // rows in s are (n, d) [[A, -c], [0, 1]], whose determinant is det A. Degree 4 instead of 9, so
    // a fourth plane exactly through the vertex of three (a k-DOP's corner) is settled by the cheap
    // exact stages, where the rows in s went to the big integers. In plain double (no filter to
    // lift): the rows in s, as that tier rounds them.
    template <class K, class F>
    [[nodiscard]] constexpr sign beyond_sign(K& k, unsigned i, unsigned j, unsigned l, unsigned h, const F& in_frame) const {
        if (!arith::lifts_filter<K>() || i < 6 || j < 6 || l < 6 || h < 6) return arith::decided(k, in_frame);
        const plane_rows w{p, m};
        const sign s = arith::decided(k, [=](auto L) { return four_rows(L, w, i - 6, j - 6, l - 6, h - 6); });
        return axes == sign::positive ? s : axes == sign::negative ? -s : sign::zero;
    }
};

// d - n . c + t sum_j h_j |n . a_j| (t = +1: the box's farthest point along -n is inside the plane
// iff >= 0, so < 0 puts the whole box beyond it; t = -1: the whole box inside iff >= 0).
template <class L>
[[nodiscard]] constexpr auto box_reach(L l, const obb3& b, const plane3& h, bool farthest) {
    const auto n = arith::lift(l, h.normal);
    const auto one = l(1.0);
    const auto gap = (l(h.offset) * one - arith::dot(n, arith::lift(l, b.center))) * one;
    using sat::magnitude;
    const auto r = l(b.half_extents[0]) * magnitude(arith::dot(n, arith::lift(l, b.axes[0]))) +
                   l(b.half_extents[1]) * magnitude(arith::dot(n, arith::lift(l, b.axes[1]))) +
                   l(b.half_extents[2]) * magnitude(arith::dot(n, arith::lift(l, b.axes[2])));
    return farthest ? gap - r : gap + r;
}

// Does the box meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool obb_meets(K& k, const obb3& b, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !sat::well_formed(b) || !finite(b)) return false;
    for (int i = 0; i < m; ++i) { // a plane with the whole box beyond it
        const plane3 h = planes[i];
        if (k.sgn([=](auto L) { return box_reach(L, b, h, false); }) == sign::negative) return false;
    }
    bool centre = true; // the centre inside every plane
    for (int i = 0; i < m && centre; ++i) {
        const plane3 h = planes[i];
        centre = k.sgn([=](auto L) { return L(h.offset) * L(1.0) - arith::dot(arith::lift(L, h.normal), arith::lift(L, b.center)); }) !=
                 sign::negative;
    }
    if (centre) return true;
    const sign axes = settled(k, [=](auto L) { return arith::det3(arith::lift(L, b.axes[0]), arith::lift(L, b.axes[1]), arith::lift(L, b.axes[2])); });
    return first_row_vertex(k, frame_rows{planes, static_cast<unsigned>(m), &b, axes}).found;
}
// Is the whole box inside the m half-spaces? (Every plane read, so a NaN gives no in the exact tier.)
template <class K>
[[nodiscard]] constexpr bool obb_inside(K& k, const obb3& b, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !sat::well_formed(b) || !finite(b)) return false;
    bool all = true;
    for (int i = 0; i < m; ++i) {
        const plane3 h = planes[i];
        all = k.sgn([=](auto L) { return box_reach(L, b, h, true); }) != sign::negative && all;
    }
    return all;
}

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const obb3& b) {
    return polyq::obb_meets(k, b, c.planes.data(), c.count);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const obb3& b) {
    return polyq::obb_inside(k, b, c.planes.data(), c.count);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const obb3&);
extern template bool contains(arith::exact_kernel&, const convex_polyhedron3&, const obb3&);
} // namespace incidence::pair
