// incidence.catalog is the one list of the pairs (docs/DESIGN.md, "One list"); this test checks
// every other list against it in both directions, and fails on a pair missing anywhere:
//   bodies         every family has its body (a kernel-generic detail::intersects, contains,
//                  intersection or squared_distance of its two shapes); every body that exists for
//                  two shapes of the library has a family;
//   tables         every family's table is a file modules/query/<table>.cppm, listed in
//                  CMakeLists.txt and exported by modules/detail.cppm; every file under
//                  modules/query/<kind>/ is some family's table; CMakeLists.txt and detail.cppm
//                  list the engines and tables there are, no more;
//   tests          every family's test exists and tests/CMakeLists.txt lists it; every test of
//                  tests/query/<kind>/ is some family's;
//   fuzzers        every family's fuzzer is a harness of fuzz/CMakeLists.txt; every pair harness
//                  runs some family (the predicate's, the bounding volumes' and the scenes' run none);
//   approximate    each yes/no family's alternatives and signs_in_double agree with the exact tier
//                  on clear-cut cases (far apart, deep inside), where no floating-point method errs
//                  (a culling test, keeps_misses, may keep a pair that misses: only its no counts).
// The benchmarks are checked by tools/pair_table (its CMakeLists.txt's bench_pairs_match_catalog),
// docs/pairs.md by docs_pairs_is_generated.
#include <catch2/catch_test_macros.hpp>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <typeinfo>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/generators.hpp"

namespace test_query_catalog { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
namespace fs = std::filesystem;

namespace {
const fs::path root(INCIDENCE_SOURCE_DIR);
std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}
std::set<std::string> matches(const std::string& text, const std::string& pattern) {
    std::set<std::string> out;
    const std::regex re(pattern);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it) out.insert((*it)[1].str());
    return out;
}
std::set<std::string> files(const fs::path& dir, const std::string& ext) {
    std::set<std::string> out;
    if (!fs::exists(dir)) return out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ext) out.insert(e.path().stem().string());
    return out;
}
void same(const std::set<std::string>& a, const std::set<std::string>& b, const char* what_a, const char* what_b) {
    for (const auto& x : a)
        if (!b.contains(x)) FAIL_CHECK(x << " is in " << what_a << " but not in " << what_b);
    for (const auto& x : b)
        if (!a.contains(x)) FAIL_CHECK(x << " is in " << what_b << " but not in " << what_a);
}

// Every shape of the library (k-DOPs as the 14-DOP), for the bodies' converse check.
using shapes = std::tuple<point3, segment3, ray3, line3, plane3, triangle3, tetrahedron3, aabb3, obb3, sphere3, kdop<14>,
                          convex_polyhedron3, frustum3, mesh3, polygon3, point2, segment2, ray2, line2, polygon2, circle2>;
template <class A, class B>
concept intersects_body = requires(arith::filter_kernel& k, const A& a, const B& b) { detail::intersects(k, a, b); };
template <class A, class B>
concept contains_body = requires(arith::filter_kernel& k, const A& a, const B& b) { detail::contains(k, a, b); };
template <class A, class B>
concept intersection_body = requires(arith::filter_kernel& k, const A& a, const B& b) { detail::intersection(k, a, b); };
template <class A, class B>
concept distance_body = requires(arith::filter_kernel& k, const A& a, const B& b) { detail::squared_distance(k, a, b); };

template <class A, class B, class List>
constexpr bool listed(const List& list) {
    bool found = false;
    std::apply(
        [&](const auto&... f) {
            ((found = found || (std::is_same_v<A, typename std::decay_t<decltype(f)>::first_type> &&
                                std::is_same_v<B, typename std::decay_t<decltype(f)>::second_type>)),
             ...);
        },
        list);
    return found;
}
} // namespace

