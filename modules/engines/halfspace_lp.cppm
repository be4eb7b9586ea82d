// aabb3 against convex_polyhedron3, contains(convex_polyhedron3, aabb3), and the half-space
// feasibility test the other half-space pairs share: with a box (aabb_frustum), and of possibly
// unbounded sets (polyq::feasible: convex_polyhedron_plane, frustum_plane).
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the closed
// half-space set of convex_polyhedron_point.cppm (possibly empty or unbounded; a non-finite number
// or a count outside [0, capacity]: no set). Touching at a face, an edge or a vertex counts.
// contains(polyhedron, box): the eight corners in the set (it is convex).
// Method (exact tiers): the box is six more half-spaces, and the intersection of all of them is
// bounded, so when it is not empty it has a vertex: three of the planes, with independent normals,
// meet at a point v = V / D inside every half-space, where D = det(n_i, n_j, n_k) and
// V = c_i n_j x n_k + c_j n_k x n_i + c_k n_i x n_j; n_l . v <= c_l iff sign(c_l D - n_l . V) is
// zero or sign(D). The test tries every triple: homogeneous signs of degree 4, no division. At run
// time guesses come first: a linear program in plain double names a vertex, or at most four rows
// with no common point, which the same signs then prove or refute (polyq::first_row_vertex; rows
// with no three independent normals by their lines or planes, polyq::low_rank_empty); up to three
// programs, each along its own direction with the rows in its own order (polyq::guess_paths).
// First, a polyhedron plane with the whole box beyond it (the corner least along n_i outside, a
// sign of degree 2) says no; then a point of the box strictly inside every plane (the box's middle,
// rounded and clamped into it, or for a plane the middle is not inside, the box's corner least
// along its normal: signs of degree 2, tried only where the filter proves them) says yes (the
// culling tests' two outcomes, Assarsson and Moeller, JGT 5(1), 2000, section 3); then, for at
// most six planes, a plane that two of them imply along an edge-edge axis of the
// separating-axis test (Gottschalk, Lin and Manocha, SIGGRAPH 1996, section 5) with the box wholly
// beyond it says no (signs of degree 3, tried only where the filter proves them: edge_planes).
// Source: vertex enumeration for LP feasibility (Schrijver, Theory of Linear and Integer
// Programming, 1986, section 8.5: a nonempty pointed polyhedron has a vertex); the guess, Seidel,
// "Small-dimensional linear programming and convex hulls made easy", Discrete Comput. Geom. 6, 1991.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_convex_polyhedron.cpp).
//
// convex_polyhedron3 against plane3.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the plane
// n . x = offset (a zero normal is everything when the offset is 0 and nothing otherwise; a
// non-finite number: no set). Touching at a vertex, an edge or a face counts.
// Method (exact tiers): a convex set meets the plane iff it has points on both closed sides. Each
// side is first tried at the set's vertex least or greatest along n, guessed in double and proven
// with signs of degree <= 4: that vertex strictly inside and strictly beyond the plane says yes;
// its three planes' multipliers for n all positive (a Farkas certificate that nothing of the set
// goes further) with the vertex short of the plane says no. Undecided sides (touching, unbounded,
// degenerate) get a half-space feasibility test (polyq::feasible in aabb_convex_polyhedron.cppm)
// of the set with n . x <= offset or -n . x <= -offset, which tries the minimal faces (vertices,
// lines or planes, by the rank of the normals): homogeneous signs of degree <= 5.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, sections 7.3 (Farkas) and 8.5
// (minimal faces).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_plane.cpp).
//
// convex_polyhedron3 against convex_polyhedron3, and the test of two half-space sets that
// convex_polyhedron_frustum shares.
// Semantics: two closed half-space sets of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set). Touching at a vertex,
// an edge or a face counts.
// Method (exact tiers): the two sets meet iff the half-spaces of both together are feasible.
// At run time, with more than twelve planes in all, the exact feasibility test of all the
// half-spaces together at once (its linear program's guess first). Otherwise first, a face of
// either set with the other set wholly beyond it says no: the other set's vertex least along the
// face normal, guessed in double, short of the face, with its three planes' multipliers for the
// normal all positive (a Farkas certificate), signs of degree <= 4. Then a point strictly inside
// both says yes: the mean of the vertices of each set that lie in the other, guessed in double and
// proven with signs of degree 2. Otherwise the exact feasibility test of all the half-spaces
// together (polyq::feasible in aabb_convex_polyhedron.cppm: the minimal faces
// by the rank of the normals, signs of degree <= 5).
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, sections 7.3 (Farkas) and 8.5
// (minimal faces).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_convex_polyhedron.cpp).
//
// frustum3 against frustum3.
// Semantics: two closed view volumes of six half-spaces each (shapes/frustum3.cppm; a non-finite
// number: no set). Touching at a vertex, an edge or a face counts.
// Method (exact tiers): the test of two half-space sets (convex_polyhedron_convex_polyhedron.cppm):
// a face of either with the other wholly beyond it (a Farkas certificate) says no, a point proven
// strictly inside both says yes, else the exact feasibility test of all twelve half-spaces
// together: signs of degree <= 5. The two frustums go in a fixed order, so every tier answers the
// same for both argument orders.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, sections 7.3 and 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_frustum.cpp).
module;
#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>
export module incidence.detail:engines.halfspace_lp;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.box;
import :engines.halfspace_slabs;

