// aabb3 against aabb3: intersects, contains, and covers(a, b, c): does a u b contain c?
// Semantics: closed boxes; touching faces, edges or corners intersect; a box contains itself.
// Method: coordinate comparisons, exact in binary64, so every tier returns the exact answer.
// covers: c is covered iff c lies in a, or the closure of c \ a (at most six slabs
// c n {x_i <= a.min_i}, c n {x_i >= a.max_i}) lies in b. A flat c (min == max on an axis) is
// handled the same way. Inverted (unchecked) boxes are empty sets for `covers`' c.
// Source: Ericson, Real-Time Collision Detection (2005), section 4.2 (AABB overlap).
export module incidence.query:aabb_aabb;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::pair {

// Comparisons alone decide it, in every tier: query.cppm's decide_pair runs the body once, with
// no filter pass around it (by_comparisons).
[[nodiscard]] consteval bool decided_by_comparisons(const aabb3*, const aabb3*) { return true; }
template <class K>
[[nodiscard]] constexpr bool intersects(K&, const aabb3& a, const aabb3& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
           a.min.z <= b.max.z && b.min.z <= a.max.z;
}

template <class K>
[[nodiscard]] constexpr bool contains(K&, const aabb3& a, const aabb3& b) {
    return a.min.x <= b.min.x && b.max.x <= a.max.x && a.min.y <= b.min.y && b.max.y <= a.max.y &&
           a.min.z <= b.min.z && b.max.z <= a.max.z;
}

[[nodiscard]] constexpr bool box_inside(const double (&lo)[3], const double (&hi)[3], const aabb3& b) {
    return b.min.x <= lo[0] && hi[0] <= b.max.x && b.min.y <= lo[1] && hi[1] <= b.max.y && b.min.z <= lo[2] &&
           hi[2] <= b.max.z;
}

[[nodiscard]] constexpr bool covers(const aabb3& a, const aabb3& b, const aabb3& c) {
    const double cmin[3] = {c.min.x, c.min.y, c.min.z};
    const double cmax[3] = {c.max.x, c.max.y, c.max.z};
    const double amin[3] = {a.min.x, a.min.y, a.min.z};
    const double amax[3] = {a.max.x, a.max.y, a.max.z};
    for (int i = 0; i < 3; ++i)
        if (!(cmin[i] <= cmax[i])) return true; // c is empty (or NaN): trivially covered
    for (int i = 0; i < 3; ++i) {
        // below a on axis i: c n {x_i <= a.min_i}, nonempty part only if c.min_i < a.min_i
        if (cmin[i] < amin[i]) {
            double lo[3] = {cmin[0], cmin[1], cmin[2]};
            double hi[3] = {cmax[0], cmax[1], cmax[2]};
            if (amin[i] < hi[i]) hi[i] = amin[i];
            if (!box_inside(lo, hi, b)) return false;
        }
        // above a on axis i: c n {x_i >= a.max_i}
        if (cmax[i] > amax[i]) {
            double lo[3] = {cmin[0], cmin[1], cmin[2]};
            double hi[3] = {cmax[0], cmax[1], cmax[2]};
            if (amax[i] > lo[i]) lo[i] = amax[i];
            if (!box_inside(lo, hi, b)) return false;
        }
    }
    return true;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const aabb3&);
extern template bool contains(arith::exact_kernel&, const aabb3&, const aabb3&);
} // namespace incidence::pair
