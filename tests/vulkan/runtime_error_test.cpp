// Each misuse is a VulkanError naming the problem — never a crash or a validation error.
#include "block_writer.hpp"
#include "compute_program.hpp"
#include "vulkan_error.hpp"
#include "vulkan_test_support.hpp"

#include "shader_manifest.hpp"

#include <cstring>
#ifdef __SANITIZE_ADDRESS__
#include <sanitizer/lsan_interface.h>
#endif

namespace iblkit::vulkan {
namespace {

class RuntimeErrors : public testing::VulkanTest {
protected:
    ComputeProgram lutProgram() {
        auto options = compiler::manifestShaderOptions("hlsl/shaders.json", "PrecomputedBrdfCS");
        options.defines["SAMPLE_COUNT"] = "1";
        lut_ = compiler::compileShader(options);
        return ComputeProgram(context(), lut_.spirv, lut_.reflection);
    }
    Image lutImage(const char* format, bool storage = true) {
        return Image(context(), {"Precomputed", &texelFormatNamed(format), 16, 16, 1, 1, false, storage});
    }

    template <typename F>
    static void expectError(F&& action, const std::string& expected) {
        try {
            action();
            ADD_FAILURE() << "no error; expected: " << expected;
        } catch (const VulkanError& error) {
            EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
        }
    }

