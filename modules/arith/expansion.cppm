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

// Shewchuk's Fast-Expansion-Sum-Zeroelim: h = e + f, returns the length of h (>= 1).
// h must not alias e or f and must hold elen + flen components.
[[nodiscard]] constexpr int fast_expansion_sum_zeroelim(int elen, const double* e, int flen, const double* f, double* h) {
    int hindex = 0, ei = 0, fi = 0;
    double enow = e[0], fnow = f[0];
    double q;
    auto next_e = [&] {
        if (++ei < elen) enow = e[ei];
    };
    auto next_f = [&] {
        if (++fi < flen) fnow = f[fi];
    };
    auto emit = [&](double hh) {
        if (hh != 0.0) h[hindex++] = hh;
    };
    if ((fnow > enow) == (fnow > -enow)) {
        q = enow;
        next_e();
    } else {
        q = fnow;
        next_f();
    }
    if (ei < elen && fi < flen) {
        two_double s{};
        if ((fnow > enow) == (fnow > -enow)) {
            s = fast_two_sum(enow, q);
            next_e();
        } else {
            s = fast_two_sum(fnow, q);
            next_f();
        }
        q = s.hi;
        emit(s.lo);
        while (ei < elen && fi < flen) {
            if ((fnow > enow) == (fnow > -enow)) {
                s = two_sum(q, enow);
                next_e();
            } else {
                s = two_sum(q, fnow);
                next_f();
            }
            q = s.hi;
            emit(s.lo);
        }
    }
    while (ei < elen) {
        const auto s = two_sum(q, enow);
        next_e();
        q = s.hi;
        emit(s.lo);
    }
    while (fi < flen) {
        const auto s = two_sum(q, fnow);
        next_f();
        q = s.hi;
        emit(s.lo);
    }
    if (q != 0.0 || hindex == 0) h[hindex++] = q;
    return hindex;
}

// Shewchuk's Scale-Expansion-Zeroelim: h = e * b, returns the length of h (>= 1).
// h must not alias e and must hold 2 elen components.
[[nodiscard]] constexpr int scale_expansion_zeroelim(int elen, const double* e, double b, double* h) {
    int hindex = 0;
    auto emit = [&](double hh) {
        if (hh != 0.0) h[hindex++] = hh;
    };
    auto p = two_product(e[0], b);
    double q = p.hi;
    emit(p.lo);
    for (int i = 1; i < elen; ++i) {
        const auto prod = two_product(e[i], b);
        const auto s = two_sum(q, prod.lo);
        emit(s.lo);
        const auto t = fast_two_sum(prod.hi, s.hi);
        q = t.hi;
        emit(t.lo);
    }
    if (q != 0.0 || hindex == 0) h[hindex++] = q;
    return hindex;
}

template <int N, int M>
[[nodiscard]] constexpr expansion<N + M> operator+(const expansion<N>& a, const expansion<M>& b) {
    expansion<N + M> r;
    r.n = fast_expansion_sum_zeroelim(a.n, a.c.data(), b.n, b.c.data(), r.c.data());
    return r;
}
template <int N>
[[nodiscard]] constexpr expansion<N> operator-(const expansion<N>& a) {
    expansion<N> r;
    r.n = a.n;
    for (int i = 0; i < a.n; ++i) r.c[static_cast<unsigned>(i)] = -a.c[static_cast<unsigned>(i)];
    return r;
}
template <int N>
[[nodiscard]] constexpr expansion<N> abs(const expansion<N>& a) {
    return a.sign() < 0 ? -a : a;
}
template <int N, int M>
[[nodiscard]] constexpr expansion<N + M> operator-(const expansion<N>& a, const expansion<M>& b) {
    if constexpr (N == 1 && M == 1) {
        // Two-Diff keeps the common case (difference of two inputs) cheap.
        const auto d = two_diff(a.c[0], b.c[0]);
        expansion<2> r;
        if (d.lo != 0.0) {
            r.c[0] = d.lo;
            r.c[1] = d.hi;
            r.n = 2;
        } else {
            r.c[0] = d.hi;
            r.n = 1;
        }
        return r;
    } else {
        return a + (-b);
    }
}
// Product: scale the longer operand by each component of the shorter and accumulate, ping-
// ponging between two buffers so that nothing is copied.
template <int N, int M>
[[nodiscard]] constexpr expansion<2 * N * M> operator*(const expansion<N>& a, const expansion<M>& b) {
    const bool a_short = a.n <= b.n;
    const double* sc = a_short ? a.c.data() : b.c.data();
    const double* lg = a_short ? b.c.data() : a.c.data();
    const int sn = a_short ? a.n : b.n, ln = a_short ? b.n : a.n;
    expansion<2 * N * M> r, other;
    std::array<double, 2 * (N > M ? N : M)> piece;
    if (__builtin_is_constant_evaluated()) piece.fill(0.0);
    double* acc = r.c.data();
    double* tmp = other.c.data();
    int accn = scale_expansion_zeroelim(ln, lg, sc[0], acc);
    for (int i = 1; i < sn; ++i) {
        const int pn = scale_expansion_zeroelim(ln, lg, sc[i], piece.data());
        // acc + piece is a partial sum of the product: it fits in 2 N M components.
        accn = fast_expansion_sum_zeroelim(accn, acc, pn, piece.data(), tmp);
        double* t = acc;
        acc = tmp;
        tmp = t;
    }
    if (acc != r.c.data())
        for (int i = 0; i < accn; ++i) r.c[static_cast<unsigned>(i)] = acc[i];
    r.n = accn;
    return r;
}

} // namespace incidence::arith
