// incidence.catalog: every family names an existing modules/query/<name>.cppm with a test file
// tests/query/<name>.cpp, names are unique, and the canonical pair has a kernel body; each
// family's textbook alternatives and signs_in_double agree with the exact tier on clear-cut
// cases (far apart / deep inside), where no floating-point method may err.
#include <catch2/catch_test_macros.hpp>
#include <filesystem>
#include <set>
#include <tuple>
#include <string>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/generators.hpp"

namespace test_query_catalog { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("catalog: one family per query file, each with a test file", "[catalog]") {
    const std::filesystem::path root(INCIDENCE_SOURCE_DIR);
    std::set<std::string> names;
    catalog::for_each_listed_family([&](const auto& f) {
        INFO(f.name);
        CHECK(names.insert(f.name).second);
        CHECK(std::filesystem::exists(root / "modules/query" / (std::string(f.name) + ".cppm")));
        CHECK(std::filesystem::exists(root / "tests/query" / (std::string(f.name) + ".cpp")));
        using F = std::decay_t<decltype(f)>;
        STATIC_REQUIRE(canonical_pair<typename F::first_type, typename F::second_type>);
    });
    CHECK(names.size() == catalog::family_count + std::tuple_size_v<decltype(catalog::view_families)>);
    std::printf("[cases] catalog: %zu families\n", names.size());
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
            if (alt.test(a, b) != e) ++wrong, std::printf("  %s %s disagrees\n", f.name, alt.name);
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
