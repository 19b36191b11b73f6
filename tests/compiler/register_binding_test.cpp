// The register -> set/binding rule: what docs/bindings.md promises users.
#include "compile_error.hpp"
#include "compiler.hpp"
#include "register_binding.hpp"
#include "temp_folder.hpp"

#include <gtest/gtest.h>

namespace iblkit::compiler {
namespace {

using RC = RegisterClass;

DeclaredResource implicit(std::string name, RC registerClass, uint32_t space = 0, uint32_t count = 1) {
    return {std::move(name), registerClass, std::nullopt, space, count};
}
DeclaredResource at(std::string name, RC registerClass, uint32_t index, uint32_t space = 0, uint32_t count = 1) {
    return {std::move(name), registerClass, index, space, count};
}

TEST(RegisterRule, BindingIsTheClassShiftPlusTheRegisterAndSetIsTheSpace) {
    const auto assigned = assignRegisters(
        {at("cb", RC::ConstantBuffer, 2), at("tex", RC::ShaderResource, 5, 1), at("smp", RC::Sampler, 1),
         at("uav", RC::UnorderedAccess, 3, 2)},
        BindingShifts{}, "x.hlsl");
    ASSERT_EQ(assigned.size(), 4u);
    EXPECT_EQ(assigned[0].binding, 2u);
    EXPECT_EQ(assigned[1].binding, 32u + 5u);
    EXPECT_EQ(assigned[1].set, 1u);
    EXPECT_EQ(assigned[2].binding, 64u + 1u);
    EXPECT_EQ(assigned[3].binding, 96u + 3u);
    EXPECT_EQ(assigned[3].set, 2u);
}

TEST(RegisterRule, ImplicitRegistersTakeTheLowestFreeOneOfTheirClassInDeclarationOrder) {
    const auto assigned =
        assignRegisters({implicit("a", RC::ShaderResource), at("b", RC::ShaderResource, 0),
                         implicit("c", RC::ShaderResource), implicit("d", RC::Sampler), implicit("e", RC::ShaderResource, 1)},
                        BindingShifts{}, "x.hlsl");
    EXPECT_EQ(assigned[0].registerName(), "t1") << "t0 is taken explicitly by b";
    EXPECT_EQ(assigned[2].registerName(), "t2");
    EXPECT_EQ(assigned[3].registerName(), "s0");
    EXPECT_EQ(assigned[4].registerName(), "t0") << "space1 has its own registers";
    EXPECT_FALSE(assigned[0].explicitRegister);
    EXPECT_TRUE(assigned[1].explicitRegister);
}

TEST(RegisterRule, AnArrayTakesConsecutiveRegisters) {
    const auto assigned = assignRegisters({implicit("textures", RC::ShaderResource, 0, 4), implicit("next", RC::ShaderResource)},
                                          BindingShifts{}, "x.hlsl");
    EXPECT_EQ(assigned[0].registerName(), "t0");
    EXPECT_EQ(assigned[1].registerName(), "t4");
}

TEST(RegisterRule, ARegisterUsedTwiceIsAnError) {
    EXPECT_THROW(assignRegisters({at("a", RC::UnorderedAccess, 1), at("b", RC::UnorderedAccess, 1)}, BindingShifts{}, "x.hlsl"),
                 CompileError);
    EXPECT_NO_THROW(assignRegisters({at("a", RC::UnorderedAccess, 1), at("b", RC::UnorderedAccess, 1, 1)}, BindingShifts{}, "x.hlsl"));
}

TEST(RegisterRule, ARegisterBeyondItsClassRangeIsAnErrorNotAClash) {
    // t32 would land on binding 64, which belongs to s0.
    try {
        assignRegisters({at("far", RC::ShaderResource, 32)}, BindingShifts{}, "x.hlsl");
        FAIL() << "expected CompileError";
    } catch (const CompileError& error) {
        EXPECT_NE(std::string(error.what()).find("'far' is in register t32"), std::string::npos) << error.what();
    }
    EXPECT_NO_THROW(assignRegisters({at("far", RC::UnorderedAccess, 1000)}, BindingShifts{}, "x.hlsl"))
        << "the class with the largest shift reaches up to glslang's largest binding";
}

// u=4294967295 put u1 on binding 0, b0's (the sum wrapped), and glslang itself holds bindings in
// 16 bits: past 65534 it answered only "resource binding failed". Both are refused by name.
TEST(RegisterRule, BindingsPastGlslangsLargestAreRefusedNotWrapped) {
    BindingShifts shifts;
    EXPECT_THROW(parseBindingShift("u=4294967295", shifts), CompileError);
    EXPECT_THROW(parseBindingShift("u=65535", shifts), CompileError);
    parseBindingShift("u=65534", shifts);
    EXPECT_NO_THROW(assignRegisters({at("last", RC::UnorderedAccess, 0)}, shifts, "x.hlsl"));
    try {
        assignRegisters({at("cb", RC::ConstantBuffer, 0), at("past", RC::UnorderedAccess, 1)}, shifts, "x.hlsl");
        FAIL() << "expected CompileError";
    } catch (const CompileError& error) {
        EXPECT_NE(std::string(error.what()).find("'past' is in register u1, but the u class holds only 1 registers under "
                                                 "the binding shifts; bindings end at 65534"),
                  std::string::npos)
            << error.what();
    }
    BindingShifts huge;
    huge.set(RC::UnorderedAccess, 4294967295u); // as a manifest could set it
    EXPECT_THROW(assignRegisters({at("wrapped", RC::UnorderedAccess, 1)}, huge, "x.hlsl"), CompileError);
}

TEST(RegisterRule, TwoClassesWithTheSameShiftAreAnError) {
    BindingShifts shifts;
    parseBindingShift("t=0", shifts);
    EXPECT_THROW(assignRegisters({at("cb", RC::ConstantBuffer, 0), at("tex", RC::ShaderResource, 0)}, shifts, "x.hlsl"),
                 CompileError);
}

TEST(RegisterRule, ShiftsAreParsedAndValidated) {
    BindingShifts shifts;
    parseBindingShift("t=200", shifts);
    EXPECT_EQ(shifts.of(RC::ShaderResource), 200u);
    EXPECT_EQ(shifts.capacity(RC::UnorderedAccess), 104u);
    EXPECT_THROW(parseBindingShift("x=1", shifts), CompileError);
    EXPECT_THROW(parseBindingShift("t=", shifts), CompileError);
    EXPECT_THROW(parseBindingShift("t=1a", shifts), CompileError);
}

// The rule end to end through glslang: the case glslang alone gets wrong (b0, t0, s0, u0 all
// on binding 0) and registers in spaces.
TEST(RegisterRule, GlslangOutputFollowsTheRule) {
    testing::TempFolder folder;
    const auto source = folder.write("bindings.hlsl", R"(
cbuffer Params : register(b0) { float scale; };
cbuffer Extra : register(b1, space2) { float4 tint; };
Texture2D<float4> Input : register(t0);
Texture2D<float4> Zenith;
SamplerState Linear : register(s0);
RWTexture2D<float4> Output : register(u0);
RWStructuredBuffer<float> Counts;
StructuredBuffer<float> Weights;
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float4 v = Input.SampleLevel(Linear, float2(0.5, 0.5), 0) + Zenith.Load(int3(0, 0, 0)) * tint;
    Output[id.xy] = v * scale * Weights[0];
    Counts[0] = v.x;
}
)");
    CompileOptions options;
    options.source = source;
    const auto reflection = compileShader(options).reflection;
    const auto expect = [&](const char* name, const char* registerName, uint32_t set, uint32_t binding) {
        const auto* resource = reflection.find(name);
        ASSERT_NE(resource, nullptr) << name;
        EXPECT_EQ(resource->location.registerName(), registerName) << name;
        EXPECT_EQ(resource->location.set, set) << name;
        EXPECT_EQ(resource->location.binding, binding) << name;
    };
    expect("Params", "b0", 0, 0);
    expect("Extra", "b1", 2, 1);
    expect("Input", "t0", 0, 32);
    expect("Zenith", "t1", 0, 33); // declared before Weights: declaration order, not name order
    expect("Linear", "s0", 0, 64);
    expect("Output", "u0", 0, 96);
    expect("Counts", "u1", 0, 97);
    expect("Weights", "t2", 0, 34);
    EXPECT_TRUE(reflection.find("Weights")->readOnly);
    EXPECT_FALSE(reflection.find("Counts")->readOnly);
}

} // namespace
} // namespace iblkit::compiler
