// incidence.predicates: orientation and in-sphere predicates, exact and constexpr.
export module incidence.predicates;
export import :orient;