export namespace incidence::detail {

namespace halfspaces {

// A zero normal; two normals equal or opposite (the box's faces across one axis, a frustum's near
// and far planes, a repeated plane): no single point where they meet, known without a sign (which
// the filter could not prove zero).
[[nodiscard]] constexpr bool zero_normal(const plane3* rows, unsigned x) {
    const vec3 a = rows[x].normal;
    return a.x == 0 && a.y == 0 && a.z == 0;
}
[[nodiscard]] constexpr bool parallel_normals(const plane3* rows, unsigned x, unsigned y) {
    const vec3 a = rows[x].normal, c = rows[y].normal;
    return (a.x == c.x && a.y == c.y && a.z == c.z) || (a.x == -c.x && a.y == -c.y && a.z == -c.z);
}

// The rows a vertex search reads: row x is the half-space normal(L, x) . v <= offset(L, x), with
// zero(x) and parallel(x, y) known without a sign; rows may say the sign of the determinant of
// three normals themselves (triple_sign(k, i, j, l, det), det its lifted expression) and the
// decided sign of a fourth row at their vertex (beyond_sign(k, i, j, l, h, f), f its expression).
// plane_rows reads plane3 values as they are; frame_rows (convex_polyhedron_obb.cppm) reads a set
// in a box's own coordinates.
struct plane_rows {
    const plane3* p;
    unsigned total;
    [[nodiscard]] constexpr unsigned size() const { return total; }
    [[nodiscard]] constexpr bool zero(unsigned x) const { return zero_normal(p, x); }
    [[nodiscard]] constexpr bool parallel(unsigned x, unsigned y) const { return parallel_normals(p, x, y); }
    template <class L>
    [[nodiscard]] constexpr auto normal(L l, unsigned x) const {
        return arith::lift(l, p[x].normal);
    }
    template <class L>
    [[nodiscard]] constexpr auto offset(L l, unsigned x) const {
        return l(p[x].offset);
    }
};

// A vertex of the set of the `total` half-spaces n_i . x <= c_i: rows i, j and l, with
// independent normals, meet at v = V / D inside every half-space, where D = det(n_i, n_j, n_l) and
// V = c_i n_j x n_l + c_j n_l x n_i + c_l n_i x n_j (vertex_numerator); n_h . v <= c_h iff
// sign(c_h D - n_h . V) is zero or sign(D): homogeneous signs (degree 4 for plane3 rows).
// `independent`: some three normals are independent (the set, when not empty, then has a vertex).
struct row_vertex {
    bool found = false, independent = false;
    unsigned i = 0, j = 0, l = 0;
    sign d = sign::zero;
};
struct set_vertex {
    bool found = false, independent = false;
    plane3 i{}, j{}, l{};
    sign d = sign::zero;
};
template <class L>
[[nodiscard]] constexpr auto vertex_numerator(L lift, const plane3& a, const plane3& c, const plane3& e) {
    const auto na = arith::lift(lift, a.normal), nc = arith::lift(lift, c.normal), ne = arith::lift(lift, e.normal);
    const auto one = lift(1.0);
    const auto ca = lift(a.offset) * one, cc = lift(c.offset) * one, ce = lift(e.offset) * one;
    const auto x = arith::cross(nc, ne), y = arith::cross(ne, na), z = arith::cross(na, nc);
    using T = decltype(ca * x.x + cc * y.x + ce * z.x);
    return arith::v3<T>{ca * x.x + cc * y.x + ce * z.x, ca * x.y + cc * y.y + ce * z.y, ca * x.z + cc * y.z + ce * z.z};
}
// c_h D - n_h . V for rows i, j and l meeting at V / D and a fourth row h, as three dot products
// with the cross products: the 4 x 4 determinant of the rows (n, c).
template <class L, class Rows>
[[nodiscard]] constexpr auto four_rows(L lift, const Rows& rows, unsigned i, unsigned j, unsigned l, unsigned h) {
    const auto na = rows.normal(lift, i), nc = rows.normal(lift, j), ne = rows.normal(lift, l), nh = rows.normal(lift, h);
    const auto x = arith::cross(nc, ne);
    return rows.offset(lift, h) * arith::dot(na, x) -
           (rows.offset(lift, i) * arith::dot(nh, x) + rows.offset(lift, j) * arith::dot(nh, arith::cross(ne, na)) +
            rows.offset(lift, l) * arith::dot(nh, arith::cross(na, nc)));
}
// Is the point where rows i, j and l meet (independent normals) inside every row? found and
// independent say so, with d = sign(D); independent alone: they meet at one point, outside.
template <class K, class Rows>
[[nodiscard]] constexpr row_vertex vertex_of_rows(K& k, const Rows& rows, unsigned i, unsigned j, unsigned l) {
    row_vertex found;
    if (rows.zero(i) || rows.zero(j) || rows.zero(l) || rows.parallel(i, j) || rows.parallel(i, l) || rows.parallel(j, l)) return found;
    auto det = [=](auto L) { return arith::det3(rows.normal(L, i), rows.normal(L, j), rows.normal(L, l)); };
    sign d;
    if constexpr (requires { rows.triple_sign(k, i, j, l, det); }) d = rows.triple_sign(k, i, j, l, det);
    else d = arith::sgn<arith::hint::often_zero>(k, det);
    if (d == sign::zero) return found; // no single point
    found.independent = true;
    // V and D, lifted once into the filter for every row's condition (the same values each
    // condition would lift again)
    auto vertex = [=](auto L) {
        const auto na = rows.normal(L, i), nc = rows.normal(L, j), ne = rows.normal(L, l);
        const auto ca = rows.offset(L, i), cc = rows.offset(L, j), ce = rows.offset(L, l);
        const auto x = arith::cross(nc, ne), y = arith::cross(ne, na), z = arith::cross(na, nc);
        using T = decltype(ca * x.x + cc * y.x + ce * z.x);
        return std::pair{arith::v3<T>{ca * x.x + cc * y.x + ce * z.x, ca * x.y + cc * y.y + ce * z.y, ca * x.z + cc * y.z + ce * z.z},
                         arith::dot(na, x)};
    };
    const arith::lifted_once<K, decltype(vertex)> vl{vertex};
    auto beyond = [=, &vl](unsigned r) { // c_h D - n_h . V
        return [=, &vl](auto L) {
            if constexpr (arith::lifts_filter<K>()) {
                const auto& [V, D] = vl(L);
                return rows.offset(L, r) * D - arith::dot(rows.normal(L, r), V);
            } else {
                (void)vl;
                return four_rows(L, rows, i, j, l, r);
            }
        };
    };
    // each row's sign by the filter once: a row it proves the vertex outside of rejects it before
    // any sign is decided (a zero sign elsewhere, such as a fourth plane through the same point,
    // would otherwise end the filter's run); the rows it cannot prove are decided after
    const unsigned total = rows.size();
    std::uint64_t open[2] = {0, 0}; // rows 0 to 127 the filter left open (rows beyond: always decided)
    for (unsigned r = 0; r < total; ++r) {
        if (r == i || r == j || r == l) continue;
        const sign s = arith::sgn<arith::hint::optional>(k, beyond(r));
        if (s == -d) return found;
        if (s == sign::zero && r < 128) open[r / 64] |= std::uint64_t{1} << (r % 64);
    }
    for (unsigned r = 0; r < total; ++r) {
        if (r == i || r == j || r == l || (r < 128 && (open[r / 64] >> (r % 64) & 1) == 0)) continue;
        // decided: a fourth plane through the vertex, or an ulp off it (a k-DOP's rounded-out
        // offsets), is common; an exact zero the cheap stages cannot settle is computed in place
        const sign s = [&] {
            if constexpr (requires { rows.beyond_sign(k, i, j, l, r, beyond(r)); }) return rows.beyond_sign(k, i, j, l, r, beyond(r));
            else return arith::sgn<arith::hint::decisive>(k, beyond(r));
        }();
        if (s != sign::zero && s != d) return found;
    }
    found.found = true;
    found.i = i, found.j = j, found.l = l, found.d = d;
    return found;
}
// Every triple of rows in turn: the first vertex inside every row.
template <class K, class Rows>
[[nodiscard]] constexpr row_vertex search_row_vertex(K& k, const Rows& rows) {
    row_vertex found;
    const unsigned total = rows.size();
    for (unsigned i = 0; i < total; ++i)
        for (unsigned j = i + 1; j < total; ++j)
            for (unsigned l = j + 1; l < total; ++l) {
                const row_vertex v = vertex_of_rows(k, rows, i, j, l);
                if (v.found) return v;
                found.independent = found.independent || v.independent;
            }
    return found;
}

// Seidel's randomised incremental linear programming in plain double (Seidel, "Small-dimensional
// linear programming and convex hulls made easy", Discrete Comput. Geom. 6, 1991), for a guess
// only: the rows through the least point of the set along a fixed generic direction inside a box
// of half-width 2^200, or at most four rows with no common point. first_row_vertex proves a guess
// with the exact signs before it counts and searches every triple where it does not hold.
namespace seidel_lp {
inline constexpr unsigned box_face = ~0u; // a face of the box, not a row
inline constexpr unsigned max_rows = 2 * convex_polyhedron3::capacity + 8;
inline constexpr double half_width = 0x1p200;
template <int D>
struct row { // no initialisers: the arrays of rows are written before they are read
    std::array<double, D> a;
    double b;
    unsigned id;
};
template <int D>
struct result {
    bool feasible = true;
    std::array<double, D> x{};
    std::array<unsigned, D> tight{};   // the rows through x
    std::array<unsigned, D + 1> why{}; // infeasible: rows with no common point
    int nwhy = 0;
};
// minimise f . x over the box and the n rows a . x <= b, taken in their order
template <int D>
[[nodiscard]] constexpr result<D> solve(const row<D>* rows, unsigned n, const std::array<double, D>& f) {
    result<D> out;
    if constexpr (D == 1) {
        double lo = -half_width, hi = half_width;
        unsigned ilo = box_face, ihi = box_face;
        for (unsigned i = 0; i < n; ++i) {
            const double a = rows[i].a[0], b = rows[i].b;
            if (a > 0.0 && b / a < hi) hi = b / a, ihi = rows[i].id;
            else if (a < 0.0 && b / a > lo) lo = b / a, ilo = rows[i].id;
            else if (a == 0.0 && b < 0.0) {
                out.feasible = false, out.why[0] = rows[i].id, out.nwhy = 1;
                return out;
            }
        }
        if (lo > hi) {
            out.feasible = false, out.why = {ilo, ihi}, out.nwhy = 2;
            return out;
        }
        const bool low = !(f[0] < 0.0);
        out.x[0] = low ? lo : hi, out.tight[0] = low ? ilo : ihi;
        return out;
    } else {
        for (int c = 0; c < D; ++c) out.x[c] = f[c] > 0.0 ? -half_width : half_width, out.tight[c] = box_face;
        for (unsigned i = 0; i < n; ++i) {
            const row<D>& r = rows[i];
            double s = 0.0;
            for (int c = 0; c < D; ++c) s += r.a[c] * out.x[c];
            if (!(s > r.b)) continue;
            // the least point now lies on r's plane: x_e eliminated, |a_e| the largest
            int e = 0;
            for (int c = 1; c < D; ++c)
                if (arith::abs(r.a[static_cast<unsigned>(c)]) > arith::abs(r.a[static_cast<unsigned>(e)])) e = c;
            if (!(arith::abs(r.a[static_cast<unsigned>(e)]) > 0.0)) {
                out.feasible = false, out.why[0] = r.id, out.nwhy = 1;
                return out;
            }
            auto project = [&](const std::array<double, D>& a, double b, unsigned id) {
                const double q = a[static_cast<unsigned>(e)] / r.a[static_cast<unsigned>(e)];
                row<D - 1> p{{}, b - q * r.b, id};
                for (int c = 0, m = 0; c < D; ++c)
                    if (c != e) p.a[static_cast<unsigned>(m++)] = a[static_cast<unsigned>(c)] - q * r.a[static_cast<unsigned>(c)];
                return p;
            };
            std::array<row<D - 1>, max_rows + 2> sub;
            std::array<double, D> unit{};
            unit[static_cast<unsigned>(e)] = 1.0;
            sub[0] = project(unit, half_width, box_face);
            unit[static_cast<unsigned>(e)] = -1.0;
            sub[1] = project(unit, half_width, box_face);
            for (unsigned j = 0; j < i; ++j) sub[j + 2] = project(rows[j].a, rows[j].b, rows[j].id);
            const row<D - 1> pf = project(f, 0.0, box_face);
            const result<D - 1> lower = solve<D - 1>(sub.data(), i + 2, pf.a);
            if (!lower.feasible) {
                out.feasible = false, out.why[0] = r.id, out.nwhy = lower.nwhy + 1;
                for (int w = 0; w < lower.nwhy; ++w) out.why[static_cast<unsigned>(w + 1)] = lower.why[static_cast<unsigned>(w)];
                return out;
            }
            double xe = r.b;
            for (int c = 0, m = 0; c < D; ++c)
                if (c != e) {
                    out.x[static_cast<unsigned>(c)] = lower.x[static_cast<unsigned>(m)];
                    xe -= r.a[static_cast<unsigned>(c)] * lower.x[static_cast<unsigned>(m++)];
                }
            out.x[static_cast<unsigned>(e)] = xe / r.a[static_cast<unsigned>(e)];
            out.tight[0] = r.id;
            for (int c = 0; c + 1 < D; ++c) out.tight[static_cast<unsigned>(c + 1)] = lower.tight[static_cast<unsigned>(c)];
        }
        return out;
    }
}
// The guess for the rows: a vertex (three rows), rows with no common point (n of them), or none.
struct guess {
    bool vertex = false;
    std::array<unsigned, 4> r{};
    unsigned n = 0;
    std::array<double, 3> x{}; // the vertex
};
inline constexpr std::array<double, 3> generic_direction{1.0, 0x1.6a09e667f3bcdp-1, 0x1.279a74590331cp-2};
// f: the direction to minimise along; seed: the order the rows are taken in
inline constexpr std::uint64_t first_seed = 0x9e3779b97f4a7c15u;
template <class Rows>
[[nodiscard]] constexpr guess guess_of(const Rows& rows, const std::array<double, 3>& f = generic_direction,
                                       std::uint64_t seed = first_seed) {
    const unsigned total = rows.size();
    if (total > max_rows) return {};
    // The program is solved in y = x / 2^place, each row divided by 2^k, k the exponent of its
    // largest normal component (both exact, barring underflow), where those exponents pass 2^7: a
    // set far from the unit scale (beyond the box's half-width 2^200, or tiny; the tests scale by
    // 2^-500..2^500) would otherwise end on the box, and every guess on the search of every triple.
    // place: the exponent of the largest |offset| over the least largest normal component. Nearer
    // the unit scale nothing is scaled.
    constexpr int near_unit = 128;
    auto largest = [](double a, double b, double c) {
        const double m = arith::abs(a) > arith::abs(b) ? arith::abs(a) : arith::abs(b);
        return m > arith::abs(c) ? m : arith::abs(c);
    };
    auto exponent = [](double m) { return is_finite(m) && m != 0.0 ? arith::exponent_of(m) : 0; };
    auto far = [](int e) { return e < -near_unit || e > near_unit; };
    double most_offset = 0.0, least_normal = 0.0, most_normal = 0.0;
    for (unsigned x = 0; x < total; ++x) {
        if (rows.zero(x)) continue;
        const auto v = rows.normal(arith::lift_double{}, x);
        const double m = largest(v.x, v.y, v.z), c = arith::abs(rows.offset(arith::lift_double{}, x));
        if (c > most_offset) most_offset = c;
        if (m > most_normal) most_normal = m;
        if (least_normal == 0.0 || m < least_normal) least_normal = m;
    }
    const bool scale_rows = far(exponent(least_normal)) || far(exponent(most_normal));
    int place = most_offset > 0.0 ? exponent(most_offset) - exponent(least_normal) : 0; // at most the rows' own
    if (scale_rows) {                                                                   // each row's own, its normal scaled
        place = 0;
        bool placed = false;
        for (unsigned x = 0; x < total; ++x) {
            if (rows.zero(x)) continue;
            const auto v = rows.normal(arith::lift_double{}, x);
            const double c = rows.offset(arith::lift_double{}, x);
            if (c == 0.0 || !is_finite(c)) continue;
            const int e = exponent(c) - exponent(largest(v.x, v.y, v.z));
            if (!placed || e > place) place = e, placed = true;
        }
    }
    if (!far(place)) place = 0;
    auto scaled = [](double a, int by) { return by == 0 ? a : arith::scale_by_power_of_two(a, by); };
    std::array<row<3>, max_rows> in;
    unsigned n = 0;
    for (unsigned x = 0; x < total; ++x) {
        if (rows.zero(x)) continue;
        const auto v = rows.normal(arith::lift_double{}, x);
        const int k = scale_rows ? exponent(largest(v.x, v.y, v.z)) : 0;
        in[n++] = row<3>{{scaled(v.x, -k), scaled(v.y, -k), scaled(v.z, -k)}, scaled(rows.offset(arith::lift_double{}, x), -k - place), x};
    }
    // a fixed shuffle (xorshift), the same on every call: the expected linear time of a random order
    std::uint64_t s = seed;
    for (unsigned i = n; i > 1; --i) {
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        const auto j = static_cast<unsigned>(s % i);
        const row<3> t = in[i - 1];
        in[i - 1] = in[j], in[j] = t;
    }
    const result<3> r = solve<3>(in.data(), n, f);
    guess g;
    if (r.feasible) {
        g.vertex = true, g.n = 3;
        for (unsigned c = 0; c < 3; ++c) g.x[c] = scaled(r.x[c], place);
        for (unsigned c = 0; c < 3; ++c) g.r[c] = r.tight[c];
    } else {
        g.n = static_cast<unsigned>(r.nwhy);
        for (unsigned c = 0; c < g.n; ++c) g.r[c] = r.why[c];
    }
    for (unsigned c = 0; c < g.n; ++c)
        if (g.r[c] == box_face) return {};
    return g;
}
} // namespace seidel_lp

// Some of the rows, by their indices in `at`.
template <class Rows>
struct picked_rows {
    const Rows* rows;
    std::array<unsigned, 4> at;
    unsigned n;
    [[nodiscard]] constexpr unsigned size() const { return n; }
    [[nodiscard]] constexpr bool zero(unsigned x) const { return rows->zero(at[x]); }
    [[nodiscard]] constexpr bool parallel(unsigned x, unsigned y) const { return rows->parallel(at[x], at[y]); }
    template <class L>
    [[nodiscard]] constexpr auto normal(L l, unsigned x) const {
        return rows->normal(l, at[x]);
    }
    template <class L>
    [[nodiscard]] constexpr auto offset(L l, unsigned x) const {
        return rows->offset(l, at[x]);
    }
    template <class K, class Det>
    requires requires(const Rows& r, K& k, const Det& det) { r.triple_sign(k, 0u, 1u, 2u, det); }
    [[nodiscard]] constexpr sign triple_sign(K& k, unsigned i, unsigned j, unsigned l, const Det& det) const {
        return rows->triple_sign(k, at[i], at[j], at[l], det);
    }
};

// Is the set of the rows empty, when no three of their normals are independent? Its minimal faces
// are then the lines where two planes with independent normals meet, or the planes themselves when
// every normal is parallel to one (Schrijver 1986, section 8.5): empty iff none lies in every row.
// The line of rows i and j is V / D with w = n_i x n_j, V = c_i n_j x w + c_j w x n_i, D = w . w > 0;
// the plane of row i is V / D with V = c_i n_i, D = n_i . n_i. Signs of degree 5 and 3 for plane3
// rows, decided in place (hint::decisive: a guessed subset's line often lies on its third plane,
// to rounding). false: not empty, or all normals zero.
template <class K, class Rows>
[[nodiscard]] constexpr bool low_rank_empty(K& k, const Rows& rows) {
    const unsigned total = rows.size();
    bool pair = false;
    for (unsigned i = 0; i < total; ++i) {
        if (rows.zero(i)) continue;
        for (unsigned j = i + 1; j < total; ++j) {
            if (rows.zero(j) || rows.parallel(i, j)) continue;
            auto w = [=](auto L) { return arith::cross(rows.normal(L, i), rows.normal(L, j)); };
            if (arith::sgn<arith::hint::often_zero>(k, [=](auto L) { return w(L).x; }) == sign::zero &&
                arith::sgn<arith::hint::often_zero>(k, [=](auto L) { return w(L).y; }) == sign::zero &&
                arith::sgn<arith::hint::often_zero>(k, [=](auto L) { return w(L).z; }) == sign::zero)
                continue;
            pair = true;
            bool inside = true;
            for (unsigned r = 0; r < total && inside; ++r) {
                if (r == i || r == j) continue;
                inside = arith::sgn<arith::hint::decisive>(k, [=](auto L) {
                             const auto wv = w(L);
                             const auto nh = rows.normal(L, r);
                             return rows.offset(L, r) * arith::dot(wv, wv) - (rows.offset(L, i) * arith::det3(nh, rows.normal(L, j), wv) +
                                                                              rows.offset(L, j) * arith::det3(nh, wv, rows.normal(L, i)));
                         }) != sign::negative;
            }
            if (inside) return false;
        }
    }
    if (pair) return true;
    bool any = false;
    for (unsigned i = 0; i < total; ++i) {
        if (rows.zero(i)) continue;
        any = true;
        bool inside = true;
        for (unsigned r = 0; r < total && inside; ++r) {
            if (r == i) continue;
            inside = arith::sgn<arith::hint::decisive>(k, [=](auto L) {
                         const auto ni = rows.normal(L, i);
                         return rows.offset(L, r) * arith::dot(ni, ni) - rows.offset(L, i) * arith::dot(rows.normal(L, r), ni);
                     }) != sign::negative;
        }
        if (inside) return false;
    }
    return any;
}

// The guesses in turn, each minimising along its own direction with the rows in its own order: the
// rounded program can name rows that do meet (three k-DOP planes with dependent normals, such as
// (1, 0, 0), (0, 1, 1) and (1, 1, 1)) or a vertex the signs refute, and another direction and
// order take another path through the rows; the full search of every triple comes only after.
struct guess_path {
    std::array<double, 3> f;
    std::uint64_t seed;
};
inline constexpr std::array<guess_path, 3> guess_paths{
    guess_path{seidel_lp::generic_direction, seidel_lp::first_seed},
    guess_path{{-0x1.279a74590331cp-2, 1.0, -0x1.6a09e667f3bcdp-1}, 0xd1b54a32d192ed03u},
    guess_path{{0x1.6a09e667f3bcdp-1, -0x1.279a74590331cp-2, -1.0}, 0x8cb92ba72f3d8dd7u},
};
// The guess of seidel_lp::guess_of along one path, proven with the kernel's signs: a vertex inside every row
// (the three rows the guess ended on, or three of the rows through its point, to rounding), or
// rows with no common point (their triples, or their lines or planes when no three are
// independent). true when proven, with the answer in v. A program that ended on its box (no
// guess) is tried along the other paths as well: in near-degenerate bounded sets a rounded
// program ends there too, and stopping at it cost more on the 26-DOP pairs than it gained
// elsewhere (bench/NOTES.md, "Measured choices").
template <class K, class Rows>
[[nodiscard]] constexpr bool proven_guess(K& k, const Rows& rows, const guess_path& path, row_vertex& v) {
    const seidel_lp::guess g = seidel_lp::guess_of(rows, path.f, path.seed);
    if (!g.vertex && g.n == 0) return false;
    if (g.vertex) {
        if (v = vertex_of_rows(k, rows, g.r[0], g.r[1], g.r[2]); v.found) return true;
        // more than three rows through the vertex (a k-DOP's corner), where the three the guess
        // ended on may be dependent: the triples of the rows through it, to rounding
        std::array<unsigned, 8> through{};
        unsigned m = 0;
        for (unsigned x = 0; x < rows.size() && m < through.size(); ++x) {
            if (rows.zero(x)) continue;
            const auto n = rows.normal(arith::lift_double{}, x);
            const double c = rows.offset(arith::lift_double{}, x);
            const double gap = n.x * g.x[0] + n.y * g.x[1] + n.z * g.x[2] - c;
            const double scale = arith::abs(n.x * g.x[0]) + arith::abs(n.y * g.x[1]) + arith::abs(n.z * g.x[2]) + arith::abs(c);
            if (arith::abs(gap) <= 0x1p-30 * scale) through[m++] = x;
        }
        for (unsigned a = 0; a < m; ++a)
            for (unsigned b = a + 1; b < m; ++b)
                for (unsigned c = b + 1; c < m; ++c)
                    if (v = vertex_of_rows(k, rows, through[a], through[b], through[c]); v.found) return true;
    } else {
        const picked_rows<Rows> picked{&rows, g.r, g.n};
        v = search_row_vertex(k, picked);
        if (!v.found && v.independent) return true;
        // no three of them independent (two parallel planes facing apart, three normals in
        // one plane): their lines or planes
        if (!v.found && low_rank_empty(k, picked)) {
            v.independent = true;
            return true;
        }
    }
    return false;
}
// A vertex of the set of the rows, or that there is none: at run time the guesses of
// proven_guess first, then every triple in turn. Any vertex found is one of the set's; found
// false with independent true: the set is empty.
template <class K, class Rows>
[[nodiscard]] constexpr row_vertex first_row_vertex(K& k, const Rows& rows) {
    if (!__builtin_is_constant_evaluated())
        for (const guess_path& path : guess_paths)
            if (row_vertex v; proven_guess(k, rows, path, v)) return v;
    return search_row_vertex(k, rows);
}
template <class K>
[[nodiscard]] constexpr set_vertex first_vertex(K& k, const plane3* rows, unsigned total) {
    const row_vertex v = first_row_vertex(k, plane_rows{rows, total});
    set_vertex found;
    found.found = v.found, found.independent = v.independent, found.d = v.d;
    if (v.found) found.i = rows[v.i], found.j = rows[v.j], found.l = rows[v.l];
    return found;
}

// Is the set of the `total` half-spaces n_i . x <= c_i (finite numbers) not empty? It may be
// unbounded. A nonempty set's minimal faces are {x : n_i . x = c_i for i in I} with rank(n_I) the
// rank r of all the normals (Schrijver 1986, section 8.5), so one such face point lies in every
// half-space: for r = 3 a vertex, three planes with independent normals (first_vertex); for r = 2
// a line where two planes meet; for r = 1 a plane. Each candidate point is V / D, tested as
// sign(c_l D - n_l . V) (zero or sign(D)): homogeneous signs of degree 4 (vertices), 5 (lines) and
// 3 (planes).
template <class K>
[[nodiscard]] constexpr bool feasible(K& k, const plane3* rows, unsigned total) {
    // a zero normal is all of space (offset >= 0) or nothing: a comparison
    for (unsigned i = 0; i < total; ++i)
        if (zero_normal(rows, i) && rows[i].offset < 0) return false;
    // r = 3: the vertices
    const set_vertex v = first_vertex(k, rows, total);
    if (v.found) return true;
    if (v.independent) return false; // some three normals independent, and no vertex
    // r = 2 (the lines where two planes meet), r = 1 (the planes), r = 0 (all of space)
    return !low_rank_empty(k, plane_rows{rows, total});
}

// The planes that two of the half-spaces imply along the separating-axis test's edge-edge axes:
// for planes i < j and a box axis a where n_i[a] and n_j[a] have strictly opposite signs,
// g = |n_j[a]| n_i + |n_i[a]| n_j (a multiple of (n_i x n_j) x e_a, so g[a] = 0) bounds the set by
// g . x <= |n_j[a]| c_i + |n_i[a]| c_j (a sum of its half-spaces with weights >= 0). Kept: the axes
// whose two other components of g have a proven sign (degree 2), which names the box corner least
// along g (upper[b]: take max[b]; min on axis a). For at most six planes (a frustum's fifteen pairs).
struct implied_plane {
    int i, j;
    double alpha, beta; // |n_j[a]|, |n_i[a]|
    bool upper[3];
};
struct implied_planes {
    std::array<implied_plane, 45> at{};
    int n = 0;
};
template <class K>
[[nodiscard]] constexpr implied_planes edge_planes(K& k, const plane3* planes, int m) {
    auto at = [](vec3 v, int a) { return a == 0 ? v.x : (a == 1 ? v.y : v.z); };
    implied_planes out;
    if (m > 6) return out;
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            for (int a = 0; a < 3; ++a) {
                const vec3 ni = planes[i].normal, nj = planes[j].normal;
                if (!((at(ni, a) > 0 && at(nj, a) < 0) || (at(ni, a) < 0 && at(nj, a) > 0))) continue;
                implied_plane e{i, j, arith::abs(at(nj, a)), arith::abs(at(ni, a)), {false, false, false}};
                bool proven = true;
                for (int b = 0; b < 3 && proven; ++b) {
                    if (b == a) continue;
                    const double x = at(ni, b), y = at(nj, b);
                    const sign s = arith::sgn<arith::hint::optional>(k, [=](auto L) { return L(e.alpha) * L(x) + L(e.beta) * L(y); });
                    proven = s != sign::zero;
                    e.upper[b] = s == sign::negative;
                }
                if (proven) out.at[static_cast<unsigned>(out.n++)] = e;
            }
    return out;
}
// The sign of |n_j[a]| (c_i - n_i . q) + |n_i[a]| (c_j - n_j . q) at the box corner q that e names:
// negative says the box lies wholly beyond the implied plane. Degree 3.
template <class K>
[[nodiscard]] constexpr sign implied_side(K& k, const aabb3& b, const plane3* planes, const implied_plane& e) {
    const point3 q{e.upper[0] ? b.max.x : b.min.x, e.upper[1] ? b.max.y : b.min.y, e.upper[2] ? b.max.z : b.min.z};
    const plane3 p = planes[e.i], h = planes[e.j];
    const double alpha = e.alpha, beta = e.beta;
    return arith::sgn<arith::hint::optional>(k, [=](auto L) {
        const auto Q = arith::lift(L, q);
        return L(alpha) * (L(p.offset) * L(1.0) - arith::dot(arith::lift(L, p.normal), Q)) +
               L(beta) * (L(h.offset) * L(1.0) - arith::dot(arith::lift(L, h.normal), Q));
    });
}

// Does the box meet the m half-spaces n_i . x <= c_i (m <= convex_polyhedron3::capacity)?
template <class K>
[[nodiscard]] constexpr bool box_meets(K& k, const aabb3& b, const plane3* planes, int m) {
    constexpr int capacity = convex_polyhedron3::capacity;
    if (!well_formed(planes, m, capacity) || !well_formed_finite(b)) return false;
    // A plane with the whole box beyond it: the box corner least along its normal is outside.
    for (int i = 0; i < m; ++i) {
        const plane3 p = planes[i];
        const point3 q = least_corner(b, p.normal);
        if (k.sgn([=](auto L) { return L(p.offset) * L(1.0) - arith::dot(arith::lift(L, p.normal), arith::lift(L, q)); }) == sign::negative)
            return false;
    }
    // A point of the box strictly inside every plane: checks whose failure decides nothing. The
    // middle, then for each plane it is not proven inside, the box corner least along that normal.
    auto inside_from = [&](point3 c, int first) {
        for (int i = first; i < m; ++i) {
            const plane3 p = planes[i];
            if (arith::sgn<arith::hint::optional>(k, [=](auto L) {
                    return L(p.offset) * L(1.0) - arith::dot(arith::lift(L, p.normal), arith::lift(L, c));
                }) != sign::positive)
                return i;
        }
        return m;
    };
    const point3 c = middle_in(b);
    int outside = inside_from(c, 0);
    if (outside == m) return true;
    for (; outside < m; outside = inside_from(c, outside + 1))
        if (inside_from(least_corner(b, planes[outside].normal), 0) == m) return true;
    // A plane two of them imply with the whole box beyond it: checks whose failure decides nothing.
    const implied_planes implied = edge_planes(k, planes, m);
    for (int t = 0; t < implied.n; ++t)
        if (implied_side(k, b, planes, implied.at[static_cast<unsigned>(t)]) == sign::negative) return false;
    // The rows: the polyhedron's planes, then the box's six faces (bounded: the vertex case).
    std::array<plane3, capacity + 6> rows{};
    for (int i = 0; i < m; ++i) rows[static_cast<unsigned>(i)] = planes[i];
    const auto n = static_cast<unsigned>(m);
    rows[n + 0] = plane3{{1, 0, 0}, b.max.x};
    rows[n + 1] = plane3{{-1, 0, 0}, -b.min.x};
    rows[n + 2] = plane3{{0, 1, 0}, b.max.y};
    rows[n + 3] = plane3{{0, -1, 0}, -b.min.y};
    rows[n + 4] = plane3{{0, 0, 1}, b.max.z};
    rows[n + 5] = plane3{{0, 0, -1}, -b.min.z};
    return feasible(k, rows.data(), n + 6);
}

} // namespace halfspaces

namespace halfspaces {

// The vertices of the m half-spaces found in double (the triples of planes whose meeting point is
// nearly in every half-space), at most `capacity` of them: guesses, proven by the caller.
struct vertex_guesses {
    static constexpr int capacity = 128;
    std::array<std::array<int, 3>, capacity> triple{};
    std::array<point3, capacity> at{};
    int n = 0;
};
[[nodiscard]] constexpr vertex_guesses vertices_guess(const plane3* planes, int m) {
    auto norm1 = [](vec3 v) { return arith::abs(v.x) + arith::abs(v.y) + arith::abs(v.z); };
    vertex_guesses out;
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            for (int l = j + 1; l < m && out.n < vertex_guesses::capacity; ++l) {
                const plane3 a = planes[i], b = planes[j], c = planes[l];
                const vec3 bc = cross(b.normal, c.normal), ca = cross(c.normal, a.normal), ab = cross(a.normal, b.normal);
                const double d = dot(a.normal, bc);
                if (!(arith::abs(d) > 0x1p-30 * norm1(a.normal) * norm1(b.normal) * norm1(c.normal))) continue;
                const vec3 v = (bc * a.offset + ca * b.offset + ab * c.offset) * (1.0 / d);
                if (!finite(v)) continue;
                const double size = arith::abs(v.x) + arith::abs(v.y) + arith::abs(v.z);
                bool inside = true;
                for (int r = 0; r < m && inside; ++r) {
                    if (r == i || r == j || r == l) continue;
                    inside = dot(planes[r].normal, v) - planes[r].offset <=
                             0x1p-30 * (norm1(planes[r].normal) * size + arith::abs(planes[r].offset));
                }
                if (!inside) continue;
                const auto u = static_cast<unsigned>(out.n++);
                out.triple[u] = {i, j, l};
                out.at[u] = point3{v.x, v.y, v.z};
            }
    return out;
}

// Has the set of the m half-spaces a point x with g . x >= e? Decided from the vertex v = V / D of
// the three planes t only when every deciding sign is proven nonzero (hint::optional): yes when
// g . v > e and v is strictly inside every other half-space; no when g . v < e and
// g = y_i n_i + y_j n_j + y_l n_l with every y > 0 (Farkas: then g . x <= g . v on the whole set).
// uncertain: not decided (the caller runs feasible()).
template <class K>
[[nodiscard]] constexpr certainty side_at_vertex(K& k, const plane3* planes, int m, const std::array<int, 3>& t, vec3 g, double e) {
    if (t[0] < 0) return certainty::uncertain;
    const plane3 a = planes[t[0]], b = planes[t[1]], c = planes[t[2]];
    const sign d = arith::sgn<arith::hint::optional>(
        k, [=](auto L) { return arith::det3(arith::lift(L, a.normal), arith::lift(L, b.normal), arith::lift(L, c.normal)); });
    if (d == sign::zero) return certainty::uncertain;
    // g . V - e D, with g . (n_j x n_l) = det(g, n_j, n_l)
    const sign along = arith::sgn<arith::hint::optional>(k, [=](auto L) {
        const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal), nc = arith::lift(L, c.normal), G = arith::lift(L, g);
        return L(a.offset) * arith::det3(G, nb, nc) + L(b.offset) * arith::det3(G, nc, na) + L(c.offset) * arith::det3(G, na, nb) -
               L(e) * arith::det3(na, nb, nc);
    });
    if (along == sign::zero) return certainty::uncertain;
    if (along == d) { // g . v > e: yes if v is in the set
        for (int r = 0; r < m; ++r) {
            if (r == t[0] || r == t[1] || r == t[2]) continue;
            const plane3 h = planes[r];
            const sign s = arith::sgn<arith::hint::optional>(k, [=](auto L) {
                const auto na = arith::lift(L, a.normal), nb = arith::lift(L, b.normal), nc = arith::lift(L, c.normal);
                const auto nh = arith::lift(L, h.normal);
                return L(h.offset) * arith::det3(na, nb, nc) -
                       (L(a.offset) * arith::det3(nh, nb, nc) + L(b.offset) * arith::det3(nh, nc, na) +
                        L(c.offset) * arith::det3(nh, na, nb));
            });
            if (s != d) return certainty::uncertain;
        }
        return certainty::yes;
    }
    // g . v < e: no if the multipliers y = (det(g, n_j, n_l), det(n_i, g, n_l), det(n_i, n_j, g)) / D are positive
    const sign y0 = arith::sgn<arith::hint::optional>(
        k, [=](auto L) { return arith::det3(arith::lift(L, g), arith::lift(L, b.normal), arith::lift(L, c.normal)); });
    const sign y1 = arith::sgn<arith::hint::optional>(
        k, [=](auto L) { return arith::det3(arith::lift(L, a.normal), arith::lift(L, g), arith::lift(L, c.normal)); });
    const sign y2 = arith::sgn<arith::hint::optional>(
        k, [=](auto L) { return arith::det3(arith::lift(L, a.normal), arith::lift(L, b.normal), arith::lift(L, g)); });
    return y0 == d && y1 == d && y2 == d ? certainty::no : certainty::uncertain;
}

// Do the m half-spaces n_i . x <= c_i (m <= convex_polyhedron3::capacity) meet the plane?
template <class K>
[[nodiscard]] constexpr bool plane_meets(K& k, const plane3* planes, int m, const plane3& p) {
    constexpr int capacity = convex_polyhedron3::capacity;
    if (!well_formed(planes, m, capacity) || !finite(p.normal) || !finite(p.offset)) return false;
    // First the set's vertices least and greatest along the normal, guessed in double and proven
    // with signs: they decide most cases without the enumeration of feasible() (which meets the
    // near-zero signs of a camera frustum's side planes, nearly concurrent at the eye). The guess:
    // a linear program each (seidel_lp::guess_of), or for up to eight planes (a frustum, a box) every
    // triple in double, which measured cheaper there (and in constant evaluation).
    std::array<int, 3> least{-1, -1, -1}, greatest{-1, -1, -1};
    if (!__builtin_is_constant_evaluated() && m > 8) {
        const plane_rows view{planes, static_cast<unsigned>(m)};
        auto triple = [](const seidel_lp::guess& g) {
            return g.vertex ? std::array<int, 3>{static_cast<int>(g.r[0]), static_cast<int>(g.r[1]), static_cast<int>(g.r[2])}
                            : std::array<int, 3>{-1, -1, -1};
        };
        least = triple(seidel_lp::guess_of(view, {p.normal.x, p.normal.y, p.normal.z}));
        greatest = triple(seidel_lp::guess_of(view, {-p.normal.x, -p.normal.y, -p.normal.z}));
    } else {
        const vertex_guesses g = vertices_guess(planes, m);
        double lo = 0, hi = 0;
        for (int v = 0; v < g.n; ++v) {
            const auto u = static_cast<unsigned>(v);
            const double t = dot(p.normal, g.at[u] - point3{0, 0, 0});
            if (least[0] < 0 || t < lo) least = g.triple[u], lo = t;
            if (greatest[0] < 0 || t > hi) greatest = g.triple[u], hi = t;
        }
    }
    const certainty upper = side_at_vertex(k, planes, m, greatest, p.normal, p.offset); // a point with n . x >= c?
    if (upper == certainty::no) return false;
    const certainty lower = side_at_vertex(k, planes, m, least, -p.normal, -p.offset); // and with n . x <= c?
    if (lower == certainty::no) return false;
    std::array<plane3, capacity + 1> rows{};
    for (int i = 0; i < m; ++i) rows[static_cast<unsigned>(i)] = planes[i];
    const auto n = static_cast<unsigned>(m);
    if (lower != certainty::yes) {
        rows[n] = p; // the set's points on the plane's lower side
        if (!feasible(k, rows.data(), n + 1)) return false;
    }
    if (upper != certainty::yes) {
        rows[n] = plane3{-p.normal, -p.offset}; // and on its upper side
        if (!feasible(k, rows.data(), n + 1)) return false;
    }
    return true;
}

} // namespace halfspaces

