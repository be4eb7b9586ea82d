// A line, a ray or a segment against a scene of triangles (scene3), either argument order:
// - intersects<Tier>(x, scene): does x meet some triangle? The scalar intersects<Tier>(x, triangle)
//   of the triangles that the hierarchy cannot rule out (their boxes may meet x): in the exact and
//   aggressive tiers the brute force's answer (the scalar tier looped over every triangle);
//   conservative never says no where x meets a triangle, and says yes only where the brute force
//   does; approximate ORs the plain-double answers of at least the triangles whose boxes x meets.
// - intersection<Tier>(x, scene) -> std::optional<scene_hit>: the first contact of x with the
//   triangles' union, its least parameter there (t, point, the triangle's normal and barycentrics,
//   and the index the caller gave that triangle); where triangles tie at that parameter exactly,
//   the least index. Its values are the scalar intersection<Tier>(x, triangle)'s of that triangle:
//   exact correctly rounded; conservative and aggressive intervals that contain the exact values
//   (both decide every comparison exactly, so exists is always yes and the triangle is the exact
//   tier's); approximate in plain double (exists uncertain): the scalar approximate values of the
//   triangle it names, with the scalar pair's bound where every comparison of parameters is decided
//   the same way in double.
// Method: depth-first traversal of the hierarchy, near child first (by the split axis and the sign
// of the direction), a node skipped when the object surely misses its box: the slab test (Kay and
// Kajiya, SIGGRAPH 1986) with the entry and exit parameters widened by 2^-49 of their magnitude
// plus 2^-1070, which covers the four roundings of (bound - o) (1 / d) and of a segment's
// d = q - o where every coordinate lies within 2^400 and every nonzero direction component in
// [2^-400, 2^400] (then nothing overflows and an underflow costs at most 2^-1075). Widening the
// largest computed entry a_m bounds the true entry from below (true entry >= true a_m >= a_m -
// error(a_m)), so it is done once, after the maxima; likewise the exit. Outside that range, the
// conservative tier's box test. A first hit also skips every node that begins beyond an
// upper bound of the best parameter so far (its interval enclosure). The triangles' signs and the
// comparisons of their parameters (engines/contact.cppm, degree <= 6) run in the filter with the
// exact sign in place where it cannot decide (filter_kernel::decided_sgn), so one pass decides.
module;
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
export module incidence.scene:linear_scene;
import incidence.core;
import incidence.shapes;
import :scene3;

export namespace incidence {

// The first contact of a linear object with a scene: as triangle_hit, and the triangle's index.
template <class V = double>
struct scene_hit {
    V t;
    point_of<V> point;
    vec_of<V> normal;     // of the triangle hit, (b - a) x (c - a)
    V u, v, w;            // its barycentrics (0 for a degenerate triangle)
    std::size_t triangle; // the caller's index; std::size_t(-1) only in a conservative hit that may exist (exists uncertain)
    certainty exists = certainty::yes;
};

template <class S>
concept scene_linear = std::is_same_v<S, ray3> || std::is_same_v<S, segment3> || std::is_same_v<S, line3>;

template <tier Tier>
using scene_value_t = std::conditional_t<std::is_same_v<Tier, conservative> || std::is_same_v<Tier, aggressive>, interval, double>;

} // namespace incidence

namespace incidence::detail {
// Compiled once in the library (traversal.cpp), for each tier and linear shape.
template <class Tier, class S>
[[nodiscard]] bool scene_any_hit(const S& x, const scene3& s);
template <class Tier, class S>
[[nodiscard]] std::optional<scene_hit<scene_value_t<Tier>>> scene_first_hit(const S& x, const scene3& s);
} // namespace incidence::detail

export namespace incidence::detail {
// The first hit of a ray among `count` triangles, with the scene's rule (the least parameter,
// ties to the least index), for the batches (batch::intersection): fill(context, start, n,
// candidate, triangles) writes triangles start .. start + n - 1 (n <= candidate_block) and marks
// with candidate[i] == 0 those the ray surely misses. Compiled once (traversal.cpp) per tier.
inline constexpr std::size_t candidate_block = 64;
using candidates_fn = void (*)(const void* context, std::size_t start, std::size_t n, std::uint8_t* candidate, triangle3* triangles);
template <class Tier>
[[nodiscard]] std::optional<scene_hit<scene_value_t<Tier>>> triangles_first_hit(const ray3& r, std::size_t count, candidates_fn fill,
                                                                                const void* context);
} // namespace incidence::detail

export namespace incidence {

template <tier Tier = exact, scene_linear S>
[[nodiscard]] bool intersects(const S& x, const scene3& s) {
    return detail::scene_any_hit<Tier>(x, s);
}
template <tier Tier = exact, scene_linear S>
[[nodiscard]] bool intersects(const scene3& s, const S& x) {
    return detail::scene_any_hit<Tier>(x, s);
}
template <tier Tier = exact, scene_linear S>
[[nodiscard]] std::optional<scene_hit<scene_value_t<Tier>>> intersection(const S& x, const scene3& s) {
    return detail::scene_first_hit<Tier>(x, s);
}
template <tier Tier = exact, scene_linear S>
[[nodiscard]] std::optional<scene_hit<scene_value_t<Tier>>> intersection(const scene3& s, const S& x) {
    return detail::scene_first_hit<Tier>(x, s);
}

} // namespace incidence