TEST_CASE("catalog: bodies, tables, exports, tests and fuzzers agree with the catalog both ways", "[catalog]") {
    std::set<std::string> names, tables, tests, fuzzers;
    long families = 0;
    auto note = [&](const auto& f, const std::string& kind) {
        ++families;
        tables.insert(f.table);
        fuzzers.insert(f.fuzzer);
        const std::string table(f.table);
        const std::string stem = table.substr(table.find('/') + 1);
        tests.insert(kind == "intersects" || kind == "contains" ? "intersects/" + std::string(f.name)
                                                                : table.substr(0, table.find('/')) + "/" + stem);
        INFO(f.name << " (" << kind << ")");
        CHECK(fs::exists(root / "modules/query" / (table + ".cppm")));
        CHECK(table.rfind(kind == "contains" ? "contains/" : (kind + "/"), 0) == 0);
    };
    catalog::for_each_listed_family([&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        STATIC_CHECK(intersects_body<typename F::first_type, typename F::second_type>);
        INFO(f.name);
        CHECK(names.insert(f.name).second); // unique among the yes/no pairs
        note(f, "intersects");
    });
    catalog::for_each_containment([&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        STATIC_CHECK(contains_body<typename F::first_type, typename F::second_type>);
        note(f, "contains");
    });
    catalog::for_each_value_family([&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        STATIC_CHECK(intersection_body<typename F::first_type, typename F::second_type>);
        note(f, "intersection");
    });
    catalog::for_each_distance([&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        STATIC_CHECK(distance_body<typename F::first_type, typename F::second_type>);
        note(f, "distance");
    });

    // bodies: every body of two shapes of the library has a family
    long bodies = 0, unlisted = 0;
    auto converse = [&]<class A, class B>() {
        if constexpr (intersects_body<A, B>) {
            ++bodies;
            if (!listed<A, B>(catalog::families) && !listed<A, B>(catalog::view_families)) {
                ++unlisted;
                FAIL_CHECK("an intersects body without a family" << " " << typeid(A).name() << " " << typeid(B).name());
            }
        }
        if constexpr (contains_body<A, B>) {
            ++bodies;
            if (!listed<A, B>(catalog::containments)) {
                ++unlisted;
                FAIL_CHECK("a contains body without a family" << " " << typeid(A).name() << " " << typeid(B).name());
            }
        }
        if constexpr (intersection_body<A, B>) {
            ++bodies;
            if (!listed<A, B>(catalog::value_families)) {
                ++unlisted;
                FAIL_CHECK("an intersection body without a family" << " " << typeid(A).name() << " " << typeid(B).name());
            }
        }
        if constexpr (distance_body<A, B>) {
            ++bodies;
            if (!listed<A, B>(catalog::distances)) {
                ++unlisted;
                FAIL_CHECK("a squared_distance body without a family" << " " << typeid(A).name() << " " << typeid(B).name());
            }
        }
    };
    [&]<class... S>(std::tuple<S...>*) {
        auto row = [&]<class A>() { (converse.template operator()<A, S>(), ...); };
        (row.template operator()<S>(), ...);
    }(static_cast<shapes*>(nullptr));

    // tables: the files under modules/query/<kind>/, CMakeLists.txt's module list and detail.cppm's exports
    const std::string cmake = read(root / "CMakeLists.txt"), detail = read(root / "modules/detail.cppm");
    std::set<std::string> table_files, listed_units, exported;
    for (const char* kind : {"intersects", "contains", "intersection", "distance"})
        for (const auto& f : files(root / "modules/query" / kind, ".cppm")) table_files.insert(std::string(kind) + "/" + f);
    for (const auto& u : matches(cmake, R"(\n\s*modules/query/([a-z]+/[a-z0-9_]+)\.cppm)")) listed_units.insert(u);
    for (const auto& u : matches(detail, R"(export import :([a-z]+)\.([a-z0-9_]+);)")) (void)u;
    {
        const std::regex re(R"(export import :([a-z]+)\.([a-z0-9_]+);)");
        for (auto it = std::sregex_iterator(detail.begin(), detail.end(), re); it != std::sregex_iterator(); ++it)
            if ((*it)[1] != "engines") exported.insert((*it)[1].str() + "/" + (*it)[2].str());
    }
    same(tables, table_files, "the catalog's tables", "modules/query/<kind>/");
    same(table_files, listed_units, "modules/query/<kind>/", "CMakeLists.txt");
    same(table_files, exported, "modules/query/<kind>/", "modules/detail.cppm");
    std::set<std::string> engine_files = files(root / "modules/engines", ".cppm"), engine_units, engine_exports;
    for (const auto& u : matches(cmake, R"(\n\s*modules/engines/([a-z0-9_]+)\.cppm)")) engine_units.insert(u);
    for (const auto& u : matches(detail, R"(export import :engines\.([a-z0-9_]+);)")) engine_exports.insert(u);
    same(engine_files, engine_units, "modules/engines/", "CMakeLists.txt");
    same(engine_files, engine_exports, "modules/engines/", "modules/detail.cppm");

    // tests: the pair tests there are and tests/CMakeLists.txt's list
    const std::string test_list = read(root / "tests/CMakeLists.txt");
    std::set<std::string> test_files, listed_tests;
    for (const char* kind : {"intersects", "intersection", "distance"})
        for (const auto& f : files(root / "tests/query" / kind, ".cpp")) test_files.insert(std::string(kind) + "/" + f);
    for (const auto& t : matches(test_list, R"(\n\s*query/([a-z]+/[a-z0-9_]+)\.cpp)")) listed_tests.insert(t);
    same(tests, test_files, "the catalog's tests", "tests/query/<kind>/");
    same(test_files, listed_tests, "tests/query/<kind>/", "tests/CMakeLists.txt");

    // fuzzers: the harnesses of fuzz/CMakeLists.txt that run pairs (orient3d, bounding and scene run
    // none of the catalog's: the predicate, the bounding volumes, the scenes)
    const std::string fuzz_list = read(root / "fuzz/CMakeLists.txt");
    std::set<std::string> harnesses;
    {
        const std::smatch m = [&] {
            std::smatch r;
            std::regex_search(fuzz_list, r, std::regex(R"(foreach\(name ([a-z0-9_ ]+)\))"));
            return r;
        }();
        std::istringstream in(m[1].str());
        for (std::string h; in >> h;)
            if (h != "orient3d" && h != "bounding" && h != "scene") harnesses.insert(h);
    }
    same(fuzzers, harnesses, "the catalog's fuzzers", "fuzz/CMakeLists.txt");
    for (const auto& h : harnesses) CHECK(fs::exists(root / "fuzz" / (h + ".cpp")));

    std::printf("[cases] catalog: %ld families (%zu yes/no pairs), %ld bodies of the library's shapes, %ld without a family; %zu tables, "
                "%zu engines, %zu tests, %zu fuzzers\n",
                families, names.size(), bodies, unlisted, tables.size(), engine_files.size(), tests.size(), fuzzers.size());
    CHECK(unlisted == 0);
}

