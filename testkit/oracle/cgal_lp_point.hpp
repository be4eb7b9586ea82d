// Inside the oracle only (CGAL types): a point of a convex set, exactly, from the LP oracle.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include <gmpxx.h>

#include "cgal_oracle.hpp"

namespace oracle {
// A point of s as exact rationals (the LP's verified solution), or nothing when s is empty; throws
// when no pricing strategy gives a verified answer.
std::optional<std::array<mpq_class, 3>> lp_point(const convex_set& s);
// The exact minimum of |x - c|^2 over s (CGAL's QP_solver over Gmpzf, certificate-checked): an
// empty inner value when s is empty, nothing when every pricing strategy's answer is rejected.
std::optional<std::optional<mpq_class>> qp_squared_distance(const convex_set& s, const std::array<double, 3>& c);
// The exact minimum of |x - y|^2 over x in a and y in b (both nonempty); nullopt when every pricing
// strategy's answer is rejected.
std::optional<mpq_class> qp_sets_squared_distance(const convex_set& a, const convex_set& b);
// The rows n . x <= c of s in rationals, for s given by half-spaces and slabs alone or a box with a
// nonzero determinant (its six faces); nothing for another set.
struct exact_row {
    std::array<mpq_class, 3> n;
    mpq_class c;
};
std::optional<std::vector<exact_row>> exact_rows(const convex_set& s);
} // namespace oracle
