// FCL 0.7 (Debian libfcl-dev) as a benchmark peer: fcl::OBB<double>::overlap,
// fcl::detail::sphereBoxIntersect, sphereBoxDistance, sphereCapsuleIntersect, sphereCapsuleDistance, capsuleCapsuleDistance, GJKSolver_libccd and fcl::detail::Intersect<double>::intersect_Triangle, called as FCL's users call them.
#include "fcl_peer.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <memory>
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/sphere_box.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/sphere_capsule.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/capsule_capsule.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>

namespace fcl_peer {

namespace {
fcl::OBB<double> box(const double c[3], const double a[9], const double h[3]) {
    fcl::Matrix3<double> axis;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) axis(k, i) = a[3 * i + k]; // the columns are the axes
    return fcl::OBB<double>(axis, fcl::Vector3<double>(c[0], c[1], c[2]), fcl::Vector3<double>(h[0], h[1], h[2]));
}
fcl::Vector3<double> v(const double p[3]) { return {p[0], p[1], p[2]}; }
fcl::Transform3<double> box_pose(const double cb[3], const double ab[9]) {
    fcl::Transform3<double> X = fcl::Transform3<double>::Identity();
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) X.linear()(k, i) = ab[3 * i + k]; // the columns are the axes
    X.translation() = v(cb);
    return X;
}
struct posed_capsule {
    fcl::Capsule<double> shape;
    fcl::Transform3<double> pose;
};
posed_capsule capsule(const double a[3], const double b[3], double r) {
    const fcl::Vector3<double> A = v(a), B = v(b), d = B - A;
    fcl::Transform3<double> X = fcl::Transform3<double>::Identity();
    X.translation() = 0.5 * (A + B);
    const double length = d.norm();
    if (length > 0) X.linear() = Eigen::Quaterniond::FromTwoVectors(fcl::Vector3<double>::UnitZ(), d).toRotationMatrix();
    return {fcl::Capsule<double>(r, length), X};
}
} // namespace

bool obb_obb(const double ca[3], const double aa[9], const double ha[3], const double cb[3], const double ab[9], const double hb[3]) {
    return box(ca, aa, ha).overlap(box(cb, ab, hb));
}
bool sphere_obb(const double c[3], double r, const double cb[3], const double ab[9], const double hb[3]) {
    fcl::Transform3<double> ball = fcl::Transform3<double>::Identity();
    ball.translation() = v(c);
    return fcl::detail::sphereBoxIntersect<double>(fcl::Sphere<double>(r), ball, fcl::Box<double>(2 * hb[0], 2 * hb[1], 2 * hb[2]),
                                                   box_pose(cb, ab), nullptr);
}
bool capsule_sphere(const double a[3], const double b[3], double r, const double c[3], double rs) {
    const posed_capsule k = capsule(a, b, r);
    fcl::Transform3<double> ball = fcl::Transform3<double>::Identity();
    ball.translation() = v(c);
    return fcl::detail::sphereCapsuleIntersect<double>(fcl::Sphere<double>(rs), ball, k.shape, k.pose, nullptr);
}
bool capsule_capsule(const double a1[3], const double b1[3], double r1, const double a2[3], const double b2[3], double r2) {
    const posed_capsule k1 = capsule(a1, b1, r1), k2 = capsule(a2, b2, r2);
    double dist = 0;
    fcl::Vector3<double> w1, w2;
    fcl::detail::capsuleCapsuleDistance<double>(k1.shape, k1.pose, k2.shape, k2.pose, &dist, &w1, &w2);
    return dist <= 0;
}
bool capsule_obb(const double a[3], const double b[3], double r, const double cb[3], const double ab[9], const double hb[3]) {
    const posed_capsule k = capsule(a, b, r);
    const fcl::detail::GJKSolver_libccd<double> solver;
    return solver.shapeIntersect(k.shape, k.pose, fcl::Box<double>(2 * hb[0], 2 * hb[1], 2 * hb[2]), box_pose(cb, ab), nullptr);
}
bool point_apart_obb(const double p[3], const double cb[3], const double ab[9], const double hb[3]) {
    fcl::Transform3<double> at = fcl::Transform3<double>::Identity();
    at.translation() = v(p);
    double dist = 0;
    return fcl::detail::sphereBoxDistance<double>(fcl::Sphere<double>(0.0), at, fcl::Box<double>(2 * hb[0], 2 * hb[1], 2 * hb[2]),
                                                  box_pose(cb, ab), &dist, nullptr, nullptr);
}
bool point_apart_capsule(const double p[3], const double a[3], const double b[3], double r) {
    const posed_capsule k = capsule(a, b, r);
    fcl::Transform3<double> at = fcl::Transform3<double>::Identity();
    at.translation() = v(p);
    double dist = 0;
    return fcl::detail::sphereCapsuleDistance<double>(fcl::Sphere<double>(0.0), at, k.shape, k.pose, &dist, nullptr, nullptr);
}
bool triangle_triangle(const double p1[3], const double p2[3], const double p3[3], const double q1[3], const double q2[3],
                       const double q3[3]) {
    return fcl::detail::Intersect<double>::intersect_Triangle(v(p1), v(p2), v(p3), v(q1), v(q2), v(q3));
}

struct mesh_pair::impl {
    std::shared_ptr<fcl::BVHModel<fcl::OBBRSS<double>>> a, b;
};

namespace {
std::shared_ptr<fcl::BVHModel<fcl::OBBRSS<double>>> model(const double* v, std::size_t nv, const std::uint32_t* t, std::size_t nt) {
    std::vector<fcl::Vector3<double>> points;
    std::vector<fcl::Triangle> triangles;
    for (std::size_t i = 0; i < nv; ++i) points.emplace_back(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    for (std::size_t i = 0; i < nt; ++i) triangles.emplace_back(t[3 * i], t[3 * i + 1], t[3 * i + 2]);
    auto m = std::make_shared<fcl::BVHModel<fcl::OBBRSS<double>>>();
    m->beginModel();
    m->addSubModel(points, triangles);
    m->endModel();
    return m;
}
} // namespace

mesh_pair::mesh_pair(const double* va, std::size_t nva, const std::uint32_t* ta, std::size_t nta, const double* vb, std::size_t nvb,
                     const std::uint32_t* tb, std::size_t ntb)
    : p_(new impl{model(va, nva, ta, nta), model(vb, nvb, tb, ntb)}) {}
mesh_pair::~mesh_pair() { delete p_; }

std::vector<std::pair<std::size_t, std::size_t>> mesh_pair::contacts() const {
    const fcl::CollisionObject<double> a(p_->a), b(p_->b);
    const fcl::CollisionRequest<double> request(100000000, false);
    fcl::CollisionResult<double> result;
    fcl::collide(&a, &b, request, result);
    std::vector<std::pair<std::size_t, std::size_t>> out;
    for (std::size_t i = 0; i < result.numContacts(); ++i) {
        const auto& c = result.getContact(i);
        out.push_back({static_cast<std::size_t>(c.b1), static_cast<std::size_t>(c.b2)});
    }
    return out;
}

} // namespace fcl_peer
