// The LP oracle: do two convex sets meet? Exact linear-programming feasibility with CGAL's
// QP_solver over CGAL::Gmpzf (exact big floats). Every LP coefficient is an input double as
// given, never a computed one: a box is c + sum t_i a_i with |t_i| <= h_i, a segment or a
// triangle the convex combinations of its vertices, a plane n . x = offset, a k-DOP its slabs
// lo <= n . x <= hi (n the integer directions), a convex polyhedron or a frustum its half-spaces
// n . x <= offset. Before the LP, a corner certificate (corners_decide) decides most cases exactly
// when one set is a polytope given by its corners and the other slabs and half-spaces alone.
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
// x given by its slabs and half-spaces alone, every value finite?
bool finite_rows_only(const convex_set& x) {
    if (x.plane || !x.points.empty() || !x.generators.empty()) return false;
    for (const auto& sl : x.slabs)
        if (!finite(sl.n) || !std::isfinite(sl.lo) || !std::isfinite(sl.hi)) return false;
    for (const auto& hs : x.halfspaces)
        if (!finite(hs.n) || !std::isfinite(hs.offset)) return false;
    return true;
}

// The sign of n . (p + sum_i t_i g_i) - c, t_i the lower or upper bound of generator i as bit i of
// `corner` says: in double when rounding cannot reach it, else in rationals. The double sum has at
// most 13 terms, each a product of at most three doubles: at most 14 roundings on each, under
// 2^-49 of the sum of the terms' magnitudes, plus under 2^-1068 from last products that underflow.
// A first product t g_k that underflows (its error would grow with n_k) leaves the sign to rationals.
int corner_sign(const std::array<double, 3>& n, double c, const std::array<double, 3>& p,
                const std::vector<convex_set::generator>& gs, unsigned corner) {
    double s = -c, size = std::fabs(c);
    bool underflow = false;
    for (unsigned k = 0; k < 3; ++k) {
        const double a = n[k] * p[k];
        s += a, size += std::fabs(a);
    }
    for (unsigned i = 0; i < gs.size(); ++i) {
        const double t = (corner >> i & 1U) ? gs[i].hi : gs[i].lo;
        for (unsigned k = 0; k < 3; ++k) {
            const double tg = t * gs[i].g[k], a = tg * n[k];
            underflow = underflow || (std::fabs(tg) < 0x1p-1022 && t != 0 && gs[i].g[k] != 0);
            s += a, size += std::fabs(a);
        }
    }
    if (!underflow && std::isfinite(size) && std::isfinite(s)) {
        const double reach = size * 0x1p-48 + 0x1p-1060;
        if (s > reach) return 1;
        if (s < -reach) return -1;
    }
    mpq_class e = -mpq_class(c);
    for (unsigned k = 0; k < 3; ++k) e += mpq_class(n[k]) * p[k];
    for (unsigned i = 0; i < gs.size(); ++i) {
        const mpq_class t((corner >> i & 1U) ? gs[i].hi : gs[i].lo);
        for (unsigned k = 0; k < 3; ++k) e += t * gs[i].g[k] * n[k];
    }
    return sgn(e);
}
} // namespace

int corners_decide(const convex_set& x, const convex_set& v) {
    if (!finite_rows_only(x)) return 0;
    if (v.plane || !v.slabs.empty() || !v.halfspaces.empty() || v.points.empty() || v.generators.size() > 3) return 0;
    for (const auto& g : v.generators)
        if (!g.has_lo || !g.has_hi || !(g.lo <= g.hi) || !finite(g.g) || !std::isfinite(g.lo) || !std::isfinite(g.hi)) return 0;
    for (const auto& p : v.points)
        if (!finite(p)) return 0;
    const unsigned per_point = 1U << v.generators.size();
    const std::size_t count = v.points.size() * per_point;
    std::vector<bool> inside(count, true);
    // Every corner's sign against the bound c of the row n; false when all lie strictly on `side`.
    auto not_all_beyond = [&](const std::array<double, 3>& n, double c, int side) {
        bool some_not = false;
        for (std::size_t j = 0; j < count; ++j) {
            const int s = corner_sign(n, c, v.points[j / per_point], v.generators, static_cast<unsigned>(j % per_point));
            if (s == side) inside[j] = false;
            else some_not = true;
        }
        return some_not;
    };
    for (const auto& hs : x.halfspaces)
        if (!not_all_beyond(hs.n, hs.offset, 1)) return -1;
    for (const auto& sl : x.slabs)
        if (!not_all_beyond(sl.n, sl.lo, -1) || !not_all_beyond(sl.n, sl.hi, 1)) return -1;
    for (const bool in : inside)
        if (in) return 1;
    return 0;
}

