// incidence.core: points and vectors, signs and tiers, errors and results.
export module incidence.core;
export import :vec;
export import :tier;
export import :error;
export import :hits;
