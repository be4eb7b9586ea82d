// Inside the oracle only (CGAL types): a point of a convex set, exactly, from the LP oracle.
#pragma once
#include <array>
#include <optional>

#include <gmpxx.h>

#include "cgal_oracle.hpp"

namespace oracle {
// A point of s as exact rationals (the LP's verified solution), or nothing when s is empty; throws
// when no pricing strategy gives a verified answer.
std::optional<std::array<mpq_class, 3>> lp_point(const convex_set& s);
// The corner certificate, for x given by its slabs and half-spaces alone and v a polytope given by
// its corners (points, plus up to three generators with both bounds: the corners are each point
// plus every choice of bounds): -1 when every corner lies strictly beyond one bound of x (apart:
// v is the hull of its corners), +1 when one corner lies within every bound (a common point),
// 0 when neither, or when x or v has another form or a value that is not finite. Every sign is
// exact (double when rounding cannot reach it, else rationals).
int corners_decide(const convex_set& x, const convex_set& v);
} // namespace oracle
