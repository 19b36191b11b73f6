#pragma once

#include <string>
#include <vector>

namespace iblkit::stress {

// What the bake's loader does with an input no kernel should see.
struct InputRow {
    std::string input;
    std::string policy;   // "default", "--strict", "--sanitize"
    std::string outcome;  // the one-line error, or what was changed
    bool refused = false;
    bool expectedRefusal = false;
    bool passed() const { return refused == expectedRefusal; }
};

// 64x32 EXR panoramas of radiance 1 with one texel of 1e37, NaN, +Inf or -Inf, or with negative
// texels, through bake::loadEnvironment under each policy.
std::vector<InputRow> checkInputPolicies();

} // namespace iblkit::stress
