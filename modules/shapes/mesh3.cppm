// mesh3{vertices, triangles}: a closed triangle mesh, viewed (the caller owns both arrays), and
// the solid it bounds: the points of its triangles together with the points from which a ray
// crosses the surface an odd number of times (the even-odd rule; for an embedded closed surface,
// its interior; nested shells make cavities). It may be non-convex.
// Aggregate construction accepts anything and queries then never read out of range (a triangle
// naming a missing vertex makes the mesh no set: every query says no); make() refuses empty
// meshes, non-finite vertices, out-of-range indices, and open meshes (an edge used by an odd
// number of triangles, so the surface has a boundary and the inside is undefined).
module;
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>
export module incidence.shapes:mesh3;
import incidence.core;
import :triangle3;

export namespace incidence {

struct mesh3 {
    std::span<const point3> vertices;
    std::span<const std::array<std::uint32_t, 3>> triangles;

    // Every index names a vertex and there is a triangle.
    [[nodiscard]] constexpr bool indices_valid() const {
        if (triangles.empty()) return false;
        for (const auto& t : triangles)
            if (t[0] >= vertices.size() || t[1] >= vertices.size() || t[2] >= vertices.size()) return false;
        return true;
    }
    // Triangle i (indices_valid() first).
    [[nodiscard]] constexpr triangle3 triangle(std::size_t i) const {
        const auto& t = triangles[i];
        return {vertices[t[0]], vertices[t[1]], vertices[t[2]]};
    }
    // Refuses an empty mesh, non-finite vertices, out-of-range indices and an open surface.
    [[nodiscard]] static constexpr result<mesh3> make(std::span<const point3> vertices,
                                                      std::span<const std::array<std::uint32_t, 3>> triangles) {
        const mesh3 m{vertices, triangles};
        if (vertices.empty() || triangles.empty()) return error{errc::empty_input};
        for (const point3& p : vertices)
            if (!is_finite(p)) return error{errc::not_finite};
        if (!m.indices_valid()) return error{errc::index_out_of_range};
        // Closed: every undirected edge is used an even number of times.
        std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
        edges.reserve(triangles.size() * 3);
        for (const auto& t : triangles)
            for (int i = 0; i < 3; ++i) {
                const std::uint32_t a = t[static_cast<unsigned>(i)], b = t[static_cast<unsigned>((i + 1) % 3)];
                edges.emplace_back(a < b ? a : b, a < b ? b : a);
            }
        std::sort(edges.begin(), edges.end());
        for (std::size_t i = 0; i < edges.size();) {
            std::size_t j = i;
            while (j < edges.size() && edges[j] == edges[i]) ++j;
            if ((j - i) % 2 != 0) return error{errc::open_mesh};
            i = j;
        }
        return m;
    }
};

} // namespace incidence
