// Floating-point expansions: a value is the exact sum of nonoverlapping doubles, stored in
// increasing magnitude with zeros eliminated. Capacities grow at compile time
// (sum: N+M, product: 2NM), so generic predicate code evaluates exactly without allocation.
// Source: Shewchuk, DCG 18 (1997), sections 2.6-2.8 (Fast-Expansion-Sum, Scale-Expansion,
// both with zero elimination); requires round-to-nearest-even and no underflow/overflow,
// which the caller ensures by scaling inputs into a safe exponent window (kernel.cppm).
module;
#include <array>
export module incidence.arith:expansion;
import :eft;

export namespace incidence::arith {

template <int N>
struct expansion {
    static constexpr int capacity = N;
    // Only c[0 .. n) is ever read; the rest stays uninitialised (no memset of large capacities).
    std::array<double, N> c;
    int n = 1; // at least one component; zero is {0.0}

    // Constant evaluation forbids copying indeterminate values, so fill there only.
    constexpr expansion() {
        if (__builtin_is_constant_evaluated()) c.fill(0.0);
        c[0] = 0.0;
    }
    constexpr explicit expansion(double x) : expansion() { c[0] = x; }

    [[nodiscard]] constexpr double estimate() const {
        double s = 0.0;
        for (int i = 0; i < n; ++i) s += c[static_cast<unsigned>(i)];
        return s;
    }
    // The sign of an expansion is the sign of its largest (last) component.
    [[nodiscard]] constexpr int sign() const {
        const double top = c[static_cast<unsigned>(n - 1)];
        return top > 0.0 ? 1 : (top < 0.0 ? -1 : 0);
    }
};

// Shewchuk's Fast-Expansion-Sum-Zeroelim: h = e + f.
template <int N, int M>
[[nodiscard]] constexpr expansion<N + M> fast_expansion_sum_zeroelim(const expansion<N>& e,
                                                                     const expansion<M>& f) {
    expansion<N + M> h;
    int hindex = 0;
    int ei = 0, fi = 0;
    double enow = e.c[0], fnow = f.c[0];
    double q;
    auto next_e = [&] { ++ei; if (ei < e.n) enow = e.c[static_cast<unsigned>(ei)]; };
    auto next_f = [&] { ++fi; if (fi < f.n) fnow = f.c[static_cast<unsigned>(fi)]; };
    auto emit = [&](double hh) { if (hh != 0.0) h.c[static_cast<unsigned>(hindex++)] = hh; };
    if ((fnow > enow) == (fnow > -enow)) { q = enow; next_e(); }
    else { q = fnow; next_f(); }
    if (ei < e.n && fi < f.n) {
        two_double s{};
        if ((fnow > enow) == (fnow > -enow)) { s = fast_two_sum(enow, q); next_e(); }
        else { s = fast_two_sum(fnow, q); next_f(); }
        q = s.hi; emit(s.lo);
        while (ei < e.n && fi < f.n) {
            if ((fnow > enow) == (fnow > -enow)) { s = two_sum(q, enow); next_e(); }
            else { s = two_sum(q, fnow); next_f(); }
            q = s.hi; emit(s.lo);
        }
    }
    while (ei < e.n) { const auto s = two_sum(q, enow); next_e(); q = s.hi; emit(s.lo); }
    while (fi < f.n) { const auto s = two_sum(q, fnow); next_f(); q = s.hi; emit(s.lo); }
    if (q != 0.0 || hindex == 0) h.c[static_cast<unsigned>(hindex++)] = q;
    h.n = hindex;
    return h;
}

// Shewchuk's Scale-Expansion-Zeroelim: h = e * b.
template <int N>
[[nodiscard]] constexpr expansion<2 * N> scale_expansion_zeroelim(const expansion<N>& e, double b) {
    expansion<2 * N> h;
    int hindex = 0;
    auto emit = [&](double hh) { if (hh != 0.0) h.c[static_cast<unsigned>(hindex++)] = hh; };
    auto p = two_product(e.c[0], b);
    double q = p.hi;
    emit(p.lo);
    for (int i = 1; i < e.n; ++i) {
        const auto prod = two_product(e.c[static_cast<unsigned>(i)], b);
        const auto s = two_sum(q, prod.lo);
        emit(s.lo);
        const auto t = fast_two_sum(prod.hi, s.hi);
        q = t.hi;
        emit(t.lo);
    }
    if (q != 0.0 || hindex == 0) h.c[static_cast<unsigned>(hindex++)] = q;
    h.n = hindex;
    return h;
}

template <int N, int M>
[[nodiscard]] constexpr expansion<N + M> operator+(const expansion<N>& a, const expansion<M>& b) {
    return fast_expansion_sum_zeroelim(a, b);
}
template <int N>
[[nodiscard]] constexpr expansion<N> operator-(const expansion<N>& a) {
    expansion<N> r = a;
    for (int i = 0; i < r.n; ++i) r.c[static_cast<unsigned>(i)] = -r.c[static_cast<unsigned>(i)];
    return r;
}
template <int N, int M>
[[nodiscard]] constexpr expansion<N + M> operator-(const expansion<N>& a, const expansion<M>& b) {
    if constexpr (N == 1 && M == 1) {
        // Two-Diff keeps the common case (difference of two inputs) cheap.
        const auto d = two_diff(a.c[0], b.c[0]);
        expansion<2> r;
        if (d.lo != 0.0) { r.c[0] = d.lo; r.c[1] = d.hi; r.n = 2; }
        else { r.c[0] = d.hi; r.n = 1; }
        return r;
    } else {
        return fast_expansion_sum_zeroelim(a, -b);
    }
}
// Product: scale the longer operand by each component of the shorter and sum the pieces.
template <int N, int M>
[[nodiscard]] constexpr expansion<2 * N * M> operator*(const expansion<N>& a, const expansion<M>& b) {
    expansion<2 * N * M> acc;
    const bool a_short = a.n <= b.n;
    const int count = a_short ? a.n : b.n;
    for (int i = 0; i < count; ++i) {
        expansion<2 * N * M> piece;
        if (a_short) {
            const auto s = scale_expansion_zeroelim(b, a.c[static_cast<unsigned>(i)]);
            piece.n = s.n;
            for (int j = 0; j < s.n; ++j) piece.c[static_cast<unsigned>(j)] = s.c[static_cast<unsigned>(j)];
        } else {
            const auto s = scale_expansion_zeroelim(a, b.c[static_cast<unsigned>(i)]);
            piece.n = s.n;
            for (int j = 0; j < s.n; ++j) piece.c[static_cast<unsigned>(j)] = s.c[static_cast<unsigned>(j)];
        }
        if (i == 0) { acc = piece; continue; }
        // acc + piece never exceeds the product's capacity: it is a partial sum of the product.
        const auto sum = fast_expansion_sum_zeroelim(acc, piece);
        acc.n = sum.n;
        for (int j = 0; j < sum.n; ++j) acc.c[static_cast<unsigned>(j)] = sum.c[static_cast<unsigned>(j)];
    }
    return acc;
}

} // namespace incidence::arith
