#include "error_stats.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace iblkit::consistency {
namespace {

int64_t orderedFloat(float value) {
    const auto bits = std::bit_cast<int32_t>(value);
    return bits < 0 ? int64_t(INT32_MIN) - bits : bits;
}

template <typename Reference>
ErrorStats measure(std::span<const float> actual, std::span<const Reference> reference) {
    if (actual.size() != reference.size()) throw std::invalid_argument("measureError: sizes differ");
    ErrorStats stats;
    double squares = 0;
    for (size_t i = 0; i < actual.size(); ++i) {
        if (!std::isfinite(actual[i])) {
            ++stats.nonFinite;
            continue;
        }
        const double error = std::fabs(double(actual[i]) - double(reference[i]));
        squares += error * error;
        const double ulp = double(std::llabs(orderedFloat(actual[i]) - orderedFloat(float(reference[i]))));
        stats.maxUlp = std::max(stats.maxUlp, ulp);
        stats.maxAbsolute = std::max(stats.maxAbsolute, error);
    }
    stats.rms = actual.empty() ? 0 : std::sqrt(squares / double(actual.size()));
    return stats;
}

} // namespace

ErrorStats measureError(std::span<const float> actual, std::span<const float> reference) { return measure(actual, reference); }
ErrorStats measureError(std::span<const float> actual, std::span<const double> reference) { return measure(actual, reference); }

} // namespace iblkit::consistency
