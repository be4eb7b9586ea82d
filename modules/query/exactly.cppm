// The exact tier's re-run of a pair's body, out of line and compiled once in the library
// (docs/DESIGN.md, "Tiers"). The tier driver (query/tiers.cppm) calls exactly<Body, R>(a, b) where
// the filter left a sign open; each pair table lists the pairs it compiles once with `extern template`
// lines, from which CMakeLists.txt generates the definitions (generated/exact/, one file per table). The
// definition is in detail.cppm, where every body is visible. [[gnu::noinline]] is what makes the
// list pay at -O1 and above too: an optimising compiler instantiates an inline extern template
// (constexpr functions are inline) in every program all the same, to inline it; a noinline one it
// leaves to the library.
export module incidence.detail:exactly;

export namespace incidence::detail {

// The bodies the tiers run: Body{}(k, a, b) calls the pair's kernel-generic function of that name.
struct intersects_body;
struct contains_body;
struct intersection_body;
struct nearest_body;
struct farthest_body;
struct signed_body;
struct euclidean_body;

// Body{}(exact kernel, a, b) as an R; R{} where the exact kernel met an input it cannot represent.
template <class Body, class R, class A, class B>
[[nodiscard, gnu::noinline]] constexpr R exactly(const A& a, const B& b);

} // namespace incidence::detail
