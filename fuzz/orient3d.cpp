// orient3d: differential against CGAL Epeck on raw bit patterns (NaN, infinities, subnormals
// reach it), plus the filter's promise (a proven sign is the exact sign), the approximate tier
// on well-scaled inputs, and the symmetries orient3d(a,b,c,d) = -orient3d(b,a,c,d) =
// orient3d(b,c,a,d). Any disagreement aborts.
#include "testkit/oracle/cgal_oracle.hpp"
#include "replay.hpp"
#include <cmath>
#include <cstdlib>
#include <cstring>
import incidence;

using namespace incidence;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    double v[12] = {};
    std::memcpy(v, data, size < sizeof v ? size : sizeof v);
    const point3 a{v[0], v[1], v[2]}, b{v[3], v[4], v[5]}, c{v[6], v[7], v[8]}, d{v[9], v[10], v[11]};
    const sign s = orient3d(a, b, c, d); // must not crash or invoke UB on any input
    (void)orient3d<approximate>(a, b, c, d);
    const auto f = classify_sign([&](auto L) { return poly::orient3d(L, a, b, c, d); });
    bool finite = true;
    for (double x : v) finite = finite && std::isfinite(x);
    if (!finite) return 0;
    const int truth = oracle::orient3d(v, v + 3, v + 6, v + 9);
    if (static_cast<int>(s) != truth) std::abort();
    if (f.proven && static_cast<int>(f.value) != truth) std::abort();
    if (orient3d(b, a, c, d) != -s || orient3d(b, c, a, d) != s) std::abort();
    return 0;
}
