// A consumer of the installed library: import incidence; and ask a few questions.
#include <cstdio>
import incidence;

using namespace incidence;

int main() {
    const auto tri = triangle3::make({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const auto ray = ray3::make({0.5, 0, 1}, {0, 0, -1});
    if (!tri || !ray) return 1;
    static_assert(intersects(ray3{{0.5, 0, 1}, {0, 0, -1}}, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    const bool hit = intersects(ray.value(), tri.value()); // exact tier: the ray grazes an edge
    const auto h = intersection(ray.value(), tri.value());
    const auto bad = sphere3::make({0, 0, 0}, -1.0);
    std::printf("edge hit: %s, t = %g; sphere3::make(r = -1): %s\n", hit ? "yes" : "no", h ? h->t : -1.0,
                bad ? "accepted" : bad.error().message());
    return hit && h && h->t == 1.0 && !bad ? 0 : 1;
}