    compiler::CompiledShader lut_;
};

TEST_F(RuntimeErrors, BindingANameTheShaderLacks) {
    auto program = lutProgram();
    auto image = lutImage("R16G16_SFLOAT");
    expectError([&] { program.bind("Precomputd", image); }, "the shader has no resource 'Precomputd' (it has: Precomputed)");
}

TEST_F(RuntimeErrors, DispatchingWithAResourceUnbound) {
    auto program = lutProgram();
    expectError([&] { program.dispatchThreads(context(), {16, 16, 1}); }, "not bound: Precomputed");
}

TEST_F(RuntimeErrors, AStorageImageOfTheWrongFormat) {
    auto program = lutProgram();
    auto image = lutImage("R32G32_SFLOAT");
    expectError([&] { program.bind("Precomputed", image); },
                "wrong format: the shader declares R16G16_SFLOAT, the image is R32G32_SFLOAT");
}

TEST_F(RuntimeErrors, AnImageNotMadeForStorage) {
    auto program = lutProgram();
    auto image = lutImage("R16G16_SFLOAT", false);
    expectError([&] { program.bind("Precomputed", image); }, "the image was not made for storage");
}

TEST_F(RuntimeErrors, ABufferWhereTheShaderWantsAnImage) {
    auto program = lutProgram();
    Buffer buffer(context(), 64, vk::BufferUsageFlagBits::eStorageBuffer, "x");
    expectError([&] { program.bind("Precomputed", buffer); }, "'Precomputed' is a storage_image, not a buffer");
}

TEST_F(RuntimeErrors, ADispatchOfZeroSize) {
    auto program = lutProgram();
    auto image = lutImage("R16G16_SFLOAT");
    program.bind("Precomputed", image);
    expectError([&] { program.dispatchThreads(context(), {16, 0, 1}); }, "dispatch of zero size: 16x0x1 threads");
    expectError([&] { program.dispatchGroups(context(), {0, 1, 1}); }, "dispatch of zero size: 0x1x1 groups");
}

TEST_F(RuntimeErrors, AnAllocationThatCannotFit) {
    const vk::DeviceSize tooBig = context().largestHeapSize() + (vk::DeviceSize(1) << 20);
    expectError([&] { Buffer(context(), tooBig, vk::BufferUsageFlagBits::eStorageBuffer, "huge"); },
                "cannot allocate " + std::to_string(tooBig) + " bytes for buffer 'huge'");
}

TEST_F(RuntimeErrors, AnImageBeyondTheDeviceLimit) {
    const uint32_t limit = context().physicalDevice().getProperties().limits.maxImageDimension2D;
    expectError([&] { Image(context(), {"wide", &texelFormatNamed("R32_SFLOAT"), limit + 1, 1, 1, 1, false, false}); },
                "exceeds the device's limit of " + std::to_string(limit));
}

TEST_F(RuntimeErrors, AnUnknownFormat) {
    expectError([] { texelFormatNamed("R11G11B10_UFLOAT"); }, "unsupported format 'R11G11B10_UFLOAT' (supported: R32_SFLOAT");
}

TEST_F(RuntimeErrors, CbufferMembersByName) {
    const std::vector<compiler::BlockMember> members = {{"Roughness", "float", 0, 4}, {"Tint", "float3", 16, 12}};
    expectError([&] { packBlock("Params", members, 32, {{"Rougness", {1.0}}}); },
                "Params has no member 'Rougness' (members: Roughness, Tint)");
    expectError([&] { packBlock("Params", members, 32, {{"Tint", {1.0, 2.0}}}); }, "it takes 3 value(s), not 2");
    const auto bytes = packBlock("Params", members, 32, {{"Tint", {1.0, 2.0, 3.0}}});
    float tint[3];
    std::memcpy(tint, bytes.data() + 16, 12);
    EXPECT_EQ(tint[1], 2.0f);
}

// A uint of -1 or 1e20 was cast (undefined behaviour, in practice wrapped); each is refused.
TEST_F(RuntimeErrors, CbufferValuesTheMembersTypeCannotHoldAreRefused) {
    const std::vector<compiler::BlockMember> members = {
        {"Count", "uint", 0, 4}, {"Offset", "int", 4, 4}, {"Scale", "float", 8, 4}};
    expectError([&] { packBlock("Params", members, 16, {{"Count", {-1.0}}}); }, "Params.Count is a uint: -1 is beyond uint's range");
    expectError([&] { packBlock("Params", members, 16, {{"Count", {1e20}}}); }, "Params.Count is a uint: 1e+20 is beyond uint's range");
    expectError([&] { packBlock("Params", members, 16, {{"Count", {2.5}}}); }, "Params.Count is a uint: 2.5 is not a whole number");
    expectError([&] { packBlock("Params", members, 16, {{"Offset", {3e9}}}); }, "Params.Offset is a int: 3e+09 is beyond int's range");
    expectError([&] { packBlock("Params", members, 16, {{"Scale", {1e39}}}); }, "Params.Scale is a float: 1e+39 is beyond float's range");
    const auto bytes = packBlock("Params", members, 16, {{"Count", {4294967295.0}}, {"Offset", {-2147483648.0}}});
    uint32_t count;
    int32_t offset;
    std::memcpy(&count, bytes.data(), 4);
    std::memcpy(&offset, bytes.data() + 4, 4);
    EXPECT_EQ(count, 4294967295u);
    EXPECT_EQ(offset, -2147483647 - 1);
}

#ifdef __SANITIZE_ADDRESS__
// The next test leaks a driver object on purpose; LeakSanitizer builds must not count the
// driver's allocation for it (every other test is leak-checked as usual).
struct DeliberateLeak {
    DeliberateLeak() { __lsan_disable(); }
    ~DeliberateLeak() { __lsan_enable(); }
};
#else
struct DeliberateLeak {};
#endif

// The guard the other tests rely on: an object left alive is reported when the device goes.
TEST(ValidationLayer, ReportsAnObjectLeftAlive) {
    auto log = std::make_shared<ValidationLog>();
    {
        VulkanContext context({"", true, log});
        const vk::BufferCreateInfo info({}, 64, vk::BufferUsageFlagBits::eStorageBuffer);
        VkBuffer leaked = VK_NULL_HANDLE;
        [[maybe_unused]] const DeliberateLeak deliberate;
        ASSERT_EQ(context.device().getDispatcher()->vkCreateBuffer(*context.device(),
                                                                    reinterpret_cast<const VkBufferCreateInfo*>(&info),
                                                                    nullptr, &leaked),
                  VK_SUCCESS);
    }
    const auto messages = log->messages();
    ASSERT_FALSE(messages.empty());
    EXPECT_NE(messages.front().find("VkBuffer"), std::string::npos) << messages.front();
}

} // namespace
} // namespace iblkit::vulkan
