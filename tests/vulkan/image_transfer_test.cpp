// One mip read back alone, and texels written over an image one by one: what a bake uses to
// take lights out of its source without moving the whole chain through the host.
#include "image_transfer.hpp"
#include "vulkan_error.hpp"
#include "vulkan_test_support.hpp"

namespace iblkit::vulkan {
namespace {

class ImageTransfer : public testing::VulkanTest {
protected:
    // A cube of 8² with its mips, each value distinct and exact in the format.
    Image patternCube(const char* format) {
        Image cube(context(), {"pattern", &texelFormatNamed(format), 8, 8, 6, 4, true, false});
        values_.resize(cube.valueCount());
        for (size_t i = 0; i < values_.size(); ++i) values_[i] = float(i % 2048) / 64.0f;
        cube.upload(context(), values_);
        return cube;
    }
    std::vector<float> values_;
};

TEST_F(ImageTransfer, EachMipReadBackAloneIsThatMipOfTheWholeReadback) {
    for (const char* format : {"R32G32B32A32_SFLOAT", "R16G16B16A16_SFLOAT", "R32G32_SFLOAT"}) {
        auto cube = patternCube(format);
        for (uint32_t mip = 0; mip < cube.desc().mips; ++mip) {
            const auto alone = downloadMip(context(), cube, mip);
            const auto begin = values_.begin() + std::ptrdiff_t(cube.valueOffset(mip, 0));
            const auto end = values_.begin() + std::ptrdiff_t(mip + 1 < cube.desc().mips ? cube.valueOffset(mip + 1, 0) : values_.size());
            EXPECT_EQ(alone, std::vector<float>(begin, end)) << format << " mip " << mip;
        }
    }
}

TEST_F(ImageTransfer, WrittenTexelsChangeAndNoOtherDoes) {
    auto cube = patternCube("R32G32B32A32_SFLOAT");
    // A texel on face 0, one at the far corner of face 5, and one of mip 1 left alone.
    const std::vector<TexelAt> where{{0, 0, 0}, {5, 7, 7}, {3, 2, 6}};
    const std::vector<float> written{1, 2, 3, 4, 5, 6, 7, 8, -1, -2, -3, -4};
    writeTexels(context(), cube, 0, where, written);
    auto expected = values_;
    for (size_t i = 0; i < where.size(); ++i) {
        const size_t at = cube.valueOffset(0, where[i].layer) + (size_t(where[i].row) * 8 + where[i].column) * 4;
        std::copy_n(written.begin() + std::ptrdiff_t(4 * i), 4, expected.begin() + std::ptrdiff_t(at));
    }
    EXPECT_EQ(cube.download(context()), expected);
}

TEST_F(ImageTransfer, TexelsOutsideTheMipOrValuesOfTheWrongCountAreRefused) {
    auto cube = patternCube("R32G32B32A32_SFLOAT");
    const std::vector<float> one{1, 2, 3, 4};
    const std::vector<TexelAt> outside{{0, 4, 0}}; // mip 1 is 4² across
    EXPECT_THROW(writeTexels(context(), cube, 1, outside, one), VulkanError);
    const std::vector<TexelAt> badLayer{{6, 0, 0}};
    EXPECT_THROW(writeTexels(context(), cube, 0, badLayer, one), VulkanError);
    const std::vector<TexelAt> inside{{0, 0, 0}};
    EXPECT_THROW(writeTexels(context(), cube, 0, inside, std::vector<float>{1, 2, 3}), VulkanError);
    EXPECT_THROW(downloadMip(context(), cube, 4), VulkanError);
    EXPECT_EQ(cube.download(context()), values_); // nothing written by a refused call
}

} // namespace
} // namespace iblkit::vulkan
