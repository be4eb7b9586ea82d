// sphere_ritter: Ritter's bounding sphere. From a point x, find the farthest point y, then the
// farthest point z from y; start with the sphere of diameter yz; then, in one pass, grow the
// sphere just enough to take in each point outside it (new radius (r + d) / 2, centre moved
// towards the point). Finally the radius is rounded outward against exact tests, so the
// rounding of the growing steps cannot leave a point outside.
// Source: Ritter, "An efficient bounding sphere", Graphics Gems (1990), pp. 301-303.
module;
#include <span>
export module incidence.bound:sphere_ritter;
import incidence.core;
import incidence.shapes;
import :outward;

export namespace incidence::bound {

[[nodiscard]] constexpr result<sphere3> sphere_ritter(std::span<const point3> points) {
    if (points.empty()) return error{errc::empty_input};
    for (const point3& p : points)
        if (!is_finite(p)) return error{errc::not_finite};
    auto farthest = [&](point3 from) {
        point3 best = from;
        double d = -1.0;
        for (const point3& p : points)
            if (const double l = length(p - from); l > d) d = l, best = p;
        return best;
    };
    const point3 y = farthest(points[0]), z = farthest(y);
    point3 c{0.5 * y.x + 0.5 * z.x, 0.5 * y.y + 0.5 * z.y, 0.5 * y.z + 0.5 * z.z};
    double r = 0.5 * length(z - y);
    for (const point3& p : points) {
        const double d = length(p - c);
        if (d <= r) continue;
        const double nr = 0.5 * (r + d);
        const double k = (nr - r) / d; // move the centre by (nr - r) towards p
        c = c + (p - c) * k;
        r = nr;
    }
    const auto er = enclosing_radius(c, points, r);
    if (!er) return er.error();
    return sphere3{c, er.value()};
}

} // namespace incidence::bound