namespace {
// One family's clear-cut cases. Not inlined: the fold over the families stays a list of calls
// (inlined, every family's loop made one function that took most of this file's compile time).
template <class F>
[[gnu::noinline]] void check_alternatives(const F& f, unsigned index, long& checked, long& wrong) {
    using A = typename F::first_type;
    using B = typename F::second_type;
    audit::rng r(audit::stream(support::seed(), index, 0, 0));
    for (long i = 0; i < support::cases(2000); ++i) {
        // separation level 0: moved by the objects' size from touching, at scale 1, no offset
        const auto [a, b] = audit::make_case<A, B>(r, 0, audit::settings[0]);
        const bool e = intersects(a, b);
        if (classify(a, b) == certainty::uncertain) continue; // only clear-cut cases
        ++checked;
        if (catalog::signs_in_double(a, b) != e) ++wrong;
        for (const auto& alt : f.alternatives)
            if (alt.test(a, b) != e && !(alt.keeps_misses && !e)) ++wrong, std::printf("  %s %s disagrees\n", f.name, alt.name);
    }
}
} // namespace

TEST_CASE("catalog: alternatives agree with the exact tier away from the boundary", "[catalog]") {
    long checked = 0, wrong = 0;
    unsigned index = 0;
    catalog::for_each_family([&](const auto& f) { check_alternatives(f, index++, checked, wrong); });
    std::printf("[cases] catalog alternatives: %ld clear-cut cases, %ld disagreements\n", checked, wrong);
    CHECK(checked > 1000);
    CHECK(wrong == 0);
}

} // namespace test_query_catalog
