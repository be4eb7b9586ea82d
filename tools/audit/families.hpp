// The audit's stability and tradeoff runs over the families of incidence::catalog, split into
// parts that compile in separate files (families_part1.cpp .. families_part4.cpp) so the build
// spreads them over the cores; audit.cpp calls the parts in order. Include after
// `import incidence;`, the CGAL oracle header, generators.hpp, json.hpp and methods.hpp.
#pragma once
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace audit_run {

using namespace incidence;

struct options {
    std::string command = "all";
    std::string scene;
    std::string out = "audit-report";
    long cases = 500; // per level and setting
    long tradeoff_cases = 6000;
    std::uint64_t seed = 20261122;
    int reps = 7;
    int rays = 24;       // camera rays per side
    long pairs = 400000; // cap on near (non-adjacent) triangle pairs
    bool report = true;
};

// Progress on stderr, only when it is a terminal (audit.cpp).
void progress(const char* fmt, ...);
void progress_done();

inline double now_ns() { return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

struct counts {
    long cases = 0, wrong = 0, false_positive = 0, false_negative = 0;
    void add(bool answer, bool truth) {
        ++cases;
        if (answer != truth) {
            ++wrong;
            if (answer) ++false_positive;
            else ++false_negative;
        }
    }
};
// A one-sided tier's promise: conservative never answers no to a true yes, aggressive never yes to a no.
inline long violations(const std::string& name, const counts& c) {
    if (name == "conservative") return c.false_negative;
    if (name == "aggressive") return c.false_positive;
    if (name == "exact") return c.wrong;
    return 0;
}

// --- stability -------------------------------------------------------------------------------
// Not inlined (nor tradeoff_family): each part's fold calls every family once, and inlining them
// all made one function that took most of a part's compile time.
template <class Family>
[[gnu::noinline]] void stability_family(audit::json& j, const Family& fam, unsigned index, const options& o, long& total_violations) {
    using A = typename Family::first_type;
    using B = typename Family::second_type;
    const auto ms = audit::methods_of(fam);
    std::vector<std::vector<counts>> by_level(ms.size(), std::vector<counts>(audit::level_count));
    std::vector<std::vector<counts>> by_setting(ms.size(), std::vector<counts>(audit::setting_count));
    std::vector<long> uncertain(audit::level_count, 0);
    for (int level = 0; level < audit::level_count; ++level) {
        progress("stability: %s, level %d of %d", fam.name, level + 1, audit::level_count);
        for (unsigned s = 0; s < audit::setting_count; ++s) {
            audit::rng r(audit::stream(o.seed, index, level, s));
            for (long i = 0; i < o.cases; ++i) {
                const auto [a, b] = audit::make_case<A, B>(r, level, audit::settings[s]);
                const bool truth = ms[0].test(a, b);
                if (classify(a, b) == certainty::uncertain) ++uncertain[std::size_t(level)];
                for (std::size_t m = 0; m < ms.size(); ++m) {
                    if (ms[m].kind == "peer" && !audit::peer_accepts(a, b)) continue;
                    const bool ans = ms[m].test(a, b);
                    by_level[m][std::size_t(level)].add(ans, truth);
                    by_setting[m][s].add(ans, truth);
                }
            }
        }
    }
    j.object().kv("name", fam.name).kv("cases_per_level", o.cases * long(audit::setting_count)).list("uncertain", uncertain);
    j.key("methods").array();
    for (std::size_t m = 0; m < ms.size(); ++m) {
        long v = 0;
        std::vector<long> n, w, fp, fn;
        for (const counts& c : by_level[m]) {
            n.push_back(c.cases), w.push_back(c.wrong), fp.push_back(c.false_positive), fn.push_back(c.false_negative);
            v += violations(ms[m].name, c);
        }
        total_violations += v;
        if (v) std::fprintf(stderr, "incidence-audit: %s %s broke its contract %ld times\n", fam.name, ms[m].name.c_str(), v);
        j.object().kv("name", ms[m].name).kv("kind", ms[m].kind).kv("contract_violations", v);
        j.list("cases", n).list("wrong", w).list("false_positive", fp).list("false_negative", fn);
        j.key("by_setting").array();
        for (const counts& c : by_setting[m])
            j.object()
                .kv("cases", c.cases)
                .kv("wrong", c.wrong)
                .kv("false_positive", c.false_positive)
                .kv("false_negative", c.false_negative)
                .end_object();
        j.end_array().end_object();
    }
    j.end_array().end_object();
}

// --- tradeoff --------------------------------------------------------------------------------
// Median ns per call of each method over a set, the methods interleaved in every repetition.
template <class M, class A, class B>
std::vector<double> time_methods(const std::vector<M>& ms, const std::vector<A>& as, const std::vector<B>& bs,
                                 const std::vector<char>& peer_ok, int reps) {
    std::vector<std::vector<double>> t(ms.size());
    volatile long sink = 0;
    for (int rep = 0; rep < reps; ++rep)
        for (std::size_t m = 0; m < ms.size(); ++m) {
            const bool peer = ms[m].kind == "peer";
            long n = 0, hits = 0;
            const double t0 = now_ns();
            for (std::size_t i = 0; i < as.size(); ++i) {
                if (peer && !peer_ok[i]) continue;
                hits += ms[m].test(as[i], bs[i]);
                ++n;
            }
            const double t1 = now_ns();
            sink = sink + hits;
            t[m].push_back(n ? (t1 - t0) / double(n) : 0.0);
        }
    std::vector<double> med;
    for (auto& v : t) med.push_back(median(v));
    return med;
}

template <class Family>
[[gnu::noinline]] void tradeoff_family(audit::json& j, const Family& fam, unsigned index, const options& o) {
    using A = typename Family::first_type;
    using B = typename Family::second_type;
    const auto ms = audit::methods_of(fam);
    // near-degenerate: separations 2^-30..2^-60 and 0..8-ulp moves; random: separation 2^0..2^-3.
    std::vector<A> na, ra;
    std::vector<B> nb, rb;
    audit::rng r(audit::stream(o.seed, index, -1, 99));
    for (long i = 0; i < o.tradeoff_cases; ++i) {
        const auto& s = audit::settings[std::size_t(r.integer(0, audit::setting_count - 1))];
        const int near_level = r.coin() ? r.integer(30, 60) : audit::separation_levels + r.integer(0, audit::ulp_levels - 1);
        auto [a, b] = audit::make_case<A, B>(r, near_level, s);
        na.push_back(a), nb.push_back(b);
        auto [c, d] = audit::make_case<A, B>(r, r.integer(0, 3), s);
        ra.push_back(c), rb.push_back(d);
    }
    auto truth_and_ok = [&](const std::vector<A>& as, const std::vector<B>& bs, std::vector<char>& truth, std::vector<char>& ok) {
        for (std::size_t i = 0; i < as.size(); ++i) {
            truth.push_back(ms[0].test(as[i], bs[i]));
            ok.push_back(audit::peer_accepts(as[i], bs[i]));
        }
    };
    std::vector<char> nt, nok, rt, rok;
    truth_and_ok(na, nb, nt, nok);
    truth_and_ok(ra, rb, rt, rok);
    progress("tradeoff: %s, timing %zu methods", fam.name, ms.size());
    const auto tn = time_methods(ms, na, nb, nok, o.reps);
    const auto tr = time_methods(ms, ra, rb, rok, o.reps);
    std::vector<double> err_near(ms.size()), err_random(ms.size());
    std::vector<long> wrong_near(ms.size());
    for (std::size_t m = 0; m < ms.size(); ++m) {
        counts cn, cr;
        for (std::size_t i = 0; i < na.size(); ++i) {
            if (ms[m].kind == "peer" && !nok[i]) continue;
            cn.add(ms[m].test(na[i], nb[i]), nt[i]);
        }
        for (std::size_t i = 0; i < ra.size(); ++i) {
            if (ms[m].kind == "peer" && !rok[i]) continue;
            cr.add(ms[m].test(ra[i], rb[i]), rt[i]);
        }
        wrong_near[m] = cn.wrong;
        err_near[m] = cn.cases ? double(cn.wrong) / double(cn.cases) : 0.0;
        err_random[m] = cr.cases ? double(cr.wrong) / double(cr.cases) : 0.0;
    }
    j.object().kv("name", fam.name).kv("near_cases", na.size()).kv("random_cases", ra.size());
    j.key("methods").array();
    for (std::size_t m = 0; m < ms.size(); ++m) {
        bool pareto = true; // no other method is at least as fast and as accurate, and better in one
        for (std::size_t q = 0; q < ms.size(); ++q)
            if (q != m && tn[q] <= tn[m] && err_near[q] <= err_near[m] && (tn[q] < tn[m] || err_near[q] < err_near[m])) pareto = false;
        j.object().kv("name", ms[m].name).kv("kind", ms[m].kind).kv("source", ms[m].source);
        j.kv("ns_near", tn[m]).kv("ns_random", tr[m]).kv("wrong_near", wrong_near[m]);
        j.kv("error_rate_near", err_near[m]).kv("error_rate_random", err_random[m]).kv("pareto", pareto).end_object();
    }
    j.end_array().end_object();
}

// The parts: families [part_begin[p], part_begin[p + 1]) of catalog::families, each family
// keeping its index in the catalog (its random stream).
inline constexpr std::size_t part_count = 4;
inline constexpr std::array<std::size_t, part_count + 1> part_begin{0, catalog::family_count / 4, catalog::family_count / 2,
                                                                    3 * catalog::family_count / 4, catalog::family_count};

template <std::size_t Part>
void stability_part(audit::json& j, const options& o, long& total_violations) {
    constexpr std::size_t lo = part_begin[Part];
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (stability_family(j, std::get<lo + I>(catalog::families), unsigned(lo + I), o, total_violations), ...);
    }(std::make_index_sequence<part_begin[Part + 1] - lo>{});
}
template <std::size_t Part>
void tradeoff_part(audit::json& j, const options& o) {
    constexpr std::size_t lo = part_begin[Part];
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (tradeoff_family(j, std::get<lo + I>(catalog::families), unsigned(lo + I), o), ...);
    }(std::make_index_sequence<part_begin[Part + 1] - lo>{});
}
extern template void stability_part<0>(audit::json&, const options&, long&);
extern template void stability_part<1>(audit::json&, const options&, long&);
extern template void stability_part<2>(audit::json&, const options&, long&);
extern template void stability_part<3>(audit::json&, const options&, long&);
extern template void tradeoff_part<0>(audit::json&, const options&);
extern template void tradeoff_part<1>(audit::json&, const options&);
extern template void tradeoff_part<2>(audit::json&, const options&);
extern template void tradeoff_part<3>(audit::json&, const options&);

} // namespace audit_run
