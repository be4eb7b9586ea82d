// The LP oracle: do two convex sets meet? Exact linear-programming feasibility with CGAL's
// QP_solver over CGAL::Gmpzf (exact big floats). Every LP coefficient is an input double as
// given, never a computed one: a box is c + sum t_i a_i with |t_i| <= h_i, a segment or a
// triangle the convex combinations of its vertices, a plane n . x = offset, a k-DOP its slabs
// lo <= n . x <= hi (n the integer directions), a convex polyhedron or a frustum its half-spaces
// n . x <= offset. Before the LP, a corner certificate decides most cases exactly (rationals) when
// one set is a polytope given by its corners and the other slabs and half-spaces alone.
#include "cgal_oracle.hpp"
#include "cgal_lp_point.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

namespace oracle {

namespace {
using program = CGAL::Quadratic_program<double>;

// Adds the rows and variables of s meeting the common point x (variables 0, 1, 2).
void add(program& lp, int& var, int& row, const convex_set& s) {
    for (const auto& sl : s.slabs) // lo <= n . x <= hi, two rows
        for (const auto [bound, rel] : {std::pair{sl.lo, CGAL::LARGER}, std::pair{sl.hi, CGAL::SMALLER}}) {
            for (int k = 0; k < 3; ++k) lp.set_a(k, row, sl.n[static_cast<unsigned>(k)]);
            lp.set_b(row, bound);
            lp.set_r(row, rel);
            ++row;
        }
    for (const auto& h : s.halfspaces) { // n . x <= offset
        for (int k = 0; k < 3; ++k) lp.set_a(k, row, h.n[static_cast<unsigned>(k)]);
        lp.set_b(row, h.offset);
        lp.set_r(row, CGAL::SMALLER);
        ++row;
    }
    if (!s.plane && s.points.empty() && s.generators.empty()) return; // the slabs or half-spaces alone
    if (s.plane) {
        for (int k = 0; k < 3; ++k) lp.set_a(k, row, s.normal[static_cast<unsigned>(k)]);
        lp.set_b(row, s.offset);
        lp.set_r(row, CGAL::EQUAL);
        ++row;
        return;
    }
    // x_k - sum_v l_v p_vk - sum_g t_g g_k = 0,  sum_v l_v = 1 (every set has a point)
    for (const auto& p : s.points) {
        for (int k = 0; k < 3; ++k) lp.set_a(var, row + k, -p[static_cast<unsigned>(k)]);
        lp.set_a(var, row + 3, 1.0);
        lp.set_l(var, true, 0.0);
        ++var;
    }
    for (const auto& g : s.generators) {
        for (int k = 0; k < 3; ++k) lp.set_a(var, row + k, -g.g[static_cast<unsigned>(k)]);
        lp.set_l(var, g.has_lo, g.has_lo ? g.lo : 0.0);
        lp.set_u(var, g.has_hi, g.has_hi ? g.hi : 0.0);
        ++var;
    }
    for (int k = 0; k < 3; ++k) {
        lp.set_a(k, row + k, 1.0);
        lp.set_b(row + k, 0.0);
        lp.set_r(row + k, CGAL::EQUAL);
    }
    lp.set_b(row + 3, 1.0);
    lp.set_r(row + 3, CGAL::EQUAL);
    row += 4;
}
bool finite(const std::array<double, 3>& x) {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// The corners of v when v is the hull of its points plus bounded generators (no plane, slabs or
// half-spaces), as exact rationals; nothing otherwise or when there are more than 64.
std::optional<std::vector<std::array<mpq_class, 3>>> corners(const convex_set& v) {
    if (v.plane || !v.slabs.empty() || !v.halfspaces.empty() || v.points.empty() || v.generators.size() > 3)
        return std::nullopt;
    for (const auto& g : v.generators)
        if (!g.has_lo || !g.has_hi || !(g.lo <= g.hi) || !finite(g.g) || !std::isfinite(g.lo) || !std::isfinite(g.hi))
            return std::nullopt;
    for (const auto& p : v.points)
        if (!finite(p)) return std::nullopt;
    std::vector<std::array<mpq_class, 3>> out;
    const unsigned combos = 1U << v.generators.size();
    for (const auto& p : v.points)
        for (unsigned m = 0; m < combos; ++m) {
            std::array<mpq_class, 3> c{mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])};
            for (unsigned i = 0; i < v.generators.size(); ++i) {
                const auto& g = v.generators[i];
                const mpq_class t((m >> i & 1U) ? g.hi : g.lo);
                for (unsigned k = 0; k < 3; ++k) c[k] += t * mpq_class(g.g[k]);
            }
            out.push_back(c);
        }
    return out;
}

mpq_class dot(const std::array<double, 3>& n, const std::array<mpq_class, 3>& c) {
    return mpq_class(n[0]) * c[0] + mpq_class(n[1]) * c[1] + mpq_class(n[2]) * c[2];
}

// A certificate before the LP, when v is a polytope given by its corners and h is slabs and
// half-spaces alone: a constraint of h that every corner violates strictly (v and h are apart;
// v is the hull of its corners), or a corner that meets every constraint of h (a common point).
// Nothing when neither is found (the LP decides).
std::optional<bool> corner_certificate(const convex_set& v, const convex_set& h) {
    if (h.plane || !h.points.empty() || !h.generators.empty()) return std::nullopt;
    for (const auto& sl : h.slabs)
        if (!finite(sl.n) || !std::isfinite(sl.lo) || !std::isfinite(sl.hi)) return std::nullopt;
    for (const auto& hs : h.halfspaces)
        if (!finite(hs.n) || !std::isfinite(hs.offset)) return std::nullopt;
    const auto cs = corners(v);
    if (!cs) return std::nullopt;
    std::vector<mpq_class> d(cs->size());
    std::vector<bool> inside(cs->size(), true);
    auto values = [&](const std::array<double, 3>& n) {
        for (std::size_t i = 0; i < cs->size(); ++i) d[i] = dot(n, (*cs)[i]);
    };
    auto all = [&](auto&& pred) {
        for (const auto& x : d)
            if (!pred(x)) return false;
        return true;
    };
    for (const auto& sl : h.slabs) {
        values(sl.n);
        const mpq_class lo(sl.lo), hi(sl.hi);
        if (all([&](const mpq_class& x) { return x < lo; }) || all([&](const mpq_class& x) { return x > hi; }))
            return false;
        for (std::size_t i = 0; i < d.size(); ++i) inside[i] = inside[i] && lo <= d[i] && d[i] <= hi;
    }
    for (const auto& hs : h.halfspaces) {
        values(hs.n);
        const mpq_class offset(hs.offset);
        if (all([&](const mpq_class& x) { return x > offset; })) return false;
        for (std::size_t i = 0; i < d.size(); ++i) inside[i] = inside[i] && d[i] <= offset;
    }
    for (const bool in : inside)
        if (in) return true;
    return std::nullopt;
}
} // namespace