namespace halfspaces {

// Is some half-space of `a` proven to have the whole set `b` beyond it (b's vertex least along its
// normal, guessed from vb, short of it with a Farkas certificate)?
template <class K>
[[nodiscard]] constexpr bool face_separates(K& k, const plane3* a, int ma, const plane3* b, int mb, const vertex_guesses& vb) {
    for (int r = 0; r < ma; ++r) {
        const plane3 h = a[r];
        int best = -1;
        double lo = 0;
        for (int v = 0; v < vb.n; ++v) {
            const point3 x = vb.at[static_cast<unsigned>(v)];
            const double t = h.normal.x * x.x + h.normal.y * x.y + h.normal.z * x.z;
            if (best < 0 || t < lo) best = v, lo = t;
        }
        if (best < 0 || !(lo > h.offset)) continue; // not beyond, as far as double can tell
        // has b a point with -n . x >= -c (n . x <= c)? no: separated
        if (side_at_vertex(k, b, mb, vb.triple[static_cast<unsigned>(best)], -h.normal, -h.offset) == certainty::no) return true;
    }
    return false;
}

// Above this many planes in all, sets_meet goes to feasible() at once: its linear program's guess
// measured cheaper than every triple of each set, except for two frustums (6 + 6).
inline constexpr int guess_all_above = 12;
// Do the half-space sets a (ma planes) and b (mb planes) meet? ma, mb <= convex_polyhedron3::capacity.
template <class K>
[[nodiscard]] constexpr bool sets_meet(K& k, const plane3* a, int ma, const plane3* b, int mb) {
    constexpr int capacity = convex_polyhedron3::capacity;
    if (!well_formed(a, ma, capacity) || !well_formed(b, mb, capacity)) return false;
    std::array<plane3, 2 * capacity> rows{};
    for (int i = 0; i < ma; ++i) rows[static_cast<unsigned>(i)] = a[i];
    for (int i = 0; i < mb; ++i) rows[static_cast<unsigned>(ma + i)] = b[i];
    // at run time, many planes: the linear program's guess in feasible() first
    if (!__builtin_is_constant_evaluated() && ma + mb > guess_all_above) return feasible(k, rows.data(), static_cast<unsigned>(ma + mb));
    const vertex_guesses va = vertices_guess(a, ma), vb = vertices_guess(b, mb);
    if (face_separates(k, a, ma, b, mb, vb) || face_separates(k, b, mb, a, ma, va)) return false;
    // a point strictly inside both: the mean of the vertices of each set that look inside the other
    auto inside_all = [](const plane3* p, int m, point3 x) {
        for (int r = 0; r < m; ++r)
            if (!(dot(p[r].normal, x - point3{0, 0, 0}) <= p[r].offset)) return false;
        return true;
    };
    double sx = 0, sy = 0, sz = 0;
    int count = 0;
    auto add = [&](const vertex_guesses& g, const plane3* other, int mo) {
        for (int v = 0; v < g.n; ++v) {
            const point3 x = g.at[static_cast<unsigned>(v)];
            if (inside_all(other, mo, x)) sx += x.x, sy += x.y, sz += x.z, ++count;
        }
    };
    add(va, b, mb);
    add(vb, a, ma);
    if (count > 0) {
        const point3 w{sx / count, sy / count, sz / count};
        bool strictly = finite(w);
        auto strictly_in = [&](const plane3* p, int m) {
            for (int r = 0; r < m && strictly; ++r) {
                const plane3 h = p[r];
                strictly = arith::sgn<arith::hint::optional>(k, [=](auto L) {
                               return L(h.offset) * L(1.0) - arith::dot(arith::lift(L, h.normal), arith::lift(L, w));
                           }) == sign::positive;
            }
        };
        strictly_in(a, ma);
        strictly_in(b, mb);
        if (strictly) return true;
    }
    return feasible(k, rows.data(), static_cast<unsigned>(ma + mb));
}

} // namespace halfspaces

