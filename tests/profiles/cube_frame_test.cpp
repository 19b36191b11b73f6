// A profile's cube frame: every texel of the arranged cube holds the kit's texel of the direction
// the frame names, found by direction alone (the reference's texel centres), at every mip.
#include "profiles/cube_frame.hpp"
#include "reference/reference_irradiance.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace iblkit::profiles {
namespace {

constexpr uint32_t kChannels = 2;

// Each texel holds its own (face, column, row) and its mip: a cube whose every texel is unique.
std::vector<float> labelledChain(uint32_t size, uint32_t mips) {
    std::vector<float> values;
    for (uint32_t mip = 0; mip < mips; ++mip) {
        const uint32_t levelSize = size >> mip;
        for (uint32_t face = 0; face < 6; ++face)
            for (uint32_t row = 0; row < levelSize; ++row)
                for (uint32_t column = 0; column < levelSize; ++column) {
                    values.push_back(float(mip * 1000 + face * 100 + row * 10 + column));
                    values.push_back(float(mip));
                }
    }
    return values;
}

// The label of the texel of a `size` cube whose centre is nearest `direction`.
float labelNearest(const glm::dvec3& direction, uint32_t size, uint32_t mip) {
    double best = -2;
    float label = -1;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column)
                if (const double d = glm::dot(reference::cubeTexelCentre(face, column, row, size), direction); d > best) {
                    best = d;
                    label = float(mip * 1000 + face * 100 + row * 10 + column);
                }
    return label;
}

class MirroredFrame : public testing::TestWithParam<CubeFrame> {};

TEST_P(MirroredFrame, HoldsAtEachDirectionTheKitsTexelOfTheMirroredDirection) {
    const uint32_t size = 4, mips = 3;
    auto values = labelledChain(size, mips);
    arrangeCube(GetParam(), values, size, mips, kChannels);
    size_t index = 0;
    for (uint32_t mip = 0; mip < mips; ++mip) {
        const uint32_t levelSize = size >> mip;
        for (uint32_t face = 0; face < 6; ++face)
            for (uint32_t row = 0; row < levelSize; ++row)
                for (uint32_t column = 0; column < levelSize; ++column, index += kChannels) {
                    const auto file = reference::cubeTexelCentre(face, column, row, levelSize);
                    EXPECT_EQ(values[index], labelNearest(kitDirectionOf(GetParam(), file), levelSize, mip))
                        << "mip " << mip << " face " << face << " row " << row << " column " << column;
                    EXPECT_EQ(values[index + 1], float(mip));
                }
    }
}

TEST_P(MirroredFrame, MirroringTwiceRestoresTheCube) {
    const auto original = labelledChain(8, 4);
    auto values = original;
    arrangeCube(GetParam(), values, 8, 4, kChannels);
    EXPECT_NE(values, original);
    arrangeCube(GetParam(), values, 8, 4, kChannels);
    EXPECT_EQ(values, original);
}

INSTANTIATE_TEST_SUITE_P(CubeFrame, MirroredFrame, testing::Values(CubeFrame::MirroredX, CubeFrame::MirroredZ));

TEST(CubeFrame, TheKitsFrameChangesNothing) {
    const auto original = labelledChain(8, 4);
    auto values = original;
    arrangeCube(CubeFrame::Kit, values, 8, 4, kChannels);
    EXPECT_EQ(values, original);
}

TEST(CubeFrame, AChainLongerThanItsTexelsIsRefused) {
    auto values = labelledChain(4, 2);
    EXPECT_THROW(arrangeCube(CubeFrame::MirroredX, values, 4, 3, kChannels), std::invalid_argument);
}

} // namespace
} // namespace iblkit::profiles
