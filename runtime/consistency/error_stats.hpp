#pragma once

#include <cstddef>
#include <span>

namespace iblkit::consistency {

// How far GPU values are from a reference: the largest absolute error, the largest distance in
// float32 units in the last place (against the reference rounded to float), the root mean
// square error, and how many GPU values are NaN or infinite.
struct ErrorStats {
    size_t nonFinite = 0;
    double maxAbsolute = 0;
    double maxUlp = 0;
    double rms = 0;
};

ErrorStats measureError(std::span<const float> actual, std::span<const float> reference);
ErrorStats measureError(std::span<const float> actual, std::span<const double> reference);

} // namespace iblkit::consistency
