// Boxes and balls against one frustum (or any six half-spaces), in SIMD lanes: the kernels behind
// batch::intersects(frustum, boxes | obbs | balls) (modules/batch/culling.cppm declares it). Highway compiles this
// file once per target and dispatches at run time, as ray_triangles_simd.cpp.
//
// A lane does the three stages of the scalar query (halfspaces::box_meets in
// modules/engines/halfspace_lp.cppm) that come before its linear program, operation for
// operation, so that what it decides is the scalar answer bit for bit:
// 1. for each plane in order, c - n . q with q the box corner least along n: negative says no;
// 2. then, with every plane passed, c - n . m at the box's clamped middle m: positive at every
//    plane says yes; so does the same at the box corner least along n_i, for a plane i the middle
//    is not inside;
// 3. then, for each plane that two of the six imply along an edge-edge axis (the caller's list,
//    halfspaces::edge_planes, computed once for the batch in the tier's kernel as the scalar
//    query computes it per box), alpha (c_i - n_i . q) + beta (c_j - n_j . q) at the box corner
//    q the list names: negative says no.
// A lane no stage decides is left to the scalar query (its linear program): the boxes near the
// frustum's edges and corners. approximate: plain double. The filtered tiers: each sign of the
// scalar filter (degree 2, gamma_4; stage 3 degree 3, gamma_6), stages 1 and 2 against a static
// bound per plane and block of 64 lanes and then, where that leaves a lane undecided, the lane's
// own permanent, stage 3 against the lane's own; a lane whose plane sign is unproven before a
// negative one is left open too, as the scalar filter pass fails there. A box with a non-finite
// bound or an inverted box meets nothing. The caller passes finite planes only (a frustum with a
// non-finite number is no set: the scalar query's answer).
#include <cstddef>
#include <cstdint>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/batch/culling_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>
#include "modules/batch/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// c 1 - ((n_x x + n_y y) + n_z z), the scalar expression, for one plane (n, c) broadcast and a
// point of the lanes: in the filter, with its permanent.
HWY_INLINE fv plane_value(D d, const double* plane, const V* x) {
    auto in = [&](double v) { return fv{hn::Set(d, v), hn::Set(d, v < 0 ? -v : v)}; };
    auto lane = [&](V v) { return fv{v, hn::Abs(v)}; };
    const fv one = in(1.0);
    return in(plane[3]) * one - (in(plane[0]) * lane(x[0]) + in(plane[1]) * lane(x[1]) + in(plane[2]) * lane(x[2]));
}
HWY_INLINE V plane_value_alone(D d, const double* plane, const V* x) {
    const pv one{hn::Set(d, 1.0)};
    return (pv{hn::Set(d, plane[3])} * one -
            (pv{hn::Set(d, plane[0])} * pv{x[0]} + pv{hn::Set(d, plane[1])} * pv{x[1]} + pv{hn::Set(d, plane[2])} * pv{x[2]}))
        .v;
}

// A sign's two masks: proven positive, proven negative (approximate: the signs of plain double).
struct sign_masks {
    M pos, neg;
};

