// Recomputes one point of the audit's stability curves independently of the audit's truth: the
// same generated cases (tools/audit/generators.hpp, same seed streams), with the true answer
// from CGAL Epeck (the exact LP or QP for the OBB, k-DOP, half-space, ball-box and capsule pairs) instead of the exact tier. Prints one JSON object per level, one per line:
//   {"family": ..., "level": L, "skipped": n, "methods": {"name": [cases, wrong, fp, fn], ...}}
// Usage: audit_recompute SEED CASES FAMILY_INDEX LEVEL[,LEVEL...]   or   audit_recompute --families
#include "testkit/oracle/cgal_oracle.hpp"
#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>
#include <vector>
import incidence;
import incidence.detail;
#include "testkit/generators.hpp"
#include "testkit/methods.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/testing.hpp"
#include "testkit/flat_cases.hpp"
#include "testkit/circle2_cases.hpp"

using namespace incidence;

namespace {
void arr(point3 p, double* o) { o[0] = p.x, o[1] = p.y, o[2] = p.z; }
void arr(vec3 p, double* o) { o[0] = p.x, o[1] = p.y, o[2] = p.z; }

// CGAL Epeck truth; std::nullopt outside CGAL's preconditions (degenerate triangles).
int truth(const point3& p, const sphere3& s) {
    double q[3], c[3];
    arr(p, q), arr(s.center, c);
    return oracle::point_in_ball(q, c, s.radius);
}
int truth(const sphere3& a, const sphere3& b) {
    double c[3], d[3];
    arr(a.center, c), arr(b.center, d);
    return oracle::ball_ball(c, a.radius, d, b.radius);
}
int truth(const aabb3& b, const point3& p) {
    double q[3], mn[3], mx[3];
    arr(p, q), arr(b.min, mn), arr(b.max, mx);
    return oracle::point_in_box(q, mn, mx);
}
int truth(const aabb3& a, const aabb3& b) {
    double p[3], q[3], r[3], s[3];
    arr(a.min, p), arr(a.max, q), arr(b.min, r), arr(b.max, s);
    return oracle::box_box(p, q, r, s);
}
int truth(const ray3& r, const sphere3& s) {
    double o[3], d[3], c[3];
    arr(r.origin, o), arr(r.direction, d), arr(s.center, c);
    return oracle::ray_ball(o, d, c, s.radius);
}
int truth(const aabb3& b, const sphere3& s) {
    double mn[3], mx[3], c[3];
    arr(b.min, mn), arr(b.max, mx), arr(s.center, c);
    return oracle::ball_aabb(mn, mx, c, s.radius);
}
int truth(const aabb3& b, const ray3& r) {
    double o[3], d[3], mn[3], mx[3];
    arr(r.origin, o), arr(r.direction, d), arr(b.min, mn), arr(b.max, mx);
    return oracle::ray_box(o, d, mn, mx);
}
bool degenerate(const triangle3& t) {
    double a[3], b[3], c[3];
    arr(t.a, a), arr(t.b, b), arr(t.c, c);
    return oracle::triangle_is_degenerate(a, b, c);
}
int truth(const ray3& r, const triangle3& t) {
    if (degenerate(t)) return -1;
    double o[3], d[3], a[3], b[3], c[3];
    arr(r.origin, o), arr(r.direction, d), arr(t.a, a), arr(t.b, b), arr(t.c, c);
    return oracle::ray_triangle(o, d, a, b, c);
}
int truth(const segment3& s, const triangle3& t) {
    if (degenerate(t) || s.a == s.b) return -1;
    double p[3], q[3], a[3], b[3], c[3];
    arr(s.a, p), arr(s.b, q), arr(t.a, a), arr(t.b, b), arr(t.c, c);
    return oracle::segment_triangle(p, q, a, b, c);
}
int truth(const aabb3& b, const plane3& p) {
    if (p.normal.x == 0 && p.normal.y == 0 && p.normal.z == 0) return -1;
    double mn[3], mx[3], n[3];
    arr(b.min, mn), arr(b.max, mx), arr(p.normal, n);
    return oracle::box_plane(mn, mx, n, p.offset);
}
int truth(const plane3& p, const segment3& s) {
    if (p.normal.x == 0 && p.normal.y == 0 && p.normal.z == 0) return -1;
    double n[3], a[3], b[3];
    arr(p.normal, n), arr(s.a, a), arr(s.b, b);
    return oracle::plane_segment(n, p.offset, a, b);
}
int truth(const plane3& p, const triangle3& t) {
    if ((p.normal.x == 0 && p.normal.y == 0 && p.normal.z == 0) || degenerate(t)) return -1;
    double n[3], a[3], b[3], c[3];
    arr(p.normal, n), arr(t.a, a), arr(t.b, b), arr(t.c, c);
    return oracle::plane_triangle(n, p.offset, a, b, c);
}
int truth(const aabb3& b, const segment3& s) {
    double mn[3], mx[3], p[3], q[3];
    arr(b.min, mn), arr(b.max, mx), arr(s.a, p), arr(s.b, q);
    return oracle::box_segment(mn, mx, p, q);
}
int truth(const aabb3& b, const line3& l) {
    if (l.direction.x == 0 && l.direction.y == 0 && l.direction.z == 0) return -1;
    double mn[3], mx[3], p[3], d[3];
    arr(b.min, mn), arr(b.max, mx), arr(l.origin, p), arr(l.direction, d);
    return oracle::box_line(mn, mx, p, d);
}
int truth(const aabb3& b, const triangle3& t) {
    if (degenerate(t)) return -1;
    double mn[3], mx[3], a[3], c[3], d[3];
    arr(b.min, mn), arr(b.max, mx), arr(t.a, a), arr(t.b, c), arr(t.c, d);
    return oracle::box_triangle(mn, mx, a, c, d);
}
int truth(const triangle3& t, const triangle3& u) {
    if (degenerate(t) || degenerate(u)) return -1;
    double a[3], b[3], c[3], d[3], e[3], f[3];
    arr(t.a, a), arr(t.b, b), arr(t.c, c), arr(u.a, d), arr(u.b, e), arr(u.c, f);
    return oracle::triangle_triangle(a, b, c, d, e, f);
}
// The OBB, k-DOP, convex polyhedron and frustum pairs: exact LP feasibility.
template <class A, class B>
requires(std::is_same_v<A, obb3> || std::is_same_v<B, obb3> || std::is_same_v<A, kdop<14>> || std::is_same_v<B, kdop<14>> ||
         std::is_same_v<A, convex_polyhedron3> || std::is_same_v<A, frustum3> || std::is_same_v<B, convex_polyhedron3> ||
         std::is_same_v<B, frustum3>)
int truth(const A& a, const B& b) {
    return oracle::lp_intersect(support::lp(a), support::lp(b));
}

// A ball against a half-space set: the exact QP (the squared distance from the centre) against r^2.
template <class P>
int ball_truth(const P& a, const sphere3& s) {
    const auto t = oracle::qp_ball_meets(support::lp(a), support::a3(s.center), s.radius);
    return t ? int(*t) : -1;
}
int truth(const frustum3& a, const sphere3& s) { return ball_truth(a, s); }
int truth(const convex_polyhedron3& a, const sphere3& s) { return ball_truth(a, s); }
int truth(const kdop<14>& a, const sphere3& s) { return ball_truth(a, s); }
int truth(const obb3& a, const sphere3& s) { return ball_truth(a, s); }
int truth(const segment3& a, const sphere3& s) { return ball_truth(a, s); }
int truth(const line3& a, const sphere3& s) { return ball_truth(a, s); }
int truth(const plane3& a, const sphere3& s) { return ball_truth(a, s); }
int truth(const sphere3& s, const triangle3& a) { return ball_truth(a, s); }
int truth(const sphere3& s, const tetrahedron3& a) { return ball_truth(a, s); }
// A capsule: the exact QP (the squared distance between its segment and the partner's core).
template <class B>
int capsule_truth(const capsule3& c, const B& b) {
    std::optional<bool> t;
    const auto seg = support::lp(segment3{c.a, c.b});
    if constexpr (std::is_same_v<B, sphere3>) t = oracle::qp_sets_within(seg, support::lp(b.center), c.radius, b.radius);
    else if constexpr (std::is_same_v<B, capsule3>) t = oracle::qp_sets_within(seg, support::lp(segment3{b.a, b.b}), c.radius, b.radius);
    else t = oracle::qp_sets_within(seg, support::lp(b), c.radius);
    return t ? int(*t) : -1;
}
template <class B>
int truth(const capsule3& c, const B& b) {
    return capsule_truth(c, b);
}
int truth(const aabb3& b, const capsule3& c) { return capsule_truth(c, b); }
// A disk in the plane: testkit/circle2_cases.hpp's oracle (CGAL's squared distance over Epeck in the
// plane z = 0, exact rationals for two disks and a point).
template <class B>
int truth(const circle2& c, const B& b) {
    return support::disk_truth(c, b);
}

// The other flat pairs: CGAL Epeck (tests/oracle/cgal_flat.cpp).
template <class A, class B>
requires((support::flat_shape<A> && support::flat_shape<B>) || (support::flat2_shape<A> && support::flat2_shape<B>))
int truth(const A& a, const B& b) {
    return support::flat_truth(a, b);
}

// Not inlined: main's fold calls every family's instantiation once.
template <class Family>
[[gnu::noinline]] void recompute(const Family& fam, std::uint64_t seed, long cases, unsigned index, int level) {
    using A = typename Family::first_type;
    using B = typename Family::second_type;
    const auto ms = audit::methods_of(fam);
    std::vector<long> n(ms.size()), w(ms.size()), fp(ms.size()), fn(ms.size());
    long skipped = 0;
    for (unsigned s = 0; s < audit::setting_count; ++s) {
        audit::rng r(audit::stream(seed, index, level, s));
        for (long i = 0; i < cases; ++i) {
            const auto [a, b] = audit::make_case<A, B>(r, level, audit::settings[s]);
            const int t = truth(a, b);
            if (t < 0) {
                ++skipped;
                continue;
            }
            for (std::size_t m = 0; m < ms.size(); ++m) {
                if (ms[m].kind == "peer" && !audit::peer_accepts(a, b)) continue;
                const bool ans = ms[m].test(a, b);
                ++n[m];
                if (ans != (t == 1)) ++w[m], ++(ans ? fp[m] : fn[m]);
            }
        }
    }
    std::printf("{\"family\": \"%s\", \"level\": %d, \"skipped\": %ld, \"methods\": {", fam.name, level, skipped);
    for (std::size_t m = 0; m < ms.size(); ++m)
        std::printf("%s\"%s\": [%ld, %ld, %ld, %ld]", m ? ", " : "", ms[m].name.c_str(), n[m], w[m], fp[m], fn[m]);
    std::printf("}}\n");
}
} // namespace

