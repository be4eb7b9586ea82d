// incidence.shapes: the primitives, one per file, each an aggregate with a checked make().
export module incidence.shapes;
export import :ray3;
export import :line3;
export import :segment3;
export import :plane3;
export import :sphere3;
export import :aabb3;
export import :triangle3;
export import :kdop;
export import :obb3;
export import :ray2;
export import :line2;
export import :segment2;
export import :tetrahedron3;
export import :mesh3;
export import :polygon2;
