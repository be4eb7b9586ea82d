// The flat-pair oracle: points, segments, rays, lines, planes and triangles against each other
// with CGAL's own predicates (do_intersect, has_on), after turning each degenerate shape into
// the CGAL object of its point set (CGAL's constructors require non-degenerate input).
#include "cgal_oracle.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <variant>

namespace oracle {
namespace {

struct everything {};
struct nothing {};

template <class Kern>
using object = std::variant<typename Kern::Point_3, typename Kern::Segment_3, typename Kern::Ray_3, typename Kern::Line_3,
                            typename Kern::Plane_3, typename Kern::Triangle_3, everything, nothing>;

template <class Kern>
object<Kern> to_cgal(const flat& f) {
    using P = typename Kern::Point_3;
    using V = typename Kern::Vector_3;
    const double* v = f.v;
    const P a(v[0], v[1], v[2]);
    switch (f.kind) {
    case flat::point: return a;
    case flat::segment: {
        const P b(v[3], v[4], v[5]);
        if (a == b) return a;
        return typename Kern::Segment_3(a, b);
    }
    case flat::ray:
    case flat::line: {
        const V d(v[3], v[4], v[5]);
        if (d == CGAL::NULL_VECTOR) return a;
        if (f.kind == flat::ray) return typename Kern::Ray_3(a, d);
        return typename Kern::Line_3(a, d);
    }
    case flat::plane: {
        const V n(v[0], v[1], v[2]);
        const typename Kern::FT offset(v[3]);
        if (n == CGAL::NULL_VECTOR) {
            if (offset == 0) return everything{};
            return nothing{};
        }
        return typename Kern::Plane_3(n.x(), n.y(), n.z(), -offset);
    }
    case flat::triangle: {
        const P b(v[3], v[4], v[5]), c(v[6], v[7], v[8]);
        if (!CGAL::collinear(a, b, c)) return typename Kern::Triangle_3(a, b, c);
        // Collinear: the segment between the two farthest vertices (every vertex lies on it).
        const auto ab = CGAL::squared_distance(a, b), bc = CGAL::squared_distance(b, c), ca = CGAL::squared_distance(c, a);
        P p = a, q = b;
        if (bc > ab && bc >= ca) p = b, q = c;
        else if (ca > ab && ca > bc) p = c, q = a;
        if (p == q) return p;
        return typename Kern::Segment_3(p, q);
    }
    }
    return nothing{};
}

// CGAL 5.5's do_intersect(Line_3, Ray_3) and do_intersect(Ray_3, Ray_3) are wrong for some
// inputs with every kernel: after the supporting lines are found coplanar they compare two
// coplanar orientations that do not decide the question (the line's own point or the other ray's
// origin stands in for the crossing). Two rays from (1,0,0) along +x and from (0,1,0) along +y,
// whose lines cross behind both origins, "intersect"; a line through (10,0,0) along +x "misses"
// the ray from (5,1,0) along -y (tests/query/ray_ray.cpp and line_ray.cpp keep both). For these
// two pairs the oracle asks CGAL::intersection, which constructs the crossing point exactly.
template <class Kern, class A, class B>
constexpr bool ray_with_line_or_ray =
    (std::is_same_v<A, typename Kern::Ray_3> && (std::is_same_v<B, typename Kern::Ray_3> || std::is_same_v<B, typename Kern::Line_3>)) ||
    (std::is_same_v<B, typename Kern::Ray_3> && std::is_same_v<A, typename Kern::Line_3>);

// meets<Kern, true>: the oracle (CGAL::intersection for the two pairs above); meets<Kern, false>:
// do_intersect everywhere, as a user of CGAL would call it.
template <class Kern, bool Oracle>
bool meets(const object<Kern>& x, const object<Kern>& y) {
    using P = typename Kern::Point_3;
    return std::visit(
        [](const auto& a, const auto& b) -> bool {
            using A = std::decay_t<decltype(a)>;
            using B = std::decay_t<decltype(b)>;
            if constexpr (std::is_same_v<A, nothing> || std::is_same_v<B, nothing>) return false;
            else if constexpr (std::is_same_v<A, everything> || std::is_same_v<B, everything>) return true;
            else if constexpr (std::is_same_v<A, P> && std::is_same_v<B, P>) return a == b;
            else if constexpr (std::is_same_v<A, P>) return b.has_on(a);
            else if constexpr (std::is_same_v<B, P>) return a.has_on(b);
            else if constexpr (Oracle && ray_with_line_or_ray<Kern, A, B>) return bool(CGAL::intersection(a, b));
            else return CGAL::do_intersect(a, b);
        },
        x, y);
}

} // namespace

bool flat_intersect(const flat& a, const flat& b) {
    using K = CGAL::Exact_predicates_exact_constructions_kernel;
    return meets<K, true>(to_cgal<K>(a), to_cgal<K>(b));
}
bool flat_do_intersect_cgal(const flat& a, const flat& b) {
    using K = CGAL::Exact_predicates_exact_constructions_kernel;
    return meets<K, false>(to_cgal<K>(a), to_cgal<K>(b));
}
bool flat_intersect_epick(const flat& a, const flat& b) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    return meets<K, false>(to_cgal<K>(a), to_cgal<K>(b));
}

} // namespace oracle
