// qhull (Barber, Dobkin, Huhdanpaa; Debian's libqhull-dev, reentrant libqhull_r) as a peer for
// the convex-hull timings: build time, vertex count, and whether it reports an error.
#include "cgal_oracle.hpp"

#include <chrono>
#include <cstdio>
#include <vector>
extern "C" {
#include <libqhull_r/libqhull_r.h>
}

namespace oracle {

qhull_result qhull_hull(const double* xyz, unsigned long n) {
    std::vector<coordT> pts(xyz, xyz + 3 * n);
    qhT qh_qh;
    qhT* qh = &qh_qh;
    FILE* err = std::fopen("/dev/null", "w");
    qh_zero(qh, err);
    char cmd[] = "qhull";
    const auto t0 = std::chrono::steady_clock::now();
    const int code = qh_new_qhull(qh, 3, int(n), pts.data(), False, cmd, nullptr, err);
    const auto t1 = std::chrono::steady_clock::now();
    qhull_result r;
    r.ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
    r.error = code != 0;
    r.vertices = code == 0 ? static_cast<unsigned long>(qh->num_vertices) : 0;
    qh_freeqhull(qh, !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(qh, &curlong, &totlong);
    std::fclose(err);
    return r;
}

} // namespace oracle
