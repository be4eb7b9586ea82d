// Why a checked constructor refused its input, and the result type that carries it.
module;
#include <boost/outcome/result.hpp>
#include <cstdio>
#include <string>
export module incidence.core:error;

export namespace incidence {

enum class errc : unsigned char {
    not_finite,                // a coordinate or scalar is NaN or infinite
    zero_direction,            // a ray or line direction is the zero vector
    zero_normal,               // a plane normal is the zero vector
    negative_radius,           // a sphere radius is negative
    inverted_box,              // an AABB has min > max on some axis
    degenerate_triangle,       // the three vertices are collinear (exactly)
    degenerate_segment,        // both end points coincide
    empty_input,               // a construction was given no points
    out_of_range,              // a derived value (a sum, a radius) overflows binary64
    not_orthonormal,           // OBB axes far from unit length or from perpendicular
    too_large,                 // the input exceeds a construction's stated size limit
    degenerate_tetrahedron,    // the four vertices are coplanar (exactly)
    index_out_of_range,        // an index names nothing: a mesh triangle's vertex, a polygon's ring end
    open_mesh,                 // a mesh edge belongs to an odd number of triangles (the surface has a boundary)
    degenerate_polygon,        // a polygon ring has fewer than three vertices
    self_intersecting_polygon, // two polygon edges meet other than consecutive edges at their shared vertex
    non_planar_polygon,        // a 3D polygon's vertices are not exactly coplanar (`measured`: the largest distance off the plane)
    invalid_field_of_view,     // a camera's vertical field of view is not in (0, pi), or its aspect ratio is not positive
    invalid_clip_range,        // a camera's near distance is not positive, or its far distance not beyond it
    up_parallel_to_forward,    // a camera's up vector is zero or parallel to its viewing direction
    size_mismatch,             // a batch's output span, or one of its coordinate arrays, has another length than its input
};

struct error {
    errc code;
    double measured = 0.0; // the measured quantity behind the refusal, where one applies (non_planar_polygon)
    [[nodiscard]] constexpr const char* message() const {
        switch (code) {
        case errc::not_finite: return "a coordinate or scalar is NaN or infinite";
        case errc::zero_direction: return "the direction vector is zero";
        case errc::zero_normal: return "the plane normal is zero";
        case errc::negative_radius: return "the radius is negative";
        case errc::inverted_box: return "the box has min > max on some axis";
        case errc::degenerate_triangle: return "the triangle's vertices are collinear (zero area)";
        case errc::degenerate_segment: return "the segment's end points coincide";
        case errc::empty_input: return "no input points";
        case errc::out_of_range: return "a derived value (a coordinate sum or a radius) overflows binary64";
        case errc::not_orthonormal: return "the box axes are far from orthonormal (unit length and perpendicular within 1e-6)";
        case errc::too_large: return "the input exceeds the construction's size limit (see its documentation)";
        case errc::degenerate_tetrahedron: return "the tetrahedron's vertices are coplanar (zero volume)";
        case errc::index_out_of_range:
            return "an index is out of range (a triangle's vertex index not below the number of vertices, or polygon ring ends not "
                   "increasing up to the number of vertices)";
        case errc::open_mesh: return "the mesh is not closed: an edge belongs to an odd number of triangles";
        case errc::degenerate_polygon: return "a polygon ring has fewer than three vertices";
        case errc::invalid_field_of_view:
            return "the camera's vertical field of view is not in (0, pi) radians, or its aspect ratio (width / height) is not positive";
        case errc::invalid_clip_range:
            return "the camera's near distance is not positive, or its far distance is not greater than the near one";
        case errc::up_parallel_to_forward: return "the camera's up vector is zero or parallel to its viewing direction";
        case errc::non_planar_polygon: return "the polygon's vertices are not exactly coplanar";
        case errc::size_mismatch: return "the batch's output span, or one of its coordinate arrays, differs in length from its input";
        case errc::self_intersecting_polygon:
            return "the polygon's boundary meets itself: two edges share a point other than consecutive edges' common vertex (a crossing, "
                   "a touch, a repeated vertex or a fold back)";
        }
        return "unknown error";
    }
    // message() with the measured quantity, where one applies.
    [[nodiscard]] std::string what() const {
        std::string s = message();
        if (code == errc::non_planar_polygon) {
            char buf[96];
            std::snprintf(buf, sizeof buf, ": a vertex lies %.3g off the plane of three of them", measured);
            s += buf;
        }
        return s;
    }
    friend constexpr bool operator==(const error&, const error&) = default;
};

// Fallible construction returns either the shape or the reason it was refused.
// `.value()` on an error terminates; check `has_value()` or `operator bool` first.
template <class T>
using result = boost::outcome_v2::basic_result<T, error, boost::outcome_v2::policy::terminate>;

} // namespace incidence
