// import incidence; brings every area. Each area can also be imported alone.
export module incidence;
export import incidence.core;
export import incidence.arith;
export import incidence.predicates;
export import incidence.shapes;
export import incidence.query;
export import incidence.catalog;
export import incidence.bound;
export import incidence.batch;
export import incidence.scene;
