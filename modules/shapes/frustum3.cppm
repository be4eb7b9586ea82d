// frustum3{planes}: a view volume, the closed set of six half-spaces
// { p : dot(planes[i].normal, p) <= planes[i].offset for i < 6 } in the order near, far, left,
// right, bottom, top, outward normals, read exactly (the same meaning as convex_polyhedron3).
// from_camera() computes the six planes of a perspective camera in double, rounded: the frustum
// is then exactly the set those six planes bound (within a few ulps of the camera's ideal one).
// Camera planes, for the unit viewing direction f, right r = f x up / |f x up|, true up u = r x f,
// a = fov_y / 2, b = atan(aspect tan a) and eye e: near -f . p <= -(f . e + near), far
// f . p <= f . e + far, and the side planes through e with normals -r - f tan b, r - f tan b,
// -u - f tan a, u - f tan a (Gribb and Hartmann, "Fast extraction of viewing frustum planes from
// the world-view-projection matrix", 2001, give the same planes from the projection matrix).
module;
#include <array>
#include <cmath>
export module incidence.shapes:frustum3;
import incidence.core;
import :plane3;

export namespace incidence {

struct frustum3 {
    std::array<plane3, 6> planes;

    // Refuses non-finite values and zero normals.
    [[nodiscard]] static constexpr result<frustum3> make(const std::array<plane3, 6>& planes) {
        frustum3 f{};
        for (unsigned i = 0; i < 6; ++i) {
            const auto p = plane3::make(planes[i].normal, planes[i].offset);
            if (!p.has_value()) return p.error();
            f.planes[i] = p.value();
        }
        return f;
    }

    // A perspective camera at `eye` looking along `forward` (any length) with `up` (any length,
    // not parallel to forward), vertical field of view fov_y in radians (0 < fov_y < pi),
    // aspect = width / height > 0, and clip distances 0 < near < far along the viewing direction.
    // Refuses non-finite values, a zero forward vector (zero_direction), up within 1e-6 radians of
    // the viewing direction, and out-of-range angles and distances.
    [[nodiscard]] static result<frustum3> from_camera(point3 eye, vec3 forward, vec3 up, double fov_y, double aspect, double near,
                                                      double far) {
        if (!is_finite(eye) || !is_finite(forward) || !is_finite(up) || !is_finite(fov_y) || !is_finite(aspect) || !is_finite(near) ||
            !is_finite(far))
            return error{errc::not_finite};
        // unit vectors, scaled by the largest component first (no overflow or underflow)
        auto unit = [](vec3 v) {
            const double m = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
            if (!(m > 0.0)) return vec3{0, 0, 0};
            const vec3 w{v.x / m, v.y / m, v.z / m};
            return w * (1.0 / std::sqrt(dot(w, w)));
        };
        const vec3 f = unit(forward), u0 = unit(up);
        if (f.x == 0.0 && f.y == 0.0 && f.z == 0.0) return error{errc::zero_direction};
        if (u0.x == 0.0 && u0.y == 0.0 && u0.z == 0.0) return error{errc::up_parallel_to_forward};
        if (!(fov_y > 0.0 && fov_y < 3.141592653589793) || !(aspect > 0.0)) return error{errc::invalid_field_of_view};
        if (!(near > 0.0) || !(far > near)) return error{errc::invalid_clip_range};
        const vec3 side = cross(f, u0);
        const double ls = std::sqrt(dot(side, side));
        if (!(ls > 1e-6)) return error{errc::up_parallel_to_forward};
        const vec3 r = side * (1.0 / ls);
        const vec3 u = cross(r, f);
        const double ta = std::tan(fov_y / 2), tb = aspect * ta;
        if (!is_finite(ta) || !is_finite(tb)) return error{errc::invalid_field_of_view};
        const vec3 e = eye - point3{0, 0, 0};
        const double fe = dot(f, e);
        auto through_eye = [&](vec3 n) { return plane3{n, dot(n, e)}; };
        frustum3 fr{{plane3{-f, -(fe + near)}, plane3{f, fe + far}, through_eye(-r - f * tb), through_eye(r - f * tb),
                     through_eye(-u - f * ta), through_eye(u - f * ta)}};
        for (const auto& p : fr.planes)
            if (!is_finite(p.offset) || !is_finite(p.normal)) return error{errc::out_of_range};
        return fr;
    }
};

} // namespace incidence
