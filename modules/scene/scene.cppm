// incidence.scene: acceleration structures over many shapes, so that a query against all of them
// visits only the few it can meet. scene3 holds a set of triangles in a bounding volume hierarchy;
// intersects and intersection ask a line, a ray or a segment against it, in the four tiers, with
// the answer of the scalar query looped over every triangle (the brute force), lane by lane.
export module incidence.scene;
export import :scene3;
export import :linear_scene;
