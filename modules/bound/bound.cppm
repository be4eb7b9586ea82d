// incidence.bound: bounding volumes of point sets, one construction per file, each citing its
// source. Every returned volume provably contains every input point: bounds are rounded outward
// and checked with exact predicates. Inputs are spans of points (a mesh is its vertices);
// an empty span or a NaN/infinite coordinate is an error, never a NaN volume.
export module incidence.bound;
export import :outward;
export import :aabb_of;
export import :kdop_of;
export import :sphere_from_aabb;
export import :sphere_ritter;
export import :sphere_welzl;
export import :convex_hull;
export import :obb_fit;
export import :obb_covariance;
export import :obb_min_volume;
export import :obb_edge_flush;
