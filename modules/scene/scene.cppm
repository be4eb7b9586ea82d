// incidence.scene: acceleration structures over many shapes, so that a query against all of them
// visits only the few it can meet. scene3 holds a set of triangles in a bounding volume hierarchy;
// intersects and intersection ask a line, a ray or a segment against it (linear_scene.cppm),
// intersects a box, an oriented box, a triangle, a tetrahedron or a frustum (solid_scene.cppm), and
// intersecting lists every triangle a shape meets; a scene against a scene: every pair of triangles
// that meet (scene_scene.cppm); in the four tiers, each answer built from the
// scalar query of the triangles the hierarchy cannot rule out (traversal.cpp).
export module incidence.scene;
export import :scene3;
export import :linear_scene;
export import :solid_scene;
export import :scene_scene;