// planes: six planes as (n_x, n_y, n_z, c); edges: `edge_count` implied planes as (i, j, alpha,
// beta, upper_x, upper_y, upper_z); boxes: min x, y, z, max x, y, z, arrays of n.
void frustum_box(const double* planes, const double* edges, int edge_count, const double* const* boxes, std::size_t n, bool filter,
                 std::uint8_t* out) {
    const D d;
    constexpr double gamma = gamma_of(4);         // c 1: one operation; each n_k q_k one, two sums, the difference
    constexpr double gamma_implied = gamma_of(6); // alpha times that, and the sum of two
    constexpr std::size_t block = 64;
    const M none = hn::Not(hn::Eq(hn::Zero(d), hn::Zero(d)));
    fields all{{}, {}, 6};
    for (int k = 0; k < 6; ++k) all.p[k] = boxes[k], all.per_lane[k] = true;
    auto load = [&](const fields& g, std::size_t i, std::size_t count, V* mn, V* mx) {
        M usable = hn::FirstN(d, count);
        for (int k = 0; k < 3; ++k) {
            mn[k] = g.at(d, k, i), mx[k] = g.at(d, 3 + k, i);
            usable = hn::And(usable, hn::And(hn::And(hn::IsFinite(mn[k]), hn::IsFinite(mx[k])), hn::Le(mn[k], mx[k])));
        }
        return usable;
    };
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const fields f = from(all, start);
        // the filter's static bound per plane, from the block's largest |coordinate| on each axis
        // (any point of a box, and so every point a stage tries, is within it)
        V bound[6];
        if (filter) {
            V most[3] = {hn::Zero(d), hn::Zero(d), hn::Zero(d)};
            over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t, std::size_t count) {
                V mn[3], mx[3];
                const M usable = load(g, i, count, mn, mx);
                for (int k = 0; k < 3; ++k) most[k] = hn::Max(most[k], hn::IfThenElseZero(usable, hn::Max(hn::Abs(mn[k]), hn::Abs(mx[k]))));
            });
            pp big[3];
            for (int k = 0; k < 3; ++k) big[k] = {hn::GetLane(hn::MaxOfLanes(d, most[k]))};
            for (int p = 0; p < 6; ++p) {
                const double* h = planes + 4 * p;
                auto in = [](double v) { return pp{v < 0 ? -v : v}; };
                bound[p] = static_bound(d, gamma, (in(h[3]) * pp{1.0} - (in(h[0]) * big[0] + in(h[1]) * big[1] + in(h[2]) * big[2])).p);
            }
        }
        // plane p's sign at x for the lanes in `care`: the static bound, then each lane's own
        // the box corner least along plane p's normal (halfspaces' least_corner: min where n_k > 0)
        auto least_corner = [&](int p, const V* mn, const V* mx, V* q) {
            for (int k = 0; k < 3; ++k) q[k] = planes[4 * p + k] > 0 ? mn[k] : mx[k];
        };
        auto test = [&](int p, const V* x, M care) {
            const double* plane = planes + 4 * p;
            const V v = plane_value_alone(d, plane, x);
            if (!filter) return sign_masks{hn::Gt(v, hn::Zero(d)), hn::Lt(v, hn::Zero(d))};
            sign_masks s{hn::Gt(v, bound[p]), hn::Lt(v, hn::Neg(bound[p]))};
            if (!hn::AllFalse(d, hn::AndNot(hn::Or(s.pos, s.neg), care))) {
                const fv own = plane_value(d, plane, x);
                s = {own_positive(d, gamma, own), own_negative(d, gamma, own)};
            }
            return s;
        };
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t lane, std::size_t count) {
            V mn[3], mx[3];
            const M usable = load(g, i, count, mn, mx);
            // stage 1: alive, the lanes every plane so far has proven short of the box's far side
            M alive = usable, open = none;
            for (int p = 0; p < 6 && !hn::AllFalse(d, alive); ++p) {
                V q[3];
                least_corner(p, mn, mx, q);
                const sign_masks s = test(p, q, alive);
                if (filter) open = hn::Or(open, hn::AndNot(hn::Or(s.pos, s.neg), alive));
                alive = filter ? hn::And(alive, s.pos) : hn::AndNot(s.neg, alive);
            }
            // stage 2: the box's middle strictly inside every plane, or for a plane it is not
            // inside, the box corner least along that plane's normal
            M yes = alive;
            if (!hn::AllFalse(d, alive)) {
                V c[3];
                for (int k = 0; k < 3; ++k) {
                    const V mid = hn::Add(hn::Mul(hn::Set(d, 0.5), mn[k]), hn::Mul(hn::Set(d, 0.5), mx[k]));
                    c[k] = hn::Min(hn::Max(mid, mn[k]), mx[k]);
                }
                M middle_outside[6];
                for (int p = 0; p < 6; ++p) {
                    middle_outside[p] = hn::Not(test(p, c, alive).pos);
                    yes = hn::AndNot(middle_outside[p], yes);
                }
                M corner_inside = none;
                for (int p = 0; p < 6; ++p) {
                    const M tried = hn::AndNot(yes, hn::And(alive, middle_outside[p]));
                    if (hn::AllFalse(d, hn::AndNot(corner_inside, tried))) continue;
                    V q[3];
                    least_corner(p, mn, mx, q);
                    M inside = tried;
                    for (int j = 0; j < 6; ++j) inside = hn::And(inside, test(j, q, tried).pos);
                    corner_inside = hn::Or(corner_inside, inside);
                }
                yes = hn::Or(yes, corner_inside);
                // stage 3: the lanes alive and not accepted, beyond an implied plane
                const M rest = hn::AndNot(yes, alive);
                M beyond = none;
                for (int e = 0; e < edge_count && !hn::AllFalse(d, hn::AndNot(beyond, rest)); ++e) {
                    const double* x = edges + 7 * e;
                    const double* pi = planes + 4 * static_cast<int>(x[0]);
                    const double* pj = planes + 4 * static_cast<int>(x[1]);
                    V q[3];
                    for (int k = 0; k < 3; ++k) q[k] = x[4 + k] != 0 ? mx[k] : mn[k];
                    if (filter) {
                        const fv alpha{hn::Set(d, x[2]), hn::Set(d, x[2])}, beta{hn::Set(d, x[3]), hn::Set(d, x[3])};
                        beyond =
                            hn::Or(beyond, own_negative(d, gamma_implied, alpha * plane_value(d, pi, q) + beta * plane_value(d, pj, q)));
                    } else {
                        const V v = (pv{hn::Set(d, x[2])} * pv{plane_value_alone(d, pi, q)} +
                                     pv{hn::Set(d, x[3])} * pv{plane_value_alone(d, pj, q)})
                                        .v;
                        beyond = hn::Or(beyond, hn::Lt(v, hn::Zero(d)));
                    }
                }
                open = hn::Or(open, hn::AndNot(beyond, rest));
            }
            store_answers(d, yes, open, out + start + lane, count);
        });
    }
}

