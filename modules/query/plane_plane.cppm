// plane3 against plane3 (n . p = offset each).
// Semantics: two planes meet unless they are parallel and distinct. A zero normal is everything
// when its offset is 0 and nothing otherwise (so it meets every non-empty plane).
// Method (exact tiers): n x m != 0 (a component's sign, degree 2): they cross in a line. Parallel
// normals: the same plane iff offset_p m - offset_q n == 0 (three signs of degree 2; with
// m = lambda n this says offset_q = lambda offset_p).
// Source: Ericson, Real-Time Collision Detection (2005), section 5.4.4 (intersection of two
// planes), with the parallel case decided by signs instead of a tolerance on |n x m|.
// Approximate tier: the same signs in plain double: nearly parallel planes may read as parallel.
// Error bound: for inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when a
// sign is within 2^-48 of its permanent (tests/query/plane_plane.cpp).
export module incidence.query:plane_plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& p0, const plane3& q0) {
    // One canonical order (see segment_segment.cppm), so every tier is symmetric.
    const vec3 a = q0.normal, b = p0.normal;
    const bool swap = before(point3{a.x, a.y, a.z}, vec3{q0.offset, 0, 0}, point3{b.x, b.y, b.z}, vec3{p0.offset, 0, 0});
    const plane3& p = swap ? q0 : p0;
    const plane3& q = swap ? p0 : q0;
    const vec3 n = p.normal, m = q.normal;
    const double op = p.offset, oq = q.offset;
    // Crossing normals decide without the offsets: a NaN or infinite input is checked here.
    if (!finite(n) || !finite(m) || !finite(op) || !finite(oq)) return false;
    auto zero = [](vec3 v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; };
    auto offset_zero = [&](double o) { return k.sgn([=](auto L) { return L(o); }) == sign::zero; };
    if (zero(n) || zero(m)) {
        // A zero normal with a nonzero offset is empty; with a zero offset it is all of space,
        // which meets the other plane iff that one is not empty.
        if (zero(n) && !offset_zero(op)) return false;
        if (zero(m) && !offset_zero(oq)) return false;
        return true;
    }
    for (int i = 0; i < 3; ++i) {
        const sign c = k.sgn([=](auto L) {
            const auto x = arith::cross(arith::lift(L, n), arith::lift(L, m));
            return i == 0 ? x.x : (i == 1 ? x.y : x.z);
        });
        if (c != sign::zero) return true;
    }
    // Parallel: the same plane, or disjoint.
    for (int i = 0; i < 3; ++i) {
        const double ni = i == 0 ? n.x : (i == 1 ? n.y : n.z), mi = i == 0 ? m.x : (i == 1 ? m.y : m.z);
        if (k.sgn([=](auto L) { return L(op) * L(mi) - L(oq) * L(ni); }) != sign::zero) return false;
    }
    return true;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const plane3&, const plane3&);
} // namespace incidence::pair
