// Signs, certainties and the four precision tiers (DESIGN.md section 1).
export module incidence.core:tier;

export namespace incidence {

// The sign of a predicate's polynomial; each predicate says in one sentence what positive means.
enum class sign : signed char { negative = -1, zero = 0, positive = 1 };

[[nodiscard]] constexpr sign operator-(sign s) { return static_cast<sign>(-static_cast<int>(s)); }
[[nodiscard]] constexpr sign operator*(sign a, sign b) {
    return static_cast<sign>(static_cast<int>(a) * static_cast<int>(b));
}

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
concept tier = __is_same(T, exact) || __is_same(T, conservative) || __is_same(T, aggressive) ||
               __is_same(T, approximate);

// A closed interval [lo, hi] that contains the true value: what the conservative and
// aggressive tiers return for a computed quantity (a distance, a parameter t).
struct interval {
    double lo, hi;
    [[nodiscard]] constexpr bool contains(double x) const { return lo <= x && x <= hi; }
};

// Kleene three-valued logic on certainties.
[[nodiscard]] constexpr certainty operator!(certainty a) {
    return a == certainty::uncertain ? a : (a == certainty::yes ? certainty::no : certainty::yes);
}
[[nodiscard]] constexpr certainty to_certainty(bool b) { return b ? certainty::yes : certainty::no; }

} // namespace incidence
