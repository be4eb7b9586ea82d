// incidence.arith: error-free transforms, expansions, the semi-static filter, the exact
// dyadic fallback, and the kernels that evaluate one generic predicate in every tier.
export module incidence.arith;
export import :eft;
export import :expansion;
export import :filtered;
export import :filtered_dd;
export import :dyadic;
export import :kernel;
export import :rounding;
export import :value;