// Oriented boxes against six planes: the two stages of the scalar query (halfspaces::obb_meets in
// modules/engines/halfspace_meets.cppm) before its linear program, operation for operation:
// 1. for each plane in order, box_reach: (c 1 - n . q) 1 + sum_j h_j |n . a_j| (q the centre,
//    a_j the axes, h_j the half extents; the box's least value of c - n . x, times one): negative
//    says no (degree 3, gamma_7);
// 2. then the centre strictly inside every plane (c 1 - n . q; degree 2, gamma_4), or for a plane
//    it is not proven inside of, the box corner least along that plane's normal strictly inside
//    every plane ((c 1 - n . q) 1 - sum_j s_j (n . a_j), s_j = -h_j where n_p . a_j > 0 in
//    double, else h_j; degree 3, gamma_7), says yes.
// In the filter a sign unproven at stage 1 before a negative one fails the scalar pass: the lane
// is left open. Stage 2's signs are checks whose failure decides nothing: a lane they do not
// accept goes to the scalar query's linear program.
// obbs: 15 arrays of n (centre x, y, z; axis 0 x, y, z; axis 1; axis 2; half extents 0, 1, 2).
// A box with a non-finite number or a negative (or NaN) half extent meets nothing.
void frustum_obb(const double* planes, const double* const* obbs, std::size_t n, bool filter, std::uint8_t* out) {
    const D d;
    constexpr double gamma_reach = gamma_of(7), gamma_centre = gamma_of(4);
    constexpr std::size_t block = 64;
    const M none = hn::Not(hn::Eq(hn::Zero(d), hn::Zero(d)));
    fields all{{}, {}, 15};
    for (int k = 0; k < 15; ++k) all.p[k] = obbs[k], all.per_lane[k] = true;
    auto load = [&](const fields& g, std::size_t i, std::size_t count, lanes_obb& b) {
        return load_obb(d, g, i, count, b, [](V x) { return hn::IsFinite(x); });
    };
    // box_reach for plane p, in the filter (with its permanent) or alone
    auto in = [&](double v) { return fv{hn::Set(d, v), hn::Set(d, v < 0 ? -v : v)}; };
    auto lane = [&](V v) { return fv{v, hn::Abs(v)}; };
    auto magnitude = [&](fv x) { return fv{hn::Abs(x.v), x.p}; };
    auto reach = [&](int p, const lanes_obb& b) {
        const double* h = planes + 4 * p;
        const fv nx = in(h[0]), ny = in(h[1]), nz = in(h[2]), one = in(1.0);
        const fv gap = (in(h[3]) * one - (nx * lane(b.c[0]) + ny * lane(b.c[1]) + nz * lane(b.c[2]))) * one;
        auto along = [&](int j) { return lane(b.h[j]) * magnitude(nx * lane(b.a[j][0]) + ny * lane(b.a[j][1]) + nz * lane(b.a[j][2])); };
        return gap + (along(0) + along(1) + along(2));
    };
    auto reach_alone = [&](int p, const lanes_obb& b) {
        const double* h = planes + 4 * p;
        const pv nx{hn::Set(d, h[0])}, ny{hn::Set(d, h[1])}, nz{hn::Set(d, h[2])}, one{hn::Set(d, 1.0)};
        const pv gap = (pv{hn::Set(d, h[3])} * one - (nx * pv{b.c[0]} + ny * pv{b.c[1]} + nz * pv{b.c[2]})) * one;
        auto along = [&](int j) { return pv{b.h[j]} * pv{hn::Abs((nx * pv{b.a[j][0]} + ny * pv{b.a[j][1]} + nz * pv{b.a[j][2]}).v)}; };
        return (gap + (along(0) + along(1) + along(2))).v;
    };
    // c - n . x at the box corner x = centre + sum_j s_j a_j (s_j = +-h_j), scaled as box_reach
    auto corner = [&](int p, const lanes_obb& b, const V* s) {
        const double* h = planes + 4 * p;
        const fv nx = in(h[0]), ny = in(h[1]), nz = in(h[2]), one = in(1.0);
        const fv gap = (in(h[3]) * one - (nx * lane(b.c[0]) + ny * lane(b.c[1]) + nz * lane(b.c[2]))) * one;
        auto along = [&](int j) { return lane(s[j]) * (nx * lane(b.a[j][0]) + ny * lane(b.a[j][1]) + nz * lane(b.a[j][2])); };
        return gap - (along(0) + along(1) + along(2));
    };
    auto corner_alone = [&](int p, const lanes_obb& b, const V* s) {
        const double* h = planes + 4 * p;
        const pv nx{hn::Set(d, h[0])}, ny{hn::Set(d, h[1])}, nz{hn::Set(d, h[2])}, one{hn::Set(d, 1.0)};
        const pv gap = (pv{hn::Set(d, h[3])} * one - (nx * pv{b.c[0]} + ny * pv{b.c[1]} + nz * pv{b.c[2]})) * one;
        auto along = [&](int j) { return pv{s[j]} * (nx * pv{b.a[j][0]} + ny * pv{b.a[j][1]} + nz * pv{b.a[j][2]}); };
        return (gap - (along(0) + along(1) + along(2))).v;
    };
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const fields f = from(all, start);
        // the filter's static bounds per plane, from the block's largest |number| of each field
        // (stage 1's also bounds the corners' values: the same permanent)
        V bound_reach[6], bound_centre[6];
        if (filter) {
            V most[15];
            for (V& x : most) x = hn::Zero(d);
            over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t, std::size_t count) {
                lanes_obb b;
                const M usable = load(g, i, count, b);
                auto keep = [&](int k, V x) { most[k] = hn::Max(most[k], hn::IfThenElseZero(usable, hn::Abs(x))); };
                for (int k = 0; k < 3; ++k) {
                    keep(k, b.c[k]), keep(12 + k, b.h[k]);
                    for (int j = 0; j < 3; ++j) keep(3 + 3 * j + k, b.a[j][k]);
                }
            });
            pp big[15];
            for (int k = 0; k < 15; ++k) big[k] = {hn::GetLane(hn::MaxOfLanes(d, most[k]))};
            for (int p = 0; p < 6; ++p) {
                const double* h = planes + 4 * p;
                auto abs_of = [](double v) { return pp{v < 0 ? -v : v}; };
                const pp nx = abs_of(h[0]), ny = abs_of(h[1]), nz = abs_of(h[2]), one{1.0};
                const pp gap = (abs_of(h[3]) * one - (nx * big[0] + ny * big[1] + nz * big[2])) * one;
                auto along = [&](int j) { return big[12 + j] * (nx * big[3 + 3 * j] + ny * big[4 + 3 * j] + nz * big[5 + 3 * j]); };
                bound_reach[p] = static_bound(d, gamma_reach, (gap + (along(0) + along(1) + along(2))).p);
                bound_centre[p] = static_bound(d, gamma_centre, (abs_of(h[3]) * one - (nx * big[0] + ny * big[1] + nz * big[2])).p);
            }
        }
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t lane_at, std::size_t count) {
            lanes_obb b;
            const M usable = load(g, i, count, b);
            // stage 1: alive, the lanes every plane so far has proven short of the box's far side
            M alive = usable, open = none;
            for (int p = 0; p < 6 && !hn::AllFalse(d, alive); ++p) {
                const V v = reach_alone(p, b);
                if (!filter) {
                    alive = hn::AndNot(hn::Lt(v, hn::Zero(d)), alive);
                    continue;
                }
                sign_masks s{hn::Gt(v, bound_reach[p]), hn::Lt(v, hn::Neg(bound_reach[p]))};
                if (!hn::AllFalse(d, hn::AndNot(hn::Or(s.pos, s.neg), alive))) {
                    const fv own = reach(p, b);
                    s = {own_positive(d, gamma_reach, own), own_negative(d, gamma_reach, own)};
                }
                open = hn::Or(open, hn::AndNot(hn::Or(s.pos, s.neg), alive));
                alive = hn::And(alive, s.pos);
            }
            // stage 2: the centre strictly inside every plane, or for a plane it is not inside, the
            // box corner least along that plane's normal (checks whose failure decides nothing)
            M yes = alive, centre_outside[6];
            for (M& x : centre_outside) x = none;
            for (int p = 0; p < 6; ++p) {
                if (hn::AllFalse(d, alive)) break;
                const double* h = planes + 4 * p;
                if (!filter) {
                    centre_outside[p] = hn::Not(hn::Gt(plane_value_alone(d, h, b.c), hn::Zero(d)));
                } else {
                    M pos = hn::Gt(plane_value_alone(d, h, b.c), bound_centre[p]);
                    if (!hn::AllFalse(d, hn::AndNot(pos, alive))) pos = own_positive(d, gamma_centre, plane_value(d, h, b.c));
                    centre_outside[p] = hn::Not(pos);
                }
                yes = hn::AndNot(centre_outside[p], yes);
            }
            M corner_yes = none;
            for (int p = 0; p < 6 && !hn::AllFalse(d, alive); ++p) {
                const M tried = hn::AndNot(yes, hn::AndNot(corner_yes, hn::And(alive, centre_outside[p])));
                if (hn::AllFalse(d, tried)) continue;
                // s_j h_j: -h_j where n_p . a_j > 0 in double (the scalar's choice), else h_j
                const double* along = planes + 4 * p;
                V s[3];
                for (int j = 0; j < 3; ++j) {
                    const V t = hn::Add(hn::Add(hn::Mul(hn::Set(d, along[0]), b.a[j][0]), hn::Mul(hn::Set(d, along[1]), b.a[j][1])),
                                        hn::Mul(hn::Set(d, along[2]), b.a[j][2]));
                    s[j] = hn::IfThenElse(hn::Gt(t, hn::Zero(d)), hn::Neg(b.h[j]), b.h[j]);
                }
                M inside = tried;
                for (int q = 0; q < 6 && !hn::AllFalse(d, inside); ++q) {
                    if (!filter) {
                        inside = hn::And(inside, hn::Gt(corner_alone(q, b, s), hn::Zero(d)));
                        continue;
                    }
                    M pos = hn::Gt(corner_alone(q, b, s), bound_reach[q]);
                    if (!hn::AllFalse(d, hn::AndNot(pos, inside))) pos = own_positive(d, gamma_reach, corner(q, b, s));
                    inside = hn::And(inside, pos);
                }
                corner_yes = hn::Or(corner_yes, inside);
            }
            yes = hn::Or(yes, corner_yes);
            open = hn::Or(open, hn::AndNot(yes, alive)); // alive, the centre not proven inside: the linear program
            store_answers(d, yes, open, out + start + lane_at, count);
        });
    }
}

