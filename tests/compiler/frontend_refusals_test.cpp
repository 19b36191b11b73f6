// glslang's errors reach the user in the kit's words first, glslang's own kept after them.
#include "frontend_refusals.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

TEST(FrontendRefusals, NameTheConstructAndKeepGlslangsMessage) {
    EXPECT_EQ(inKitWords("a.hlsl:3:5: error: 'return' : type does not match, or is not convertible to, the function's return type"),
              "a.hlsl:3:5: error: a return value glslang's HLSL frontend does not convert to the function's return type (a "
              "32-bit value to a 16-bit one, a struct to another struct): convert it, as in return (half3)value; (glslang: "
              "'return' : type does not match, or is not convertible to, the function's return type)");
    const auto method = inKitWords("a.hlsl:9:1: error: '__BI_SampleLevel' : no matching overloaded function found");
    EXPECT_EQ(method.rfind("a.hlsl:9:1: error: a call to the method 'SampleLevel' whose arguments match none", 0), 0u) << method;
}

TEST(FrontendRefusals, KeepTheIncludeChainAndWordAnUnknownMessage) {
    EXPECT_EQ(inKitWords("In file included from a.hlsl:2:\nb.hlsli:4:1: error: 'frobnicate' : something new"),
              "In file included from a.hlsl:2:\nb.hlsli:4:1: error: code glslang's HLSL frontend refuses (glslang: "
              "'frobnicate' : something new)");
    EXPECT_EQ(inKitWords("not a diagnostic"), "not a diagnostic");
}

TEST(FrontendRefusals, InvalidSpirvNamesTheConstructThatMadeIt) {
    EXPECT_EQ(invalidSpirvInKitWords("a.hlsl: error: the SPIR-V is not valid for Vulkan 1.1: Invalid storage class for pointer operand 'x'"),
              "a.hlsl: error: a buffer passed to a function glslang could not inline: index the global buffer inside the "
              "function (the SPIR-V is not valid for Vulkan 1.1: Invalid storage class for pointer operand 'x')");
    EXPECT_EQ(invalidSpirvInKitWords("a.hlsl: error: the SPIR-V is not valid for Vulkan 1.1: something new"),
              "a.hlsl: error: glslang wrote SPIR-V for this shader that Vulkan does not accept (the SPIR-V is not valid for "
              "Vulkan 1.1: something new)");
    const std::string worded = "a.hlsl: error: an integer matrix (uint4x4, int3x3, ...) has no SPIR-V type for Vulkan";
    EXPECT_EQ(invalidSpirvInKitWords(worded), worded);
}

} // namespace
} // namespace iblkit::compiler
