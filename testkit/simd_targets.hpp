// The batches' tests on every SIMD target: Highway lets a test choose the target its dispatch uses,
// so each target this processor has runs the same cases. Include after `import incidence;`.
#pragma once
#include <hwy/targets.h>
#include <cstdint>
#include <string>
#include "testing.hpp"

namespace support {

// each(r, where, target) on every target this processor has and Highway generated, each with a
// fresh rng of the tests' seed (so every target sees the same cases) and where = "<name> on
// <target>"; then the dispatch is restored. The number of targets.
template <class Each>
int on_every_target(const std::string& name, const Each& each) {
    int targets = 0;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        ++targets;
        rng r(seed());
        each(r, name + " on " + hwy::TargetName(target), hwy::TargetName(target));
    }
    hwy::SetSupportedTargetsForTest(0);
    return targets;
}

} // namespace support
