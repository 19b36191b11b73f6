#include "gpu_bake.hpp"

#include "compute_program.hpp"
#include "vulkan_error.hpp"

namespace iblkit::consistency {

std::vector<float> gpuBrdfLut(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t size) {
    vulkan::ComputeProgram compute(context, program.spirv, program.reflection);
    vulkan::Image lut(context, {"Precomputed", &vulkan::texelFormatNamed("R32G32_SFLOAT"), size, size, 1, 1, false, true});
    compute.bind("Precomputed", lut);
    compute.dispatchThreads(context, {size, size, 1});
    return lut.download(context);
}

std::vector<float> gpuPrefilter(const vulkan::VulkanContext& context, const PathProgram& program,
                                const reference::CubeEnvironment& environment, float roughness, uint32_t size) {
    vulkan::ComputeProgram compute(context, program.spirv, program.reflection);
    const auto& rgba32 = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");
    vulkan::Image envMap(context, {"EnvMap", &rgba32, environment.size(), environment.size(), 6, 1, true, false});
    envMap.upload(context, environment.texels());
    const vulkan::Sampler linear(context, {});
    vulkan::Image prefiltered(context, {"Prefiltered", &rgba32, size, size, 6, 1, false, true});
    // The round-tripped HLSL renames cbuffer members; the block holds one float at its first member's offset.
    const auto* parameters = program.reflection.find("PrefilterSpecularParameter");
    if (!parameters || parameters->members.empty())
        throw vulkan::VulkanError("the prefilter program has no PrefilterSpecularParameter cbuffer with a member");
    vulkan::Buffer parameterBuffer(context, 16, vk::BufferUsageFlagBits::eUniformBuffer, "PrefilterSpecularParameter");
    parameterBuffer.write(std::as_bytes(std::span(&roughness, 1)), parameters->members.at(0).offset);
    compute.bind("EnvMap", envMap);
    compute.bind("EnvMapSampler", linear);
    compute.bind("Prefiltered", prefiltered);
    compute.bind("PrefilterSpecularParameter", parameterBuffer);
    compute.dispatchThreads(context, {size, size, 6});
    return prefiltered.download(context);
}

} // namespace iblkit::consistency