namespace halfspaces {
// A fixed order of two lists of n planes (their numbers in turn, see numbers_before), so a test
// of two sets runs on the same order of its arguments whichever way they come.
[[nodiscard]] constexpr bool planes_before(const plane3* a, const plane3* b, int n) {
    for (int i = 0; i < n; ++i) {
        const plane3 p = a[i], q = b[i];
        const double x[4] = {p.normal.x, p.normal.y, p.normal.z, p.offset}, y[4] = {q.normal.x, q.normal.y, q.normal.z, q.offset};
        if (numbers_before(x, y, 4)) return true;
        if (numbers_before(y, x, 4)) return false;
    }
    return false;
}
// Two polyhedra: the count, then the planes.
[[nodiscard]] constexpr bool before(const convex_polyhedron3& a, const convex_polyhedron3& b) {
    if (a.count != b.count) return a.count < b.count;
    const int n = a.count < 0 ? 0 : (a.count > convex_polyhedron3::capacity ? convex_polyhedron3::capacity : a.count);
    return planes_before(a.planes.data(), b.planes.data(), n);
}
} // namespace halfspaces

namespace halfspaces {
// A fixed order of two frustums: their six planes in turn.
[[nodiscard]] constexpr bool before(const frustum3& a, const frustum3& b) { return planes_before(a.planes.data(), b.planes.data(), 6); }
} // namespace halfspaces

} // namespace incidence::detail
