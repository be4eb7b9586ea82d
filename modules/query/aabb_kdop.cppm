// aabb3 against kdop<K>, and contains(kdop, aabb | segment).
// Semantics: the closed box and the closed k-DOP (possibly empty; an empty slab, an inverted box
// or a non-finite bound: no set, so no); touching at a face, an edge or a corner counts.
// Method (exact tiers): the box is the 6-DOP of its bounds, so the pair is kdop_kdop's exact
// emptiness test of the slabs of both (slab overlap, then Farkas certificates of degree 2).
// Contains: a convex shape lies in the k-DOP iff its vertices do (the slab test per vertex).
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 5; Schrijver, Theory of Linear and
// Integer Programming, 1986, section 7.3.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_kdop.cpp).
export module incidence.query:aabb_kdop;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :kdop_point;
import :kdop_kdop;

export namespace incidence::pair {

namespace kdopq {
[[nodiscard]] constexpr kdop<6> as_kdop(const aabb3& b) { return kdop<6>{{b.min.x, b.min.y, b.min.z}, {b.max.x, b.max.y, b.max.z}}; }
} // namespace kdopq

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& a, const kdop<N>& b) {
    return kdopq::meet(k, kdopq::as_kdop(a), b);
}

template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const aabb3& a) {
    if (!kdopq::well_formed(&a.min.x, &a.max.x, 1) || !kdopq::well_formed(&a.min.y, &a.max.y, 1) || !kdopq::well_formed(&a.min.z, &a.max.z, 1))
        return false;
    const point3 c[8] = {{a.min.x, a.min.y, a.min.z}, {a.max.x, a.min.y, a.min.z}, {a.min.x, a.max.y, a.min.z}, {a.max.x, a.max.y, a.min.z},
                         {a.min.x, a.min.y, a.max.z}, {a.max.x, a.min.y, a.max.z}, {a.min.x, a.max.y, a.max.z}, {a.max.x, a.max.y, a.max.z}};
    return kdopq::contains_all(k, b, c, 8);
}
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const segment3& s) {
    const point3 p[2] = {s.a, s.b};
    return kdopq::contains_all(k, b, p, 2);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const kdop<6>&);
extern template bool intersects(arith::exact_kernel&, const aabb3&, const kdop<14>&);
extern template bool intersects(arith::exact_kernel&, const aabb3&, const kdop<18>&);
extern template bool intersects(arith::exact_kernel&, const aabb3&, const kdop<26>&);
extern template bool contains(arith::exact_kernel&, const kdop<6>&, const aabb3&);
extern template bool contains(arith::exact_kernel&, const kdop<14>&, const aabb3&);
extern template bool contains(arith::exact_kernel&, const kdop<18>&, const aabb3&);
extern template bool contains(arith::exact_kernel&, const kdop<26>&, const aabb3&);
extern template bool contains(arith::exact_kernel&, const kdop<6>&, const segment3&);
extern template bool contains(arith::exact_kernel&, const kdop<14>&, const segment3&);
extern template bool contains(arith::exact_kernel&, const kdop<18>&, const segment3&);
extern template bool contains(arith::exact_kernel&, const kdop<26>&, const segment3&);
} // namespace incidence::pair
