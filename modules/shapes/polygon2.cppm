// polygon2{vertices, ring_ends}: a polygon in the plane with holes, viewed (the caller owns both
// arrays): one or more closed rings of vertices, ring i being vertices [ring_ends[i-1],
// ring_ends[i]) (ring 0 starts at 0; no ring_ends: one ring of every vertex). Its point set is
// its edges together with the points from which a ray crosses the rings an odd number of times
// (the even-odd rule: a ring inside the outer ring is a hole, a ring inside a hole an island).
// Simple or not, convex or not; either orientation for every ring.
// Aggregate construction accepts anything and queries never read out of range (bad ring ends
// make the polygon no set: every query says no); make() refuses no vertices, non-finite ones,
// ring ends that are not increasing up to the vertex count, a ring of fewer than three vertices,
// and a boundary that meets itself (decided exactly, by orientation signs), so that what it
// accepts is a set of disjoint simple rings.
module;
#include <cstddef>
#include <cstdint>
#include <span>
export module incidence.shapes:polygon2;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct polygon2 {
    std::span<const point2> vertices;
    std::span<const std::uint32_t> ring_ends;

    [[nodiscard]] constexpr std::size_t rings() const { return ring_ends.empty() ? 1 : ring_ends.size(); }
    [[nodiscard]] constexpr std::size_t ring_begin(std::size_t i) const { return i == 0 ? 0 : ring_ends[i - 1]; }
    [[nodiscard]] constexpr std::size_t ring_end(std::size_t i) const { return ring_ends.empty() ? vertices.size() : ring_ends[i]; }
    // Ring ends increase strictly up to the number of vertices, and there is a vertex.
    [[nodiscard]] constexpr bool indices_valid() const {
        if (vertices.empty()) return false;
        std::size_t previous = 0;
        for (std::size_t i = 0; i < ring_ends.size(); ++i) {
            if (ring_ends[i] <= previous || ring_ends[i] > vertices.size()) return false;
            previous = ring_ends[i];
        }
        return ring_ends.empty() || previous == vertices.size();
    }
    // The vertex after vertex j on its ring [b, e) (indices_valid() first).
    [[nodiscard]] static constexpr std::size_t next(std::size_t j, std::size_t b, std::size_t e) { return j + 1 == e ? b : j + 1; }

    [[nodiscard]] static constexpr result<polygon2> make(std::span<const point2> vertices, std::span<const std::uint32_t> ring_ends = {}) {
        const polygon2 g{vertices, ring_ends};
        if (vertices.empty()) return error{errc::empty_input};
        for (const point2& p : vertices)
            if (!is_finite(p)) return error{errc::not_finite};
        if (!g.indices_valid()) return error{errc::index_out_of_range};
        for (std::size_t i = 0; i < g.rings(); ++i)
            if (g.ring_end(i) - g.ring_begin(i) < 3) return error{errc::degenerate_polygon};
        if (!g.boundary_simple()) return error{errc::self_intersecting_polygon};
        return g;
    }

    // Every two edges are disjoint, except consecutive edges of a ring, which share only their
    // common vertex. O(n^2) exact segment tests (O'Rourke, Computational Geometry in C, 2nd ed.,
    // section 1.5: intersection from orientation signs).
    [[nodiscard]] constexpr bool boundary_simple() const {
        for (std::size_t ri = 0; ri < rings(); ++ri)
            for (std::size_t i = ring_begin(ri); i < ring_end(ri); ++i) {
                const std::size_t i2 = next(i, ring_begin(ri), ring_end(ri));
                const point2 a = vertices[i], b = vertices[i2];
                if (a == b) return false; // a repeated vertex: a zero-length edge
                for (std::size_t rj = ri; rj < rings(); ++rj)
                    for (std::size_t j = rj == ri ? i + 1 : ring_begin(rj); j < ring_end(rj); ++j) {
                        const std::size_t j2 = next(j, ring_begin(rj), ring_end(rj));
                        const point2 c = vertices[j], d = vertices[j2];
                        if (j == i2 || j2 == i) {         // consecutive: they share one vertex
                            const bool forward = j == i2; // a -> b == c -> d
                            const point2 p = forward ? a : c, q = forward ? b : a, r = forward ? d : b;
                            // p -> q -> r: only q shared, unless r folds back onto p -> q
                            if (j == i2 && j2 == i) return false; // a two-vertex ring (make refuses it earlier)
                            if (orientation(p, q, r) == sign::zero && dot_sign(p, q, r) == sign::positive) return false;
                            continue;
                        }
                        if (segments_meet(a, b, c, d)) return false;
                    }
            }
        return true;
    }

private:
    [[nodiscard]] static constexpr sign orientation(point2 a, point2 b, point2 c) {
        arith::exact_kernel k;
        return k.sgn([=](auto L) { return (L(b.x) - L(a.x)) * (L(c.y) - L(a.y)) - (L(b.y) - L(a.y)) * (L(c.x) - L(a.x)); });
    }
    // sign of (p - q) . (r - q): positive when r lies on p's side of q along a line through them.
    [[nodiscard]] static constexpr sign dot_sign(point2 p, point2 q, point2 r) {
        arith::exact_kernel k;
        return k.sgn([=](auto L) { return (L(p.x) - L(q.x)) * (L(r.x) - L(q.x)) + (L(p.y) - L(q.y)) * (L(r.y) - L(q.y)); });
    }
    [[nodiscard]] static constexpr bool between(point2 a, point2 b, point2 p) { // p on line ab: within the segment?
        const bool by_x = a.x != b.x;
        const double lo = by_x ? (a.x < b.x ? a.x : b.x) : (a.y < b.y ? a.y : b.y);
        const double hi = by_x ? (a.x < b.x ? b.x : a.x) : (a.y < b.y ? b.y : a.y);
        const double v = by_x ? p.x : p.y;
        return lo <= v && v <= hi;
    }
    [[nodiscard]] static constexpr bool segments_meet(point2 a, point2 b, point2 c, point2 d) {
        const sign o1 = orientation(a, b, c), o2 = orientation(a, b, d), o3 = orientation(c, d, a), o4 = orientation(c, d, b);
        if (o1 == sign::zero && between(a, b, c)) return true;
        if (o2 == sign::zero && between(a, b, d)) return true;
        if (o3 == sign::zero && between(c, d, a)) return true;
        if (o4 == sign::zero && between(c, d, b)) return true;
        return o1 != sign::zero && o2 != sign::zero && o3 != sign::zero && o4 != sign::zero && o1 != o2 && o3 != o4;
    }
};

} // namespace incidence
