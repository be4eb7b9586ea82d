// The tier contracts every differential harness enforces; any breach aborts. Include after
// `import incidence;`.
#pragma once
#include <cstdlib>

template <class A, class B>
void contracts(const A& x, const B& y, bool truth) {
    using namespace incidence;
    const bool e = intersects<exact>(x, y);
    if (e != truth) std::abort();
    if (intersects<exact>(y, x) != e) std::abort();
    if (truth && !intersects<conservative>(x, y)) std::abort();
    if (!truth && intersects<aggressive>(x, y)) std::abort();
    const certainty c = classify(x, y);
    if (c != certainty::uncertain && (c == certainty::yes) != truth) std::abort();
}

// contains(x, y) against the truth: the exact tier agrees, conservative never misses, aggressive
// never lies, classify_contains is never wrong, the approximate tier finishes.
template <class A, class B>
void contains_contracts_with(const A& x, const B& y, bool truth) {
    using namespace incidence;
    (void)contains<approximate>(x, y);
    if (contains<exact>(x, y) != truth) std::abort();
    if (truth && !contains<conservative>(x, y)) std::abort();
    if (!truth && contains<aggressive>(x, y)) std::abort();
    const certainty c = classify_contains(x, y);
    if (c != certainty::uncertain && (c == certainty::yes) != truth) std::abort();
}
