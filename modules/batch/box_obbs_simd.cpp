// Oriented boxes against one axis-aligned box, in SIMD lanes: the kernel behind
// batch::intersects(aabb3, obbs) (modules/batch/solids.cppm declares it). Highway compiles this
// file once per target and dispatches at run time, as ray_triangles_simd.cpp.
//
// A lane evaluates the scalar query's 15 separating axes (sat::box_box_pass in
// modules/engines/separating_axes.cppm, as modules/query/intersects/obb_pairs.cppm calls it: the
// box read as a zonotope with the unit generators, the oriented box in place) operation for
// operation. With those generators most of the pass's products are by 1 or 0 and
// exact, so a lane computes only what remains: the axis values are the same doubles. Face
// axes of the box (= the coordinate axes, box_box_fast's first stage):
//   |d_m| - a_m - ((b_0 |B_0m| + b_1 |B_1m|) + b_2 |B_2m|)
// face axes of the oriented box, n_m = B_j x B_k (m, j, k cyclic), det = n_0 . B_0:
//   |n_m . d| - b_m |det| - ((a_0 |n_mx| + a_1 |n_my|) + a_2 |n_mz|)
// edge axes e_i x B_j, E_j = B_j x d:
//   |E_j[i]| - (a_{i+1} |B_j[i+2]| + a_{i+2} |B_j[i+1]|) - (b_{j+1} |n_{j+2}[i]| + b_{j+2} |n_{j+1}[i]|)
// (d = 2 c - (min + max), a_m = max_m - min_m, b_j = 2 h_j). A positive axis says no; all 15
// negative, with the box solid (no zero extent) or the oriented box solid with det nonzero, says
// yes; anything else (a zero axis, flat boxes) is left to the scalar query (2), which then takes
// its general path. approximate: plain double signs, the scalar's own; a lane whose numbers are
// not finite, or whose values overflow (then the scalar's products by 0 are NaN where these are
// not), is left open. The filtered tiers: each sign against the static bound of its axis family
// (sat::box_box_static_bounds, from the block of 64 lanes' largest magnitudes and the scalar's own
// gamma per family, which the caller passes): a bound at least the scalar's for every lane, so a
// lane decides only where the scalar's bounded pass decides too, and the same way. A lane with a
// number above 2^149 in magnitude, non-finite, or a negative or NaN extent is left open.
#include <cstddef>
#include <cstdint>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/batch/box_obbs_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>
#include "modules/batch/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// box: six values (min x, y, z, max x, y, z); obbs: fifteen arrays of n (centre, axes, half
// extents); gammas: the scalar filter's gamma for the face axes of the box, of the oriented box,
// the edge axes, and the two determinants, or null for the approximate tier.
void box_obb(const double* const* box, const double* const* obbs, std::size_t n, const double* gammas, std::uint8_t* out) {
    const D d;
    constexpr std::size_t block = 64;
    constexpr double top = 0x1p150; // sat::box_box_static_bounds' range
    const bool filter = gammas != nullptr;
    double lo[3], hi[3], s[3], a[3];
    bool finite = true, solid_box = true;
    for (int k = 0; k < 3; ++k) {
        lo[k] = *box[k], hi[k] = *box[3 + k];
        s[k] = lo[k] + hi[k], a[k] = hi[k] + -lo[k]; // box_centre2 and box_extent2 of the zonotope
        finite = finite && s[k] - s[k] == 0.0 && a[k] - a[k] == 0.0;
        solid_box = solid_box && hi[k] != lo[k];
    }
    // an inverted box meets nothing, a box with a non-finite sum is the scalar query's to answer
    if (!(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2])) {
        std::memset(out, 0, n);
        return;
    }
    if (!finite) {
        std::memset(out, 2, n);
        return;
    }
    auto abs_of = [](double v) { return v < 0 ? -v : v; };
    auto largest = [](double x, double y) { return x > y ? x : y; };
    // the box's magnitudes (sat::magnitudes_of): generators 1, extent, centre per coordinate
    const double box_extent =
        largest(largest(abs_of(hi[0]) + abs_of(-lo[0]), abs_of(hi[1]) + abs_of(-lo[1])), abs_of(hi[2]) + abs_of(-lo[2]));
    double box_centre[3];
    for (int k = 0; k < 3; ++k) box_centre[k] = abs_of(lo[k]) + abs_of(hi[k]);
    fields all{{}, {}, 15};
    for (int k = 0; k < 15; ++k) all.p[k] = obbs[k], all.per_lane[k] = true;
    // a lane is usable with every number finite (approximate) or within 2^149 (the filter's range)
    auto load = [&](const fields& g, std::size_t i, std::size_t count, lanes_obb& b) {
        const V cap = hn::Set(d, 0x1p149);
        if (filter) return load_obb(d, g, i, count, b, [&](V x) { return hn::Le(hn::Abs(x), cap); });
        return load_obb(d, g, i, count, b, [](V x) { return hn::IsFinite(x); });
    };
    const M none = hn::Not(hn::Eq(hn::Zero(d), hn::Zero(d)));
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const fields f = from(all, start);
        // the static bounds, by box_axis_kind: face of the box, face of the oriented box, edge
        // pair, det of the box, det of the oriented box
        V bound[5];
        double bound_det_box = 0;
        if (filter) {
            V most_generator = hn::Zero(d), most_extent = hn::Zero(d), most_centre[3] = {hn::Zero(d), hn::Zero(d), hn::Zero(d)};
            over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t, std::size_t count) {
                lanes_obb b;
                const M usable = load(g, i, count, b);
                auto most = [&](V x, V y) { return hn::Max(hn::Abs(x), hn::Abs(y)); };
                // in trees, so that the maxima do not wait on each other
                const V generator = hn::Max(hn::Max(hn::Max(most(b.a[0][0], b.a[0][1]), most(b.a[0][2], b.a[1][0])),
                                                    hn::Max(most(b.a[1][1], b.a[1][2]), most(b.a[2][0], b.a[2][1]))),
                                            hn::Abs(b.a[2][2]));
                most_generator = hn::Max(most_generator, hn::IfThenElseZero(usable, generator));
                most_extent = hn::Max(most_extent, hn::IfThenElseZero(usable, hn::Max(most(b.h[0], b.h[1]), hn::Abs(b.h[2]))));
                for (int k = 0; k < 3; ++k) most_centre[k] = hn::Max(most_centre[k], hn::IfThenElseZero(usable, hn::Abs(b.c[k])));
            });
            auto top_of = [&](V x) { return hn::GetLane(hn::MaxOfLanes(d, x)); };
            // as sat::box_box_static_bounds: al = 1 (the unit generators), be, ea, eb, de
            const double al = 1.0, be = top_of(most_generator), ea = box_extent, eb = 2.0 * top_of(most_extent);
            const double de = largest(largest(box_centre[0] + 2.0 * top_of(most_centre[0]), box_centre[1] + 2.0 * top_of(most_centre[1])),
                                      box_centre[2] + 2.0 * top_of(most_centre[2]));
            double perm[5];
            if ((al <= top) & (be <= top) & (ea <= top) & (eb <= top) & (de <= top)) {
                constexpr double six = 6.0 * (1.0 + 0x1p-30);
                const double p[5] = {six * al * al * (de + al * ea + 3.0 * be * eb), six * be * be * (de + be * eb + 3.0 * al * ea),
                                     six * al * be * (de + 2.0 * al * ea + 2.0 * be * eb), six * al * al * al, six * be * be * be};
                for (int k = 0; k < 5; ++k) perm[k] = gammas[k] * p[k] + 0x1p-600;
            } else {
                for (double& x : perm) x = __builtin_huge_val(); // no bound: nothing is proven
            }
            for (int k = 0; k < 5; ++k) bound[k] = hn::Set(d, perm[k]);
            bound_det_box = perm[3];
        }
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t lane_at, std::size_t count) {
            lanes_obb b;
            const M usable = load(g, i, count, b);
            V dd[3], ext[3], AB[3][3];
            for (int k = 0; k < 3; ++k) {
                dd[k] = hn::Sub(hn::Add(b.c[k], b.c[k]), hn::Set(d, s[k]));
                ext[k] = hn::Add(b.h[k], b.h[k]);
                for (int j = 0; j < 3; ++j) AB[j][k] = hn::Abs(b.a[j][k]);
            }
            const V a_[3] = {hn::Set(d, a[0]), hn::Set(d, a[1]), hn::Set(d, a[2])};
            M separated = none, negative = usable, finite_values = usable;
            auto axis = [&](V v, int kind) {
                finite_values = hn::And(finite_values, hn::IsFinite(v));
                if (filter) {
                    separated = hn::Or(separated, hn::Gt(v, bound[kind]));
                    negative = hn::And(negative, hn::Lt(v, hn::Neg(bound[kind])));
                } else {
                    separated = hn::Or(separated, hn::Gt(v, hn::Zero(d)));
                }
            };
            auto settled = [&] { return hn::AllTrue(d, hn::Or(hn::And(separated, finite_values), hn::Not(usable))); };
            // the box's faces (the coordinate axes)
            for (int k = 0; k < 3; ++k)
                axis(hn::Sub(hn::Sub(hn::Abs(dd[k]), a_[k]),
                             hn::Add(hn::Add(hn::Mul(ext[0], AB[0][k]), hn::Mul(ext[1], AB[1][k])), hn::Mul(ext[2], AB[2][k]))),
                     0);
            M yes = none;
            if (!settled()) {
                // the oriented box's faces
                const vec<pv> B0{{b.a[0][0]}, {b.a[0][1]}, {b.a[0][2]}}, B1{{b.a[1][0]}, {b.a[1][1]}, {b.a[1][2]}},
                    B2{{b.a[2][0]}, {b.a[2][1]}, {b.a[2][2]}};
                const vec<pv> nB[3] = {cross(B1, B2), cross(B2, B0), cross(B0, B1)};
                const vec<pv> D3{{dd[0]}, {dd[1]}, {dd[2]}};
                const V det = dot(nB[0], B0).v;
                V An[3][3]; // |n_m[i]|
                for (int q = 0; q < 3; ++q) An[q][0] = hn::Abs(nB[q].x.v), An[q][1] = hn::Abs(nB[q].y.v), An[q][2] = hn::Abs(nB[q].z.v);
                for (int q = 0; q < 3; ++q)
                    axis(hn::Sub(hn::Sub(hn::Abs(dot(nB[q], D3).v), hn::Mul(ext[q], hn::Abs(det))),
                                 hn::Add(hn::Add(hn::Mul(a_[0], An[q][0]), hn::Mul(a_[1], An[q][1])), hn::Mul(a_[2], An[q][2]))),
                         1);
                if (!settled()) {
                    // the nine edge axes
                    const vec<pv> E[3] = {cross(B0, D3), cross(B1, D3), cross(B2, D3)};
                    for (int q = 0; q < 3; ++q) { // B_q
                        const V e[3] = {E[q].x.v, E[q].y.v, E[q].z.v};
                        for (int k = 0; k < 3; ++k) { // e_k
                            const int k1 = (k + 1) % 3, k2 = (k + 2) % 3, q1 = (q + 1) % 3, q2 = (q + 2) % 3;
                            axis(hn::Sub(hn::Sub(hn::Abs(e[k]), hn::Add(hn::Mul(a_[k1], AB[q][k2]), hn::Mul(a_[k2], AB[q][k1]))),
                                         hn::Add(hn::Mul(ext[q1], An[q2][k]), hn::Mul(ext[q2], An[q1][k]))),
                                 2);
                        }
                    }
                    finite_values = hn::And(finite_values, hn::IsFinite(det));
                    // yes: no axis separates, every one proven (approximate: not positive), and a
                    // solid box (its det is 1) or a solid oriented box with det proven nonzero
                    const M solid_obb =
                        hn::And(hn::And(hn::Ne(b.h[0], hn::Zero(d)), hn::Ne(b.h[1], hn::Zero(d))), hn::Ne(b.h[2], hn::Zero(d)));
                    const bool box_det = filter ? 1.0 > bound_det_box : true;
                    const M det_nonzero = filter ? hn::Or(hn::Gt(det, bound[4]), hn::Lt(det, hn::Neg(bound[4])))
                                                 : hn::Or(hn::Gt(det, hn::Zero(d)), hn::Gt(hn::Neg(det), hn::Zero(d)));
                    const M all = filter ? negative : usable;
                    yes = hn::AndNot(separated, all);
                    if (!(solid_box && box_det)) yes = hn::And(yes, hn::And(solid_obb, det_nonzero));
                }
            }
            const M decided = hn::And(finite_values, hn::Or(separated, yes));
            store_answers(d, hn::And(yes, decided), hn::Not(decided), out + start + lane_at, count);
        });
    }
}

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(box_obb);

// The entry point (declared extern "C++" in modules/batch/solids.cppm).
void box_obbs(const double* const* box, const double* const* obbs, std::size_t n, const double* gammas, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(box_obb)(box, obbs, n, gammas, out);
}
} // namespace incidence::batch::simd
#endif
