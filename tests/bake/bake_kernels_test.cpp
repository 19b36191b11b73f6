// BakeKernels: the kernels the settings name, made on worker threads under the validation layer,
// and a worker's error surfacing where its kernels are asked for.
#include "bake_kernels.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

namespace iblkit::bake {
namespace {

vulkan::ContextOptions validated(std::shared_ptr<vulkan::ValidationLog> log) {
    vulkan::ContextOptions options;
    options.validation = true;
    options.validationLog = std::move(log);
    return options;
}

TEST(BakeKernels, MakesTheMethodsTheSettingsNameCleanly) {
    // 131072 samples split past llvmpipe's loop limit: a chunked method is the document's at that
    // count, where the convolution and the quadrature grid dispatch once.
    auto log = std::make_shared<vulkan::ValidationLog>();
    {
        const vulkan::VulkanContext context(validated(log));
        BakeSettings chunked;
        chunked.specularMethod = chunked.lutMethod = "document";
        chunked.samples = chunked.lutSamples = 131072;
        BakeKernels documents(context, resolveSettings(chunked));
        EXPECT_GT(documents.specular()->chunkSamples(), 0u);
        EXPECT_GT(documents.lut()->chunkSamples(), 0u);
        BakeKernels defaults(context, resolveSettings(BakeSettings{}));
        EXPECT_EQ(defaults.specular()->chunkSamples(), 0u);
        EXPECT_EQ(defaults.lut()->chunkSamples(), 0u);
        EXPECT_NO_THROW(defaults.irradiance());
        EXPECT_NO_THROW(defaults.preview());
        BakeKernels unlitScene(context, resolveSettings(BakeSettings{}), NeededOutputs{false, false, false});
        EXPECT_EQ(unlitScene.specular(), nullptr) << "no lit material: no prefilter compiled";
        EXPECT_EQ(unlitScene.lut(), nullptr);
        EXPECT_NO_THROW(unlitScene.preview());
    }
    for (const auto& message : log->messages()) ADD_FAILURE() << "validation: " << message;
}

TEST(BakeKernels, AWorkersErrorSurfacesWhereItsKernelsAreAskedFor) {
    const vulkan::VulkanContext context;
    auto settings = resolveSettings(BakeSettings{}); // the quadrature grid
    settings.lutSampleCount = 2;                      // below its 4 nodes per side, past what resolveSettings lets through
    BakeKernels kernels(context, settings);
    EXPECT_NO_THROW(kernels.specular());
    EXPECT_THROW(kernels.lut(), std::invalid_argument);
}

} // namespace
} // namespace iblkit::bake
