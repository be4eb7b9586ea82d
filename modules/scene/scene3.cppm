// scene3: a set of triangles (their closed surfaces, no inside: a renderer's scene) held in a
// bounding volume hierarchy. Built once (make), then read by every query without allocation.
// Method: binned surface-area heuristic (Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", IEEE Symposium on Interactive Ray Tracing 2007): 16 bins along each axis of the
// node's centroid bounds, traversal cost 1 against one triangle test per triangle; a node becomes
// a leaf at 2 triangles or fewer, where no split is cheaper (up to 8 triangles), and at depth 60.
// Node volume: the axis-aligned box, exact (the least and greatest coordinates of the node's
// vertices, no rounding), so a box test that never misses a box the object meets (the queries'
// widened slabs, linear_scene.cppm) never misses a triangle either.
// make() refuses NaN or infinite coordinates and more than 2^32 - 1 triangles; an empty set is a
// scene that nothing meets. Degenerate triangles are kept (as the segment or point they are).
module;
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>
export module incidence.scene:scene3;
import incidence.core;
import incidence.shapes;

export namespace incidence {

class scene3 {
public:
    // A node of the hierarchy; the root is nodes()[0] (absent in an empty scene).
    struct node {
        aabb3 box;           // the exact bounds of the vertices of the triangles below it
        std::uint32_t first; // a leaf: its first triangle (an index into triangles()); inner: its first child (the second follows)
        std::uint32_t count; // a leaf: its number of triangles (at least 1); inner: 0
        std::uint32_t axis;  // inner: the split axis (0, 1, 2); the first child holds the lesser centroids
        [[nodiscard]] constexpr bool leaf() const { return count != 0; }
    };
    static constexpr int max_depth = 60;

    [[nodiscard]] static result<scene3> make(std::span<const triangle3> triangles);
    // The triangles of a mesh (an open one too: the scene is their surfaces).
    [[nodiscard]] static result<scene3> make(std::span<const point3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles);

    [[nodiscard]] std::span<const node> nodes() const { return nodes_; }
    // The triangles in the hierarchy's order; source(i) is the index the caller gave triangles()[i].
    [[nodiscard]] std::span<const triangle3> triangles() const { return triangles_; }
    [[nodiscard]] std::size_t source(std::size_t i) const { return source_[i]; }
    [[nodiscard]] std::size_t size() const { return triangles_.size(); }
    [[nodiscard]] bool empty() const { return triangles_.empty(); }
    // Every coordinate within 2^400 in magnitude: the widened slab test's range (linear_scene.cppm).
    [[nodiscard]] bool moderate() const { return moderate_; }

private:
    std::vector<node> nodes_;
    std::vector<triangle3> triangles_;
    std::vector<std::uint32_t> source_;
    bool moderate_ = true;
};

} // namespace incidence
