// The audit's stability and tradeoff runs, part 2 of 4 of incidence::catalog's families (families.hpp).
#include "testkit/oracle/cgal_oracle.hpp"
#include <string>
#include <vector>
import incidence;
#include "testkit/generators.hpp"
#include "testkit/json.hpp"
#include "testkit/methods.hpp"
#include "families.hpp"

template void audit_run::stability_part<1>(audit::json&, const options&, long&);
template void audit_run::tradeoff_part<1>(audit::json&, const options&);
