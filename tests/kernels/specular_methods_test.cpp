// What each prefilter method takes: sampled methods without a chunked twin and the sample table
// stop at the driver's loop limit, and say so.
#include "kernels/specular_method.hpp"

#include "vulkan_test_support.hpp"

#include <stdexcept>

namespace iblkit::kernels {
namespace {

TEST(SpecularMethods, KindsAndLimitsFollowTheKernelTable) {
    EXPECT_EQ(specularKindOf("document"), SpecularKind::Sampled);
    EXPECT_EQ(specularKindOf("filtered"), SpecularKind::Sampled);
    EXPECT_EQ(specularKindOf("table"), SpecularKind::Table);
    EXPECT_EQ(specularKindOf("pyramid"), SpecularKind::Pyramid);
    EXPECT_EQ(specularKindOf("mipchain"), SpecularKind::MipChain);
    EXPECT_EQ(specularKindOf("convolution"), SpecularKind::Convolution);
    EXPECT_THROW(specularKindOf("nope"), std::out_of_range);
    EXPECT_EQ(maxSamplesOf("document"), kMaxSamples) << "its chunked twin splits the loop";
    EXPECT_EQ(maxSamplesOf("filtered"), kLoopLimit);
    EXPECT_EQ(maxSamplesOf("table"), kLoopLimit);
    EXPECT_EQ(maxSamplesOf("pyramid"), 4u);
    EXPECT_EQ(specularMethods(),
              (std::vector<std::string>{"document", "filtered", "table", "pyramid", "mipchain", "convolution"}))
        << "each method once, though the ring serves two";
}

class SpecularMethodLimits : public iblkit::testing::VulkanTest {};

TEST_F(SpecularMethodLimits, CountsPastTheLoopLimitAreRefusedByName) {
    try {
        SpecularMethod method(context(), "filtered", kLoopLimit + 1);
        ADD_FAILURE() << "65536 filtered samples were accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("no chunked kernel"), std::string::npos) << error.what();
    }
    EXPECT_THROW(SpecularMethod(context(), "table", kLoopLimit + 1), std::invalid_argument);
    EXPECT_THROW(SpecularMethod(context(), "table", 0), std::invalid_argument);
    EXPECT_THROW(SpecularMethod(context(), "pyramid", 5), std::invalid_argument);
    EXPECT_THROW(SpecularMethod(context(), "pyramid", 0), std::invalid_argument);
}

} // namespace
} // namespace iblkit::kernels
