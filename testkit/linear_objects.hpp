// A ray, a line or a segment as the value oracle takes it (oracle::linear_object,
// testkit/oracle/cgal_oracle.hpp): for the value test and the values fuzzer. Include after
// `import incidence;`.
#pragma once
#include "testkit/oracle/cgal_oracle.hpp"

namespace support {
inline oracle::linear_object object_of(const incidence::ray3& r) {
    return {oracle::linear_object::ray, {r.origin.x, r.origin.y, r.origin.z}, {r.direction.x, r.direction.y, r.direction.z}};
}
inline oracle::linear_object object_of(const incidence::line3& l) {
    return {oracle::linear_object::line, {l.origin.x, l.origin.y, l.origin.z}, {l.direction.x, l.direction.y, l.direction.z}};
}
inline oracle::linear_object object_of(const incidence::segment3& s) {
    return {oracle::linear_object::segment, {s.a.x, s.a.y, s.a.z}, {s.b.x, s.b.y, s.b.z}};
}
} // namespace support
