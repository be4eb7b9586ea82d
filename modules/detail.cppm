// incidence.detail: the library's internals (docs/DESIGN.md, "Layout"): the shared engines
// (modules/engines/) and the kernel-generic body of every pair (modules/query/<kind>/), all in
// namespace incidence::detail. Not part of the API: `import incidence;` does not bring it, and its
// names may change at any time. Tests, fuzzers, benchmarks and tools import it to reach the bodies.
export module incidence.detail;
import incidence.arith;
export import :exactly;
export import :engines.ball_flat;
export import :engines.ball_halfspaces;
export import :engines.ball_obb;
export import :engines.capsule_obb;
export import :engines.certificate;
export import :engines.box;
export import :engines.capsule;
export import :engines.capsule_rows;
export import :engines.box_triangle;
export import :engines.clip;
export import :engines.contact;
export import :engines.frustum;
export import :engines.halfspace_lp;
export import :engines.halfspace_meets;
export import :engines.halfspace_slabs;
export import :engines.kdop;
export import :engines.linear;
export import :engines.mesh;
export import :engines.nearest_feature;
export import :engines.plane;
export import :engines.polygon2;
export import :engines.polygon3;
export import :engines.scene_scale;
export import :engines.segment_pieces;
export import :engines.separating_axes;
export import :engines.sphere;
export import :engines.tetrahedron;
export import :engines.triangle;
export import :intersects.box_pairs;
export import :intersects.halfspace_pairs;
export import :intersects.kdop_pairs;
export import :intersects.linear_pairs;
export import :intersects.mesh_pairs;
export import :intersects.obb_pairs;
export import :intersects.plane_pairs;
export import :intersects.polygon2_pairs;
export import :intersects.polygon_pairs;
export import :intersects.sphere_pairs;
export import :intersects.capsule_pairs;
export import :contains.capsule_pairs;
export import :intersects.circle2_pairs;
export import :contains.circle2_pairs;
export import :intersects.tetrahedron_pairs;
export import :intersects.triangle_pairs;
export import :contains.box_pairs;
export import :contains.halfspace_pairs;
export import :contains.kdop_pairs;
export import :contains.mesh_pairs;
export import :contains.obb_pairs;
export import :contains.polygon2_pairs;
export import :contains.polygon_pairs;
export import :contains.sphere_pairs;
export import :contains.tetrahedron_pairs;
export import :intersection.linear_pairs;
export import :distance.ball_point;
export import :distance.box_point;
export import :distance.linear_pairs;
export import :distance.triangle_pairs;
export import :distance.halfspace_point;
export import :distance.triangles_point;

export namespace incidence::detail {

struct intersects_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr bool operator()(K& k, const A& a, const B& b) const {
        return detail::intersects(k, a, b);
    }
};
struct contains_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr bool operator()(K& k, const A& a, const B& b) const {
        return detail::contains(k, a, b);
    }
};
struct intersection_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr auto operator()(K& k, const A& a, const B& b) const {
        return detail::intersection(k, a, b);
    }
};
struct nearest_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr auto operator()(K& k, const A& a, const B& b) const {
        return detail::squared_distance(k, a, b);
    }
};
struct farthest_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr auto operator()(K& k, const A& a, const B& b) const {
        return detail::max_squared_distance(k, a, b);
    }
};
struct euclidean_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr auto operator()(K& k, const A& a, const B& b) const {
        return detail::distance(k, a, b);
    }
};
struct signed_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr auto operator()(K& k, const A& a, const B& b) const {
        return detail::signed_distance(k, a, b);
    }
};

// Declared in query/exactly.cppm, where the pair tables name their instances.
template <class Body, class R, class A, class B>
constexpr R exactly(const A& a, const B& b) {
    arith::exact_kernel e;
    const R r = Body{}(e, a, b);
    if (!e.valid) return R{};
    return r;
}

} // namespace incidence::detail