int main(int argc, char** argv) {
    if (argc == 2 && std::string(argv[1]) == "--families") {
        std::printf("[");
        bool first = true;
        catalog::for_each_family([&](const auto& f) { std::printf("%s\"%s\"", first ? "" : ", ", f.name), first = false; });
        std::printf("]\n");
        return 0;
    }
    if (argc != 5) {
        std::fprintf(stderr, "usage: audit_recompute SEED CASES FAMILY_INDEX LEVEL[,LEVEL...] | --families\n");
        return 2;
    }
    const auto seed = std::strtoull(argv[1], nullptr, 10);
    const long cases = std::strtol(argv[2], nullptr, 10);
    const auto index = unsigned(std::strtoul(argv[3], nullptr, 10));
    // one JSON line per level, in the order given (one process for a family's sample)
    std::vector<int> levels;
    for (const char* p = argv[4]; *p;) {
        char* end = nullptr;
        levels.push_back(int(std::strtol(p, &end, 10)));
        if (end == p || (*end != ',' && *end != 0)) {
            std::fprintf(stderr, "audit_recompute: LEVEL is a comma-separated list of integers\n");
            return 2;
        }
        p = *end == ',' ? end + 1 : end;
    }
    if (index >= catalog::family_count) {
        std::fprintf(stderr, "audit_recompute: family index or level out of range\n");
        return 2;
    }
    for (const int level : levels)
        if (level < 0 || level >= audit::level_count) {
            std::fprintf(stderr, "audit_recompute: family index or level out of range\n");
            return 2;
        }
    unsigned i = 0;
    catalog::for_each_family([&](const auto& f) {
        if (i++ == index)
            for (const int level : levels) recompute(f, seed, cases, index, level);
    });
    return 0;
}
