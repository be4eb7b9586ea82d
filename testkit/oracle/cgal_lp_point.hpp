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
} // namespace oracle
