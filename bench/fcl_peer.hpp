// FCL's OBB-OBB, sphere-box, capsule and triangle-triangle tests (plain double), a peer in the benchmarks only. Its own
// translation unit: FCL's and Eigen's headers never meet `import incidence;`.
#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace fcl_peer {
// Box: centre c, axes a[0..2] (a[3 * i + k]: component k of axis i), half extents h.
bool obb_obb(const double ca[3], const double aa[9], const double ha[3], const double cb[3], const double ab[9], const double hb[3]);
// A ball (centre c, radius r) against that box: fcl::detail::sphereBoxIntersect without contacts.
bool sphere_obb(const double c[3], double r, const double cb[3], const double ab[9], const double hb[3]);
// A capsule (segment a b, radius r) against a ball (fcl::detail::sphereCapsuleIntersect), a capsule
// (fcl::detail::capsuleCapsuleDistance: touching when the signed distance is <= 0) and a box (as
// above; fcl::detail::GJKSolver_libccd::shapeIntersect, FCL's default narrow phase for the pair).
// Each capsule is an fcl::Capsule along z posed at the segment's midpoint by the rotation taking z
// to b - a (rounded, as FCL's users pose one).
bool capsule_sphere(const double a[3], const double b[3], double r, const double c[3], double rs);
bool capsule_capsule(const double a1[3], const double b1[3], double r1, const double a2[3], const double b2[3], double r2);
bool capsule_obb(const double a[3], const double b[3], double r, const double cb[3], const double ab[9], const double hb[3]);
// Is point p apart from a box (as above) or a capsule, as FCL's distance API answers it:
// fcl::detail::sphereBoxDistance and sphereCapsuleDistance with a ball of radius 0 at p, true when
// they report a distance (> 0). FCL gives no distance for a point on or in the solid, so a point on
// the boundary is not apart here, where the signed distance is 0.
bool point_apart_obb(const double p[3], const double cb[3], const double ab[9], const double hb[3]);
bool point_apart_capsule(const double p[3], const double a[3], const double b[3], double r);
bool triangle_triangle(const double p1[3], const double p2[3], const double p3[3], const double q1[3], const double q2[3],
                       const double q3[3]);

// Two triangle meshes (vertices as x, y, z triples, triangles as three indices), each an FCL
// BVHModel<OBBRSS> built once: fcl::collide with every contact asked for (enable_contact off), as a
// user lists the touching triangle pairs of two meshes.
class mesh_pair {
public:
    mesh_pair(const double* va, std::size_t nva, const std::uint32_t* ta, std::size_t nta, const double* vb, std::size_t nvb,
              const std::uint32_t* tb, std::size_t ntb);
    ~mesh_pair();
    mesh_pair(const mesh_pair&) = delete;
    mesh_pair& operator=(const mesh_pair&) = delete;
    // The pairs (triangle of a, triangle of b) FCL reports in contact.
    [[nodiscard]] std::vector<std::pair<std::size_t, std::size_t>> contacts() const;

private:
    struct impl;
    impl* p_;
};
} // namespace fcl_peer
