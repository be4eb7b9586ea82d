// incidence.detail: the library's internals (docs/DESIGN.md, "Layout"): the shared engines
// (modules/engines/) and the kernel-generic body of every pair (modules/query/<kind>/), all in
// namespace incidence::detail. Not part of the API: `import incidence;` does not bring it, and its
// names may change at any time. Tests, fuzzers, benchmarks and tools import it to reach the bodies.
export module incidence.detail;
export import :engines.box;
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
export import :distance.box_point;
