// Signs, certainties and the four precision tiers (docs/DESIGN.md, "Tiers").
module;
#include <type_traits>
export module incidence.core:tier;
import :vec;

export namespace incidence {

// The sign of a predicate's polynomial; each predicate says in one sentence what positive means.
enum class sign : signed char { negative = -1, zero = 0, positive = 1 };

[[nodiscard]] constexpr sign operator-(sign s) { return static_cast<sign>(-static_cast<int>(s)); }
[[nodiscard]] constexpr sign operator*(sign a, sign b) { return static_cast<sign>(static_cast<int>(a) * static_cast<int>(b)); }

// What a floating-point filter can say about a yes/no question.
enum class certainty : unsigned char { no, yes, uncertain };

// answer == the true answer on the exact rational values of the inputs, always.
struct exact {};
// A `no` is certain: a true yes is never reported as no.
struct conservative {};
// A `yes` is certain: a true no is never reported as yes.
struct aggressive {};
// Plain floating point, fastest; wrong only within the stated distance of the decision boundary.
struct approximate {};

template <class T>
concept tier =
    std::is_same_v<T, exact> || std::is_same_v<T, conservative> || std::is_same_v<T, aggressive> || std::is_same_v<T, approximate>;

// A closed interval [lo, hi] that contains the true value: what the conservative and
// aggressive tiers return for a computed quantity (a distance, a parameter t). An end may be
// infinite (a parameter whose line lies in a plane, a denominator not proven nonzero).
struct interval {
    double lo, hi;
    [[nodiscard]] constexpr bool contains(double x) const { return lo <= x && x <= hi; }
    [[nodiscard]] constexpr double width() const { return hi - lo; }
    friend constexpr bool operator==(const interval&, const interval&) = default;
};
// Three intervals: the box that contains a computed point or vector (a hit point, a normal) in
// the conservative and aggressive tiers.
struct interval3 {
    interval x, y, z;
    [[nodiscard]] constexpr bool contains(point3 p) const { return x.contains(p.x) && y.contains(p.y) && z.contains(p.z); }
    [[nodiscard]] constexpr bool contains(vec3 v) const { return x.contains(v.x) && y.contains(v.y) && z.contains(v.z); }
    friend constexpr bool operator==(const interval3&, const interval3&) = default;
};

// Kleene three-valued logic on certainties.
[[nodiscard]] constexpr certainty operator!(certainty a) {
    return a == certainty::uncertain ? a : (a == certainty::yes ? certainty::no : certainty::yes);
}
[[nodiscard]] constexpr certainty to_certainty(bool b) { return b ? certainty::yes : certainty::no; }

} // namespace incidence