// Balls against the six planes: the scalar query's first stage (ball_rows::sides_of in
// modules/engines/ball_halfspaces.cppm), operation for operation. For each plane in order,
// e = n . c - c_p 1 (gamma_4); where e > 0, e e - (r r) (n . n) (gamma_10): positive says no (the
// ball wholly beyond the plane), and the scalar loop stops there. Every e proven negative says yes
// (the centre inside); a lane with the centre beyond some plane and no plane with the ball wholly
// beyond it goes to the scalar query (its search for the nearest face, edge or vertex), and so
// does a lane with a sign unproven before it is decided, as the scalar filter pass fails there.
// The filter's bounds are each lane's own permanents. A ball with a non-finite number meets
// nothing. The caller passes finite planes with nonzero normals only.
void frustum_ball(const double* planes, const double* const* balls, std::size_t n, bool filter, std::uint8_t* out) {
    const D d;
    constexpr double gamma_side = gamma_of(4), gamma_apart = gamma_of(10);
    const M none = hn::Not(hn::Eq(hn::Zero(d), hn::Zero(d)));
    fields all{{}, {}, 4};
    for (int k = 0; k < 4; ++k) all.p[k] = balls[k], all.per_lane[k] = true;
    auto in = [&](double v) { return fv{hn::Set(d, v), hn::Set(d, v < 0 ? -v : v)}; };
    auto lane = [&](V v) { return fv{v, hn::Abs(v)}; };
    over_fields(d, all, n, [&](const fields& g, std::size_t i, std::size_t lane_at, std::size_t count) {
        V c[3];
        M usable = hn::FirstN(d, count);
        for (int k = 0; k < 3; ++k) c[k] = g.at(d, k, i), usable = hn::And(usable, hn::IsFinite(c[k]));
        const V r = g.at(d, 3, i);
        usable = hn::And(usable, hn::IsFinite(r));
        // live: the lanes the scalar loop still runs; open: left to the scalar query
        M live = usable, open = none, outside = none, apart = none;
        // the lanes of `among` where x > 0: in plain double, or proven (a sign left unproven leaves
        // its lane to the scalar query, as the scalar filter pass fails there)
        auto positive = [&](const fv& x, double gamma, M among) {
            if (!filter) return hn::And(among, hn::Gt(x.v, hn::Zero(d)));
            const M pos = own_positive(d, gamma, x), unproven = hn::AndNot(hn::Or(pos, own_negative(d, gamma, x)), among);
            open = hn::Or(open, unproven);
            live = hn::AndNot(unproven, live);
            return hn::And(hn::AndNot(unproven, among), pos);
        };
        for (int p = 0; p < 6 && !hn::AllFalse(d, live); ++p) {
            const double* h = planes + 4 * p;
            const fv nx = in(h[0]), ny = in(h[1]), nz = in(h[2]);
            const fv e = (nx * lane(c[0]) + ny * lane(c[1]) + nz * lane(c[2])) - in(h[3]) * in(1.0);
            const M beyond = positive(e, gamma_side, live);
            if (hn::AllFalse(d, beyond)) continue;
            outside = hn::Or(outside, beyond);
            const M wholly = positive(e * e - (lane(r) * lane(r)) * (nx * nx + ny * ny + nz * nz), gamma_apart, beyond);
            apart = hn::Or(apart, wholly);
            live = hn::AndNot(wholly, live);
        }
        const M yes = hn::AndNot(hn::Or(open, hn::Or(apart, outside)), usable);
        open = hn::Or(open, hn::AndNot(apart, hn::And(usable, outside)));
        store_answers(d, yes, open, out + lane_at, count);
    });
}

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(frustum_box);
HWY_EXPORT(frustum_obb);
HWY_EXPORT(frustum_ball);

// The entry point (declared extern "C++" in modules/batch/culling.cppm).
void frustum_boxes(const double* planes, const double* edges, int edge_count, const double* const* boxes, std::size_t n, bool filter,
                   std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(frustum_box)(planes, edges, edge_count, boxes, n, filter, out);
}
void frustum_obbs(const double* planes, const double* const* obbs, std::size_t n, bool filter, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(frustum_obb)(planes, obbs, n, filter, out);
}
void frustum_balls(const double* planes, const double* const* balls, std::size_t n, bool filter, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(frustum_ball)(planes, balls, n, filter, out);
}
} // namespace incidence::batch::simd
#endif
