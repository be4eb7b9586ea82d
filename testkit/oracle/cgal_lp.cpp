// The LP oracle: do two convex sets meet? Exact linear-programming feasibility with CGAL's
// QP_solver over CGAL::Gmpzf (exact big floats). Every LP coefficient is an input double as
// given, never a computed one: a box is c + sum t_i a_i with |t_i| <= h_i, a segment or a
// triangle the convex combinations of its vertices, a plane n . x = offset, a k-DOP its slabs
// lo <= n . x <= hi (n the integer directions), a convex polyhedron or a frustum its half-spaces
// n . x <= offset. Before the LP, two exact stages decide most cases when one set has bounds
// (slabs and half-spaces alone, or a box's six face planes in rationals): a corner certificate
// (corners_decide) when the other is given by its corners, and clipping in rationals
// (clip_decide) when the other is a point, segment, triangle, ray or line.
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

// Adds the rows and variables of s meeting the common point x (variables x0, x0 + 1, x0 + 2).
void add(program& lp, int& var, int& row, const convex_set& s, int x0 = 0) {
    for (const auto& sl : s.slabs) // lo <= n . x <= hi, two rows
        for (const auto [bound, rel] : {std::pair{sl.lo, CGAL::LARGER}, std::pair{sl.hi, CGAL::SMALLER}}) {
            for (int k = 0; k < 3; ++k) lp.set_a(x0 + k, row, sl.n[static_cast<unsigned>(k)]);
            lp.set_b(row, bound);
            lp.set_r(row, rel);
            ++row;
        }
    for (const auto& h : s.halfspaces) { // n . x <= offset
        for (int k = 0; k < 3; ++k) lp.set_a(x0 + k, row, h.n[static_cast<unsigned>(k)]);
        lp.set_b(row, h.offset);
        lp.set_r(row, CGAL::SMALLER);
        ++row;
    }
    if (!s.plane && s.points.empty() && s.generators.empty()) return; // the slabs or half-spaces alone
    if (s.plane) {
        for (int k = 0; k < 3; ++k) lp.set_a(x0 + k, row, s.normal[static_cast<unsigned>(k)]);
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
        lp.set_a(x0 + k, row + k, 1.0);
        lp.set_b(row + k, 0.0);
        lp.set_r(row + k, CGAL::EQUAL);
    }
    lp.set_b(row + 3, 1.0);
    lp.set_r(row + 3, CGAL::EQUAL);
    row += 4;
}
bool finite(const std::array<double, 3>& x) { return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]); }
// x given by its slabs and half-spaces alone, every value finite?
bool finite_rows_only(const convex_set& x) {
    if (x.plane || !x.points.empty() || !x.generators.empty()) return false;
    for (const auto& sl : x.slabs)
        if (!finite(sl.n) || !std::isfinite(sl.lo) || !std::isfinite(sl.hi)) return false;
    for (const auto& hs : x.halfspaces)
        if (!finite(hs.n) || !std::isfinite(hs.offset)) return false;
    return true;
}
// v given by its points plus bounded generators alone, every value finite?
bool finite_corners_only(const convex_set& v) {
    if (v.plane || !v.slabs.empty() || !v.halfspaces.empty() || v.points.empty() || v.generators.size() > 3) return false;
    for (const auto& g : v.generators)
        if (!g.has_lo || !g.has_hi || !(g.lo <= g.hi) || !finite(g.g) || !std::isfinite(g.lo) || !std::isfinite(g.hi)) return false;
    for (const auto& p : v.points)
        if (!finite(p)) return false;
    return true;
}

