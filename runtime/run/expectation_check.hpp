#pragma once

#include "run_file.hpp"
#include "texel_format.hpp"

#include <functional>
#include <span>
#include <string>

namespace iblkit::run {

struct CheckResult {
    bool passed = true;
    size_t compared = 0;
    size_t failed = 0;
    size_t worstIndex = 0; // the value with the largest absolute error
    double worstAbsolute = 0;
    double worstUlp = 0;
    double expected = 0, actual = 0;
    bool worstFails = false;
    double minimum = 0, maximum = 0; // range checks: what was seen
};

// Distance in units in the last place of the format's components (half, float, 8-bit unorm,
// integers), so a ULP tolerance means the same thing for every format.
double ulpDistance(const vulkan::TexelFormat& format, double actual, double expected);

// A value passes when it equals the expected one, or is within any tolerance given (abs,
// rel, ulp); NaN passes only against NaN. An empty tolerance means exact.
CheckResult compareValues(std::span<const double> actual, std::span<const double> expected, const Tolerance& tolerance,
                          const vulkan::TexelFormat& format);

// Every value within [min, max]; NaN and infinities fail.
CheckResult checkRange(std::span<const double> actual, double min, double max);

std::string describeTolerance(const Tolerance& tolerance);

} // namespace iblkit::run
