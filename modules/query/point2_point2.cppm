// point2 against point2.
// Semantics: Two points meet iff both coordinates are equal (NaN is never equal, and an infinite
// coordinate is no point).
// Method: a finiteness check and two coordinate comparisons. A binary64 comparison is exact
// (the sign of p.x - q.x without rounding), so every tier, the approximate one included, gives
// the exact answer and the filter is never uncertain; like aabb_point, no kernel sign is needed.
// Source: IEEE 754-2019, section 5.11 (comparisons are exact; -0 == +0; NaN is unordered).
export module incidence.query:point2_point2;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

// Comparisons alone decide it, in every tier: query.cppm's decide_pair runs the body once, with
// no filter pass around it (by_comparisons).
[[nodiscard]] consteval bool decided_by_comparisons(const point2*, const point2*) { return true; }
template <class K>
[[nodiscard]] constexpr bool intersects(K&, const point2& p, const point2& q) {
    return finite(p) && p.x == q.x && p.y == q.y; // an infinite point is no shape
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const point2&, const point2&);
} // namespace incidence::pair