std::optional<bool> lp_intersect_verified(const convex_set& a, const convex_set& b) {
    // Independent of the LP below and exact (rationals): decides most random cases far faster.
    if (const auto r = corner_certificate(a, b)) return r;
    if (const auto r = corner_certificate(b, a)) return r;
    program lp(CGAL::EQUAL, false, 0.0, false, 0.0); // free variables unless bounded
    int var = 3, row = 0;
    add(lp, var, row, a);
    add(lp, var, row, b);
    // The answer is taken only once CGAL's own certificate check (solves_linear_program: the
    // solution, or the Farkas proof of infeasibility, verified exactly) accepts it. In CGAL 5.5
    // Bland's rule returned a "feasible" point that violates a constraint on a touching case, and
    // the default filtered pricing cycled on another: exact Dantzig first, the others as backups.
    for (const auto pricing : {CGAL::QP_DANTZIG, CGAL::QP_PARTIAL_DANTZIG, CGAL::QP_BLAND}) {
        CGAL::Quadratic_program_options options;
        options.set_pricing_strategy(pricing);
        auto s = CGAL::solve_linear_program(lp, CGAL::Gmpzf(), options);
        if (s.solves_linear_program(lp)) return !s.is_infeasible();
    }
    return std::nullopt;
}

std::optional<std::array<mpq_class, 3>> lp_point(const convex_set& s) {
    program lp(CGAL::EQUAL, false, 0.0, false, 0.0);
    int var = 3, row = 0;
    add(lp, var, row, s);
    for (const auto pricing : {CGAL::QP_DANTZIG, CGAL::QP_PARTIAL_DANTZIG, CGAL::QP_BLAND}) {
        CGAL::Quadratic_program_options options;
        options.set_pricing_strategy(pricing);
        auto sol = CGAL::solve_linear_program(lp, CGAL::Gmpzf(), options);
        if (!sol.solves_linear_program(lp)) continue;
        if (sol.is_infeasible()) return std::nullopt;
        std::array<mpq_class, 3> x;
        auto it = sol.variable_values_begin();
        auto gmpq = [](const CGAL::Gmpzf& f) { // m 2^e, exactly
            mpq_t q;
            mpq_init(q);
            mpq_set_z(q, f.man());
            if (f.exp() >= 0) mpq_mul_2exp(q, q, static_cast<mp_bitcnt_t>(f.exp()));
            else mpq_div_2exp(q, q, static_cast<mp_bitcnt_t>(-f.exp()));
            mpq_class r;
            mpq_set(r.get_mpq_t(), q);
            mpq_clear(q);
            return r;
        };
        for (unsigned k = 0; k < 3; ++k, ++it) x[k] = gmpq(it->numerator()) / gmpq(it->denominator());
        return x;
    }
    throw std::runtime_error("lp_point: no pricing strategy gave a verified answer");
}

bool lp_intersect(const convex_set& a, const convex_set& b) {
    if (const auto r = lp_intersect_verified(a, b)) return *r;
    throw std::runtime_error("lp_intersect: no pricing strategy gave a verified answer");
}

} // namespace oracle