std::optional<bool> clip_decide(const convex_set& x, const convex_set& v) {
    if (!finite_rows_only(x) || v.plane || !v.slabs.empty() || !v.halfspaces.empty() || v.points.empty()) return std::nullopt;
    for (const auto& p : v.points)
        if (!finite(p)) return std::nullopt;
    using point = std::array<mpq_class, 3>;
    auto of = [](const std::array<double, 3>& p) { return point{mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; };
    // Every bound of x as n . y <= c (a slab's lower bound as -n . y <= -lo); f(r, y) = n . y - c.
    struct row {
        std::array<double, 3> n;
        double c;
        bool flip;
    };
    std::vector<row> rows;
    for (const auto& hs : x.halfspaces) rows.push_back({hs.n, hs.offset, false});
    for (const auto& sl : x.slabs) rows.push_back({sl.n, sl.hi, false}), rows.push_back({sl.n, sl.lo, true});
    auto f = [](const row& r, const point& y) {
        mpq_class e = r.n[0] * y[0] + r.n[1] * y[1] + r.n[2] * y[2] - r.c;
        return r.flip ? mpq_class(-e) : e;
    };
    if (v.points.size() == 1 && v.generators.size() == 1) { // p + t g, t within the generator's bounds
        const auto& g = v.generators[0];
        if (!finite(g.g) || (g.has_lo && !std::isfinite(g.lo)) || (g.has_hi && !std::isfinite(g.hi))) return std::nullopt;
        bool has_lo = g.has_lo, has_hi = g.has_hi;
        mpq_class lo(g.has_lo ? g.lo : 0.0), hi(g.has_hi ? g.hi : 0.0);
        const point p = of(v.points[0]);
        for (const auto& r : rows) { // f(r, p) + t n . g <= 0
            const mpq_class at_p = f(r, p);
            mpq_class a = r.n[0] * mpq_class(g.g[0]) + r.n[1] * mpq_class(g.g[1]) + r.n[2] * mpq_class(g.g[2]);
            if (r.flip) a = -a;
            if (sgn(a) == 0) {
                if (sgn(at_p) > 0) return false;
                continue;
            }
            const mpq_class t = -at_p / a;
            if (sgn(a) > 0) hi = has_hi && hi < t ? hi : t, has_hi = true;
            else lo = has_lo && lo > t ? lo : t, has_lo = true;
            if (has_lo && has_hi && lo > hi) return false;
        }
        return !(has_lo && has_hi && lo > hi);
    }
    if (!v.generators.empty() || v.points.size() > 3) return std::nullopt;
    std::vector<point> poly, next;
    for (const auto& p : v.points) poly.push_back(of(p));
    std::vector<mpq_class> d;
    for (const auto& r : rows) { // keep the part with f <= 0: the closed polygon's vertices and edge crossings
        d.clear();
        for (const auto& y : poly) d.push_back(f(r, y));
        next.clear();
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const std::size_t j = (i + 1) % poly.size();
            if (sgn(d[i]) <= 0) next.push_back(poly[i]);
            if ((sgn(d[i]) < 0 && sgn(d[j]) > 0) || (sgn(d[i]) > 0 && sgn(d[j]) < 0)) {
                const mpq_class t = d[i] / (d[i] - d[j]);
                point y;
                for (unsigned k = 0; k < 3; ++k) y[k] = poly[i][k] + t * (poly[j][k] - poly[i][k]);
                next.push_back(y);
            }
        }
        if (next.empty()) return false;
        poly.swap(next);
    }
    return true;
}

std::optional<bool> lp_intersect_verified(const convex_set& a, const convex_set& b) {
    // Independent of the LP below and exact: decides most random cases far faster.
    if (const int r = corners_decide(b, a)) return r > 0;
    if (const int r = corners_decide(a, b)) return r > 0;
    // Exact clipping in rationals, for a point, segment, triangle, ray or line against slabs and half-spaces.
    if (const auto r = clip_decide(b, a)) return r;
    if (const auto r = clip_decide(a, b)) return r;
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
