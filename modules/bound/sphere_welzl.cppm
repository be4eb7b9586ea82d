// sphere_welzl: the exact minimum enclosing ball of a point set, by Welzl's move-to-front
// algorithm (expected linear time after a random shuffle). Every "is the point outside the
// current ball" decision is exact: the ball of a support set (1 to 4 affinely independent
// points on its boundary, centre in their affine hull) is computed in exact rationals, and a
// rigorous double filter (rounded centre, a proven bound on its distance to the exact centre,
// proven bounds on the radius) settles all but the nearly cospherical points. Exact values are
// integers: all coordinates are scaled by one power of two, so a centre is N / D and a squared
// radius R / D^2 with integer N, D, R, and no rational normalisation (gcd) is ever needed. The returned
// centre is the exact centre rounded to nearest; the radius is then rounded outward against
// exact tests, so every input point is provably inside. `squared_radius` is the exact minimum
// squared radius, correctly rounded.
// Source: Welzl, "Smallest enclosing disks (balls and ellipsoids)", LNCS 555 (1991); move-to-
// front and the support-set ball as in Gaertner, "Fast and robust smallest enclosing balls",
// ESA 1999, sections 2-3. Exact integers: Boost.Multiprecision cpp_int (heap-allocating: a
// construction, not a scalar query).
// The interface: the result type and the two entry points; the exact arithmetic (Boost's cpp_int)
// lives in the implementation unit sphere_welzl.cpp, so an importer's module build does not parse it.
module;
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>
export module incidence.bound:sphere_welzl;
import incidence.core;
import incidence.shapes;

export namespace incidence::bound {

struct min_sphere {
    sphere3 sphere;                     // contains every input point (outward rounded)
    double squared_radius;              // exact minimum squared radius, correctly rounded (inf beyond binary64)
    std::vector<std::uint32_t> support; // indices of the points on the exact minimum sphere's boundary (1..4)
};

namespace welzl_detail {
// The most support points the pivoting loop keeps before it falls back to move-to-front.
inline constexpr std::size_t pivot_cap = 8;
// The minimum ball of `points` with `seed` for the shuffle and at most `cap` (<= pivot_cap)
// support points in the pivoting loop (the tests use a small one to run the fallback); see
// sphere_welzl.cpp.
[[nodiscard]] result<min_sphere> solve(std::span<const point3> points, std::uint64_t seed, std::size_t cap);
} // namespace welzl_detail

[[nodiscard]] inline result<min_sphere> sphere_welzl(std::span<const point3> points, std::uint64_t seed = 1) {
    return welzl_detail::solve(points, seed, welzl_detail::pivot_cap);
}

} // namespace incidence::bound
