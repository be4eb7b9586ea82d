// kdop<K> against segment3.
// Semantics: the closed k-DOP (possibly empty; an empty slab or a non-finite bound: no set) and
// the closed segment; touching a face, an edge or a corner counts.
// Method (exact tiers): the generalised slab test (kdop_point.cppm) over t in [0, 1], the
// direction taken exactly as d_i . b - d_i . a: signs of degree <= 2.
// Source: Kay and Kajiya, SIGGRAPH 1986 (slabs); Klosowski et al., IEEE TVCG 4(1) 1998 (k-DOPs).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_segment.cpp).
export module incidence.query:kdop_segment;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :kdop_point;

export namespace incidence::pair {

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const segment3& s) {
    return kdopq::slabs<slab_extent::segment>(k, b, s.a, vec3{0, 0, 0}, s.b);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const segment3&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const segment3&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const segment3&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const segment3&);
} // namespace incidence::pair
