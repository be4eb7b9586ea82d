// incidence-pair-table: writes the README's table of pairs from the code and the tests. Each row
// comes from incidence.catalog (the pair, what its approximate tier runs, its alternatives, its
// fuzzer) and from the leading comment of tests/query/<pair>.cpp (what the oracle test checks).
//   incidence-pair-table SOURCE_DIR            print the table
//   incidence-pair-table SOURCE_DIR --check    exit 1 if README.md's table differs (ctest)
//   incidence-pair-table SOURCE_DIR --write    replace README.md's table
// The table sits between the lines "<!-- pair table: generated -->" and "<!-- end of pair table -->".
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
import incidence;

using namespace incidence;

namespace {
std::string read(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}
// The file's leading // comment, joined into one line.
std::string leading_comment(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::string line, out;
    while (std::getline(in, line) && line.rfind("//", 0) == 0) {
        std::string t = line.substr(2);
        if (!t.empty() && t[0] == ' ') t.erase(0, 1);
        out += (out.empty() ? "" : " ") + t;
    }
    for (char& c : out)
        if (c == '|') c = '/';
    return out;
}
// One row. Not a template and not inlined: the fold over the families below stays a list of
// calls (inlined, the string work of every family made one function that took most of the
// compile time).
[[gnu::noinline]] std::string row(const std::filesystem::path& root, const std::string& name, const char* approximate,
                                  const std::vector<std::string>& alternatives, const char* fuzzer) {
    std::string alts;
    for (const auto& a : alternatives) alts += (alts.empty() ? "`" : ", `") + name + "_" + a + "`";
    return "| `" + name + "` | exact, conservative, aggressive, approximate; `classify` | " + approximate + " | " +
           (alts.empty() ? std::string("-") : alts) + " | " + leading_comment(root / "tests/query" / (name + ".cpp")) +
           " | `" + fuzzer + "` |\n";
}
std::string table(const std::filesystem::path& root) {
    std::string t = "| pair (`modules/query/`) | tiers | approximate tier runs | alternatives (`method::`) | exact-tier oracle "
                    "test (`tests/query/<pair>.cpp`) | fuzzer (`fuzz/`) |\n|---|---|---|---|---|---|\n";
    catalog::for_each_listed_family([&](const auto& f) {
        std::vector<std::string> alts;
        for (const auto& a : f.alternatives) alts.emplace_back(a.name);
        t += row(root, f.name, f.approximate_method, alts, f.fuzzer);
    });
    return t;
}
constexpr const char* begin_mark = "<!-- pair table: generated -->\n";
constexpr const char* end_mark = "<!-- end of pair table -->\n";
} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: incidence-pair-table SOURCE_DIR [--check | --write]\n");
        return 2;
    }
    const std::filesystem::path root(argv[1]);
    const std::string mode = argc > 2 ? argv[2] : "";
    const std::string t = table(root);
    if (mode.empty()) {
        std::fputs(t.c_str(), stdout);
        return 0;
    }
    const std::filesystem::path readme = root / "README.md";
    std::string r = read(readme);
    const auto b = r.find(begin_mark), e = r.find(end_mark);
    if (b == std::string::npos || e == std::string::npos || e < b) {
        std::fprintf(stderr, "README.md has no generated pair table (markers missing)\n");
        return 1;
    }
    const auto from = b + std::string(begin_mark).size();
    if (mode == "--check") {
        if (r.substr(from, e - from) == t) return 0;
        std::fprintf(stderr, "README.md's pair table is stale; regenerate it with: incidence-pair-table %s --write\nexpected:\n%s",
                     argv[1], t.c_str());
        return 1;
    }
    if (mode == "--write") {
        r.replace(from, e - from, t);
        std::ofstream(readme) << r;
        return 0;
    }
    std::fprintf(stderr, "unknown mode %s\n", mode.c_str());
    return 2;
}
