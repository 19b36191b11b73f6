// The polynomial LUT: its committed coefficients are the fit's, and the fit is as close to the
// converged LUT as measured.
#include "converged_lut.hpp"
#include "lut_fit.hpp"
#include "read_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace iblkit::reference {
namespace {

TEST(LutFit, TheCommittedIncludeIsTheFitsOutput) {
    EXPECT_EQ(testing::readFile("hlsl/Common/BrdfLutFit.fxh"), brdfLutFitInclude())
        << "regenerate it: iblkit lut-fit -o hlsl/Common/BrdfLutFit.fxh";
}

// The largest error over a 64² LUT's texels, against the converged LUT, for each degree: measured
// 0.27, 0.18, 0.13, 0.088, 0.083, 0.043, 0.047, 0.028, 0.021 at degrees 1 to 9 (the grazing, low
// roughness corner, where G1(V) turns over N.V ~ roughness² / 2, dominates every degree; least
// squares lowers the RMS at every degree, the largest error not always). Bound: the measurement
// plus 10 %. Every value stays in [0, 1].
TEST(LutFit, EachDegreeIsAsCloseAsMeasured) {
    const uint32_t size = 64;
    const auto converged = convergedBrdfLut(size);
    const double measured[] = {0.268, 0.176, 0.126, 0.0883, 0.0832, 0.0432, 0.0468, 0.0281, 0.0206};
    const auto fits = fitBrdfLutEveryDegree();
    for (uint32_t degree = 1; degree <= kMaxLutFitDegree; ++degree) {
        const auto lut = brdfLutFromFit<double>(size, fits[degree - 1]);
        double largest = 0;
        for (size_t i = 0; i < lut.size(); ++i) largest = std::max(largest, std::abs(lut[i] - converged[i]));
        EXPECT_LT(largest, measured[degree - 1] * 1.1) << "degree " << degree;
        EXPECT_TRUE(std::all_of(lut.begin(), lut.end(), [](double v) { return v >= 0 && v <= 1; })) << degree;
    }
}

TEST(LutFit, RefusesDegreesItHasNoCoefficientsFor) {
    EXPECT_THROW(fitBrdfLut(0), std::invalid_argument);
    EXPECT_THROW(fitBrdfLut(kMaxLutFitDegree + 1), std::invalid_argument);
}

} // namespace
} // namespace iblkit::reference
