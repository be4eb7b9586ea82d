// FCL 0.7 (Debian libfcl-dev) as a benchmark peer: fcl::OBB<double>::overlap and
// fcl::detail::Intersect<double>::intersect_Triangle, called as FCL's users call them.
#include "fcl_peer.hpp"

#include <fcl/math/bv/OBB.h>
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

namespace fcl_peer {

namespace {
fcl::OBB<double> box(const double c[3], const double a[9], const double h[3]) {
    fcl::Matrix3<double> axis;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) axis(k, i) = a[3 * i + k]; // the columns are the axes
    return fcl::OBB<double>(axis, fcl::Vector3<double>(c[0], c[1], c[2]), fcl::Vector3<double>(h[0], h[1], h[2]));
}
fcl::Vector3<double> v(const double p[3]) { return {p[0], p[1], p[2]}; }
} // namespace

bool obb_obb(const double ca[3], const double aa[9], const double ha[3], const double cb[3], const double ab[9], const double hb[3]) {
    return box(ca, aa, ha).overlap(box(cb, ab, hb));
}
bool triangle_triangle(const double p1[3], const double p2[3], const double p3[3], const double q1[3], const double q2[3],
                       const double q3[3]) {
    return fcl::detail::Intersect<double>::intersect_Triangle(v(p1), v(p2), v(p3), v(q1), v(q2), v(q3));
}

} // namespace fcl_peer
