// aabb3 against point3, and the point's minimum and maximum squared distance to the box.
// Semantics: closed box, so a point on a face, edge or corner intersects.
// Method: coordinate comparisons, which are exact in binary64, so every tier gives the exact
// answer for the yes/no test. Distances: min distance uses the clamped per-axis gap
// max(min - p, 0, p - max); max distance the farthest corner per axis; the exact tier sums the
// squares in exact dyadic arithmetic and rounds once (correctly rounded).
// Error bound, approximate distance: each gap rounds once, each square once, two additions:
// |d_approx - d| <= gamma_4 d + 4 * 2^-1074 (Higham, Accuracy and Stability, 2002, section 3.1).
// Source: Ericson, Real-Time Collision Detection (2005), section 5.1.3 (SqDistPointAABB).
export module incidence.query:aabb_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::pair {

// Comparisons alone decide it, in every tier: query.cppm's decide_pair runs the body once, with
// no filter pass around it (by_comparisons).
[[nodiscard]] consteval bool decided_by_comparisons(const aabb3*, const point3*) { return true; }
template <class K>
[[nodiscard]] constexpr bool intersects(K&, const aabb3& b, const point3& p) {
    return b.min.x <= p.x && p.x <= b.max.x && b.min.y <= p.y && p.y <= b.max.y && b.min.z <= p.z &&
           p.z <= b.max.z;
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const point3& p) {
    return intersects(k, b, p);
}

enum class distance_kind : unsigned char { nearest, farthest };

template <class Tier>
[[nodiscard]] constexpr auto squared_distance_impl(const aabb3& b, const point3& p, distance_kind kind) {
    const double pc[3] = {p.x, p.y, p.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z};
    const double mx[3] = {b.max.x, b.max.y, b.max.z};
    if constexpr (__is_same(Tier, exact)) {
        arith::dyadic sum{};
        for (int i = 0; i < 3; ++i) {
            // Choose the gap by exact comparisons of the inputs, then square it exactly.
            arith::dyadic g{};
            if (kind == distance_kind::nearest) {
                if (pc[i] < mn[i]) g = arith::to_dyadic(mn[i]) - arith::to_dyadic(pc[i]);
                else if (pc[i] > mx[i]) g = arith::to_dyadic(pc[i]) - arith::to_dyadic(mx[i]);
            } else {
                const auto a = arith::to_dyadic(pc[i]) - arith::to_dyadic(mn[i]);
                const auto c = arith::to_dyadic(mx[i]) - arith::to_dyadic(pc[i]);
                // farther face: compare |p - min| with |max - p| exactly
                const auto aa = a * a, cc = c * c;
                g = arith::sign_of(aa - cc) >= 0 ? a : c;
            }
            sum = sum + g * g;
        }
        return arith::to_double(sum);
    } else {
        double s = 0.0;
        for (int i = 0; i < 3; ++i) {
            double g = 0.0;
            if (kind == distance_kind::nearest) {
                if (pc[i] < mn[i]) g = mn[i] - pc[i];
                else if (pc[i] > mx[i]) g = pc[i] - mx[i];
            } else {
                const double a = arith::abs(pc[i] - mn[i]);
                const double c = arith::abs(mx[i] - pc[i]);
                g = a > c ? a : c;
            }
            s += g * g;
        }
        if constexpr (__is_same(Tier, approximate)) {
            return s;
        } else {
            // gamma_4 relative plus underflow slack; the interval encloses the exact value.
            constexpr double g4 = 4 * arith::unit_roundoff / (1 - 4 * arith::unit_roundoff) * (1 + 0x1p-20);
            const double e = g4 * s + 0x1p-1070;
            const double lo = s - e;
            return interval{lo > 0.0 ? lo : 0.0, s + e};
        }
    }
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const point3&);
extern template bool contains(arith::exact_kernel&, const aabb3&, const point3&);
} // namespace incidence::pair
