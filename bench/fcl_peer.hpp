// FCL's OBB-OBB and triangle-triangle tests (plain double), a peer in the benchmarks only. Its own
// translation unit: FCL's and Eigen's headers never meet `import incidence;`.
#pragma once

namespace fcl_peer {
// Box: centre c, axes a[0..2] (a[3 * i + k]: component k of axis i), half extents h.
bool obb_obb(const double ca[3], const double aa[9], const double ha[3], const double cb[3], const double ab[9], const double hb[3]);
bool triangle_triangle(const double p1[3], const double p2[3], const double p3[3], const double q1[3], const double q2[3],
                       const double q3[3]);
} // namespace fcl_peer
