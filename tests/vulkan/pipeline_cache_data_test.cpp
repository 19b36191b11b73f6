// The pipeline cache's data: what a device gives is taken back by the next context on it and
// pipelines are made after it; data whose header names another device, driver build or version,
// or that is cut short, never reaches the driver.
#include "buffer.hpp"
#include "compute_program.hpp"
#include "vulkan_test_support.hpp"

#include <cstring>

namespace iblkit::vulkan {
namespace {

class PipelineCacheData : public testing::VulkanTest {
protected:
    // Makes a pipeline on `context`, runs it, and checks what it wrote.
    static void runAPipeline(const VulkanContext& context) {
        const auto shader = testing::compileTestShader("fill", R"(
RWStructuredBuffer<uint> Values;
[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { Values[id.x] = id.x * 3 + 1; }
)");
        Buffer values(context, 4 * 4, vk::BufferUsageFlagBits::eStorageBuffer, "Values");
        ComputeProgram program(context, shader.spirv, shader.reflection);
        program.bind("Values", values);
        program.dispatchGroups(context, {1, 1, 1});
        const auto bytes = values.read();
        uint32_t read[4];
        std::memcpy(read, bytes.data(), sizeof read);
        EXPECT_EQ(read[3], 10u);
    }
    std::vector<std::byte> dataAfterAPipeline() const {
        runAPipeline(context());
        return context().pipelineCacheData();
    }
};

TEST_F(PipelineCacheData, TheNextContextTakesItBackAndMakesPipelines) {
    const auto data = dataAfterAPipeline();
    ASSERT_GE(data.size(), 32u) << "the header alone is 32 bytes";
    const VulkanContext next;
    EXPECT_TRUE(next.addPipelineCacheData(data));
    runAPipeline(next);
}

TEST_F(PipelineCacheData, DataForAnotherDeviceOrDriverIsRefused) {
    const auto data = dataAfterAPipeline();
    const auto changed = [&data](size_t offset, std::byte value) {
        auto copy = data;
        copy.at(offset) = value;
        return copy;
    };
    EXPECT_FALSE(context().addPipelineCacheData(changed(4, std::byte{2}))) << "header version 2";
    EXPECT_FALSE(context().addPipelineCacheData(changed(8, data[8] ^ std::byte{1}))) << "another vendor";
    EXPECT_FALSE(context().addPipelineCacheData(changed(12, data[12] ^ std::byte{1}))) << "another device";
    EXPECT_FALSE(context().addPipelineCacheData(changed(31, data[31] ^ std::byte{1}))) << "another driver build";
    EXPECT_FALSE(context().addPipelineCacheData(changed(0, std::byte{0xff}))) << "a header longer than the data";
    EXPECT_FALSE(context().addPipelineCacheData(std::span(data).first(31))) << "cut short";
    EXPECT_FALSE(context().addPipelineCacheData({}));
    EXPECT_TRUE(context().addPipelineCacheData(data));
}

TEST_F(PipelineCacheData, TheIdentityNamesVendorDeviceAndUuid) {
    const auto identity = context().pipelineCacheIdentity();
    ASSERT_EQ(identity.size(), 8u + 1 + 8 + 1 + 32);
    EXPECT_EQ(identity[8], '-');
    EXPECT_EQ(identity.find_first_not_of("0123456789abcdef-"), std::string::npos);
}

} // namespace
} // namespace iblkit::vulkan
