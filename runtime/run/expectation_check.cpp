#include "expectation_check.hpp"

#include "half_float.hpp"

#include <bit>
#include <cmath>
#include <cstring>

namespace iblkit::run {
namespace {

// Floats ordered as integers, so that adjacent floats differ by one.
int64_t orderedFloat(float value) {
    const auto bits = std::bit_cast<int32_t>(value);
    return bits < 0 ? int64_t(INT32_MIN) - bits : bits;
}

int64_t orderedHalf(float value) {
    const auto bits = std::bit_cast<int16_t>(numeric::toHalfBits(value));
    return bits < 0 ? int64_t(INT16_MIN) - bits : bits;
}

void consider(CheckResult& result, size_t index, double actual, double expected, bool ok,
              const vulkan::TexelFormat* format) {
    ++result.compared;
    if (!ok) {
        ++result.failed;
        result.passed = false;
    }
    const double error = std::isnan(actual) || std::isnan(expected) ? INFINITY : std::fabs(actual - expected);
    // The worst value: a failing one before any passing one, then the largest error.
    const bool fails = !ok;
    const bool takes = result.compared == 1 || (fails && !result.worstFails) ||
                       (fails == result.worstFails && error > result.worstAbsolute);
    if (takes) {
        result.worstFails = fails;
        result.worstIndex = index;
        result.worstAbsolute = error;
        result.worstUlp = format ? ulpDistance(*format, actual, expected) : 0;
        result.expected = expected;
        result.actual = actual;
    }
}

} // namespace

double ulpDistance(const vulkan::TexelFormat& format, double actual, double expected) {
    if (std::isnan(actual) || std::isnan(expected)) return INFINITY;
    switch (format.kind) {
    case vulkan::ComponentKind::Float:
        if (format.bytesPerChannel == 2) return double(std::llabs(orderedHalf(float(actual)) - orderedHalf(float(expected))));
        return double(std::llabs(orderedFloat(float(actual)) - orderedFloat(float(expected))));
    case vulkan::ComponentKind::UNorm: return std::fabs(std::round(actual * 255.0) - std::round(expected * 255.0));
    default: return std::fabs(actual - expected);
    }
}

CheckResult compareValues(std::span<const double> actual, std::span<const double> expected, const Tolerance& tolerance,
                          const vulkan::TexelFormat& format) {
    CheckResult result;
    for (size_t i = 0; i < actual.size(); ++i) {
        const double a = actual[i], e = expected[i];
        bool ok;
        if (std::isnan(e) || std::isnan(a)) {
            ok = std::isnan(e) && std::isnan(a);
        } else {
            const double error = std::fabs(a - e);
            ok = a == e || (tolerance.absolute && error <= *tolerance.absolute) ||
                 (tolerance.relative && error <= *tolerance.relative * std::fabs(e)) ||
                 (tolerance.ulp && ulpDistance(format, a, e) <= *tolerance.ulp);
        }
        consider(result, i, a, e, ok, &format);
    }
    return result;
}

CheckResult checkRange(std::span<const double> actual, double min, double max) {
    CheckResult result;
    result.minimum = INFINITY;
    result.maximum = -INFINITY;
    for (size_t i = 0; i < actual.size(); ++i) {
        const double a = actual[i];
        result.minimum = std::min(result.minimum, a);
        result.maximum = std::max(result.maximum, a);
        const bool ok = std::isfinite(a) && a >= min && a <= max;
        const double nearest = std::isfinite(a) ? std::clamp(a, min, max) : min;
        consider(result, i, a, nearest, ok, nullptr);
    }
    return result;
}

std::string describeTolerance(const Tolerance& tolerance) {
    if (tolerance.exact()) return "exactly";
    std::string text;
    const auto add = [&](const char* name, const std::optional<double>& value) {
        if (!value) return;
        char number[32];
        std::snprintf(number, sizeof number, "%g", *value);
        text += (text.empty() ? "within " : " or ") + std::string(name) + " " + number;
    };
    add("abs", tolerance.absolute);
    add("rel", tolerance.relative);
    add("ulp", tolerance.ulp);
    return text;
}

} // namespace iblkit::run
