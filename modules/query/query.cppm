// incidence.query: the public front door, one partition per kind of query (docs/DESIGN.md,
// "Layout"): intersects and classify (yes/no), contains and covers, intersection (where a line
// meets a set), the squared distances, and the textbook methods kept for comparison. Each kind
// dispatches onto the kernel-generic bodies of incidence.detail (modules/query/<kind>/), whose
// tiers come from one driver (tiers.cppm).
export module incidence.query;
export import :tiers;
export import :intersects;
export import :contains;
export import :intersection;
export import :distance;
export import :methods;