using qpoint = std::array<mpq_class, 3>;
qpoint rational(const std::array<double, 3>& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }
mpq_class dot(const qpoint& a, const qpoint& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
qpoint cross(const qpoint& a, const qpoint& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

// The bounds n . y <= c of a set: its half-spaces and the sides of its slabs as given (doubles; a
// slab's lower bound lo <= n . y as -n . y <= -lo, negation being exact), or the faces of a box
// c0 + sum_i s_i a_i, lo_i <= s_i <= hi_i (rationals: with n_i = a_j x a_k and
// D = n_i . a_i = det(a_0, a_1, a_2), n_i . (y - c0) = s_i D).
struct bounds {
    struct given {
        std::array<double, 3> n;
        double c;
    };
    struct exact {
        qpoint n;
        mpq_class c;
    };
    std::vector<given> doubles;
    std::vector<exact> rationals;
};
// The bounds of x when it is slabs and half-spaces alone, or a box with a nonzero determinant.
std::optional<bounds> bounds_of(const convex_set& x) {
    bounds out;
    if (finite_rows_only(x)) {
        out.doubles.reserve(x.halfspaces.size() + 2 * x.slabs.size());
        for (const auto& hs : x.halfspaces) out.doubles.push_back({hs.n, hs.offset});
        for (const auto& sl : x.slabs) {
            out.doubles.push_back({sl.n, sl.hi});
            out.doubles.push_back({{-sl.n[0], -sl.n[1], -sl.n[2]}, -sl.lo});
        }
        return out;
    }
    if (x.points.size() != 1 || x.generators.size() != 3 || !finite_corners_only(x)) return std::nullopt;
    const qpoint a[3] = {rational(x.generators[0].g), rational(x.generators[1].g), rational(x.generators[2].g)};
    const mpq_class det = dot(cross(a[1], a[2]), a[0]);
    if (sgn(det) == 0) return std::nullopt;
    const qpoint c0 = rational(x.points[0]);
    out.rationals.reserve(6);
    for (unsigned i = 0; i < 3; ++i) {
        const qpoint n = cross(a[(i + 1) % 3], a[(i + 2) % 3]);
        const mpq_class at_c0 = dot(n, c0), lo = x.generators[i].lo * det, hi = x.generators[i].hi * det;
        const mpq_class& top = sgn(det) > 0 ? hi : lo;
        const mpq_class& bottom = sgn(det) > 0 ? lo : hi;
        out.rationals.push_back({n, at_c0 + top});
        out.rationals.push_back({{-n[0], -n[1], -n[2]}, -(at_c0 + bottom)});
    }
    return out;
}

// The sign of n . (p + sum_i t_i g_i) - c, t_i the lower or upper bound of generator i as bit i of
// `corner` says: in double when rounding cannot reach it, else in rationals. The double sum has at
// most 13 terms, each a product of at most three doubles: at most 14 roundings on each, under
// 2^-49 of the sum of the terms' magnitudes, plus under 2^-1068 from last products that underflow.
// A first product t g_k that underflows (its error would grow with n_k) leaves the sign to rationals.
int corner_sign(const std::array<double, 3>& n, double c, const std::array<double, 3>& p, const std::vector<convex_set::generator>& gs,
                unsigned corner) {
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

// The corner certificate, for x given by its bounds bs (bounds_of: x's slabs and half-spaces alone,
// or a box's six faces) and v a polytope given by its corners (points, plus up to three generators
// with both bounds: the corners are each point plus every choice of bounds): -1 when every corner
// lies strictly beyond one bound of x (apart: v is the hull of its corners), +1 when one corner
// lies within every bound (a common point), 0 when neither, or when x has no bounds or v has
// another form or a value that is not finite. Every sign is exact (double when rounding cannot
// reach it, else rationals).
int corners_decide(const std::optional<bounds>& bs, const convex_set& v) {
    if (!bs || !finite_corners_only(v)) return 0;
    const unsigned per_point = 1U << v.generators.size();
    const std::size_t count = v.points.size() * per_point;
    std::vector<qpoint> corners; // in rationals, for a box's bounds
    if (!bs->rationals.empty())
        for (const auto& p : v.points)
            for (unsigned m = 0; m < per_point; ++m) {
                qpoint y = rational(p);
                for (unsigned i = 0; i < v.generators.size(); ++i) {
                    const auto& g = v.generators[i];
                    const mpq_class t((m >> i & 1U) ? g.hi : g.lo);
                    for (unsigned k = 0; k < 3; ++k) y[k] += t * g.g[k];
                }
                corners.push_back(y);
            }
    std::vector<bool> inside(count, true);
    // sign(j): the sign of n . y - c at corner j for one bound; true when every corner is beyond it
    auto all_beyond = [&](auto&& sign) {
        bool all = true;
        for (std::size_t j = 0; j < count; ++j)
            if (sign(j) > 0) inside[j] = false;
            else all = false;
        return all;
    };
    for (const auto& b : bs->doubles)
        if (all_beyond([&](std::size_t j) {
                return corner_sign(b.n, b.c, v.points[j / per_point], v.generators, static_cast<unsigned>(j % per_point));
            }))
            return -1;
    for (const auto& b : bs->rationals)
        if (all_beyond([&](std::size_t j) { return sgn(dot(b.n, corners[j]) - b.c); })) return -1;
    for (const bool in : inside)
        if (in) return 1;
    return 0;
}

// Exact clipping in GMP rationals, for x's bounds bs as in corners_decide and v a point, a segment or a
// triangle (one to three points: the convex polygon of v cut by each bound in turn, Sutherland and
// Hodgman 1974) or p + t g with one generator (a segment, ray or line: the interval of t cut by
// each bound). Whether they meet; nothing when x or v has another form or a value that is not finite.
std::optional<bool> clip_decide(const std::optional<bounds>& bs, const convex_set& v) {
    if (!bs || v.plane || !v.slabs.empty() || !v.halfspaces.empty() || v.points.empty()) return std::nullopt;
    for (const auto& p : v.points)
        if (!finite(p)) return std::nullopt;
    std::vector<std::pair<qpoint, mpq_class>> rows; // n . y <= c
    for (const auto& b : bs->doubles) rows.emplace_back(rational(b.n), mpq_class(b.c));
    for (const auto& b : bs->rationals) rows.emplace_back(b.n, b.c);
    if (v.points.size() == 1 && v.generators.size() == 1) { // p + t g, t within the generator's bounds
        const auto& g = v.generators[0];
        if (!finite(g.g) || (g.has_lo && !std::isfinite(g.lo)) || (g.has_hi && !std::isfinite(g.hi))) return std::nullopt;
        bool has_lo = g.has_lo, has_hi = g.has_hi;
        mpq_class lo(g.has_lo ? g.lo : 0.0), hi(g.has_hi ? g.hi : 0.0);
        const qpoint p = rational(v.points[0]), d = rational(g.g);
        for (const auto& [n, c] : rows) { // n . p - c + t n . d <= 0
            const mpq_class at_p = dot(n, p) - c, a = dot(n, d);
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
    std::vector<qpoint> poly, next;
    for (const auto& p : v.points) poly.push_back(rational(p));
    std::vector<mpq_class> d;
    for (const auto& [n, c] : rows) { // keep the part with n . y <= c: the closed polygon's vertices and edge crossings
        d.clear();
        for (const auto& y : poly) d.push_back(dot(n, y) - c);
        next.clear();
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const std::size_t j = (i + 1) % poly.size();
            if (sgn(d[i]) <= 0) next.push_back(poly[i]);
            if ((sgn(d[i]) < 0 && sgn(d[j]) > 0) || (sgn(d[i]) > 0 && sgn(d[j]) < 0)) {
                const mpq_class t = d[i] / (d[i] - d[j]);
                qpoint y;
                for (unsigned k = 0; k < 3; ++k) y[k] = poly[i][k] + t * (poly[j][k] - poly[i][k]);
                next.push_back(y);
            }
        }
        if (next.empty()) return false;
        poly.swap(next);
    }
    return true;
}
} // namespace

std::optional<bool> lp_intersect_verified(const convex_set& a, const convex_set& b) {
    // Independent of the LP below and exact: decides most random cases far faster.
    const auto bounds_a = bounds_of(a), bounds_b = bounds_of(b);
    if (const int r = corners_decide(bounds_b, a)) return r > 0;
    if (const int r = corners_decide(bounds_a, b)) return r > 0;
    // Exact clipping in rationals, for a point, segment, triangle, ray or line against bounds.
    if (const auto r = clip_decide(bounds_b, a)) return r;
    if (const auto r = clip_decide(bounds_a, b)) return r;
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

namespace {
// The exact minimum of the QP's objective, once CGAL's certificate check accepts a pricing
// strategy's solution: std::nullopt when none is accepted, an empty set as infeasible.
struct qp_minimum {
    bool infeasible = false;
    mpq_class value;
};
std::optional<qp_minimum> minimum(const program& qp) {
    const auto gmpq = [](const CGAL::Gmpzf& f) { // m 2^e, exactly
        mpq_class q(mpz_class(f.man()));
        if (f.exp() >= 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(f.exp()));
        else mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-f.exp()));
        return q;
    };
    for (const auto pricing : {CGAL::QP_DANTZIG, CGAL::QP_PARTIAL_DANTZIG, CGAL::QP_BLAND}) {
        CGAL::Quadratic_program_options options;
        options.set_pricing_strategy(pricing);
        auto sol = CGAL::solve_quadratic_program(qp, CGAL::Gmpzf(), options);
        if (!sol.solves_quadratic_program(qp)) continue; // CGAL's own certificate check
        if (sol.is_infeasible()) return qp_minimum{true, 0};
        if (!sol.is_optimal()) continue;
        const auto v = sol.objective_value();
        return qp_minimum{false, gmpq(v.numerator()) / gmpq(v.denominator())};
    }
    return std::nullopt;
}
} // namespace

std::optional<bool> qp_ball_meets(const convex_set& s, const std::array<double, 3>& c, double r) {
    const auto d = qp_squared_distance(s, c);
    if (!d) return std::nullopt;
    if (!*d) return false; // the set is empty
    return **d <= mpq_class(r) * mpq_class(r);
}

// The least |x - y|^2 / 2 over x in a and y in b, or nullopt (declined), or infeasible.
static std::optional<qp_minimum> sets_half_squared_distance(const convex_set& a, const convex_set& b) {
    // minimise |x - y|^2 / 2 over x in a (variables 0, 1, 2) and y in b (3, 4, 5)
    program qp(CGAL::EQUAL, false, 0.0, false, 0.0);
    int var = 6, row = 0;
    add(qp, var, row, a, 0);
    add(qp, var, row, b, 3);
    for (int k = 0; k < 3; ++k) { // CGAL's D is twice the quadratic form, its lower triangle
        qp.set_d(k, k, 1.0);
        qp.set_d(k + 3, k + 3, 1.0);
        qp.set_d(k + 3, k, -1.0);
    }
    return minimum(qp);
}

std::optional<mpq_class> qp_sets_squared_distance(const convex_set& a, const convex_set& b) {
    const auto m = sets_half_squared_distance(a, b);
    if (!m || m->infeasible) return std::nullopt;
    return mpq_class(2 * m->value);
}

std::optional<bool> qp_sets_within(const convex_set& a, const convex_set& b, double r1, double r2) {
    const auto m = sets_half_squared_distance(a, b);
    if (!m) return std::nullopt;
    if (m->infeasible) return false;
    const mpq_class reach = abs(mpq_class(r1)) + abs(mpq_class(r2));
    return 2 * m->value <= reach * reach;
}

bool ball_in_rows(const convex_set& s, const std::array<double, 3>& c, double r) {
    const qpoint q = rational(c);
    const mpq_class rr = mpq_class(r) * mpq_class(r);
    // n . c + |r| |n| <= bound: bound - n . c >= 0 and (bound - n . c)^2 >= r^2 |n|^2
    auto within = [&](const std::array<double, 3>& n, double bound) {
        const qpoint m = rational(n);
        const mpq_class room = mpq_class(bound) - dot(m, q);
        return sgn(room) >= 0 && room * room >= rr * dot(m, m);
    };
    for (const auto& h : s.halfspaces)
        if (!within(h.n, h.offset)) return false;
    for (const auto& sl : s.slabs)
        if (!within(sl.n, sl.hi) || !within({-sl.n[0], -sl.n[1], -sl.n[2]}, -sl.lo)) return false;
    return true;
}

std::optional<std::optional<mpq_class>> qp_squared_distance(const convex_set& s, const std::array<double, 3>& c) {
    // minimise |x|^2 / 2 - c . x = (|x - c|^2 - |c|^2) / 2 over the set (x: variables 0, 1, 2)
    program qp(CGAL::EQUAL, false, 0.0, false, 0.0);
    int var = 3, row = 0;
    add(qp, var, row, s);
    for (int k = 0; k < 3; ++k) {
        qp.set_d(k, k, 1.0); // CGAL's D is twice the quadratic form
        qp.set_c(k, -c[static_cast<unsigned>(k)]);
    }
    const auto m = minimum(qp);
    if (!m) return std::nullopt;
    if (m->infeasible) return std::optional<mpq_class>{};
    const qpoint q = rational(c);
    return std::optional<mpq_class>{2 * m->value + dot(q, q)};
}

std::optional<std::vector<exact_row>> exact_rows(const convex_set& s) {
    const auto b = bounds_of(s);
    if (!b) return std::nullopt;
    std::vector<exact_row> out;
    for (const auto& g : b->doubles) out.push_back({rational(g.n), mpq_class(g.c)});
    for (const auto& r : b->rationals) out.push_back({r.n, r.c});
    return out;
}

bool lp_intersect(const convex_set& a, const convex_set& b) {
    if (const auto r = lp_intersect_verified(a, b)) return *r;
    throw std::runtime_error("lp_intersect: no pricing strategy gave a verified answer");
}

} // namespace oracle
