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
// The corner certificate, for x given by its slabs and half-spaces alone or a box (a point plus
// three bounded generators, its determinant not zero: its six face bounds in rationals) and v a
// polytope given by its corners (points, plus up to three generators with both bounds: the corners
// are each point plus every choice of bounds): -1 when every corner lies strictly beyond one bound
// of x (apart: v is the hull of its corners), +1 when one corner lies within every bound (a common
// point), 0 when neither, or when x or v has another form or a value that is not finite. Every
// sign is exact (double when rounding cannot reach it, else rationals).
int corners_decide(const convex_set& x, const convex_set& v);
// Exact clipping in GMP rationals, for x as in corners_decide and v a point, a segment or a
// triangle (one to three points: the convex polygon of v cut by each bound in turn, Sutherland and
// Hodgman 1974) or p + t g with one generator (a segment, ray or line: the interval of t cut by
// each bound). Whether they meet; nothing when x or v has another form or a value that is not finite.
std::optional<bool> clip_decide(const convex_set& x, const convex_set& v);
} // namespace oracle
