#include "compute_program.hpp"

#include "block_writer.hpp"
#include "dispatch_regions.hpp"
#include "timed_submission.hpp"
#include "vulkan_error.hpp"

namespace iblkit::vulkan {
ComputeProgram::ComputeProgram(const VulkanContext& context, const std::vector<uint32_t>& spirv,
                               compiler::ShaderReflection reflection, const std::map<std::string, double>& specialization)
    : bindings_(context, std::move(reflection), vk::ShaderStageFlagBits::eCompute) {
    const auto& reflected = bindings_.reflection();
    if (reflected.stage != compiler::ShaderStage::Compute)
        throw VulkanError("entry point '" + reflected.entryPoint + "' is not a compute shader");
    if (const auto missing = missingShaderFeature(spirv, context.shaderFeatures()); !missing.empty())
        throw VulkanError("the shader needs " + missing + ", which " + context.deviceInfo().name + " does not have");
    const vk::raii::ShaderModule module(context.device(), vk::ShaderModuleCreateInfo({}, spirv.size() * 4, spirv.data()));
    std::vector<vk::SpecializationMapEntry> entries;
    const auto data = specializationBytes(reflected, specialization, entries);
    const vk::SpecializationInfo specializationInfo(static_cast<uint32_t>(entries.size()), entries.data(), data.size(),
                                                    data.data());
    const vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, *module,
                                                  reflected.entryPoint.c_str(), &specializationInfo);
    try {
        // eDispatchBase: a dispatch too large for the driver's 32-bit group count runs as regions.
        pipeline_ = vk::raii::Pipeline(context.device(), context.pipelineCache(),
                                       vk::ComputePipelineCreateInfo(vk::PipelineCreateFlagBits::eDispatchBase, stage,
                                                                     *bindings_.pipelineLayout()));
    } catch (const vk::SystemError& error) {
        throw VulkanError("the driver could not build a compute pipeline of entry point '" + reflected.entryPoint +
                          "' from SPIR-V that passed spirv-val (" + error.what() + ")");
    }
}

std::array<uint32_t, 3> ComputeProgram::groupsForThreads(std::array<uint32_t, 3> threads) const {
    std::array<uint32_t, 3> groups{};
    for (int axis = 0; axis < 3; ++axis) {
        const uint32_t size = std::max(1u, bindings_.reflection().workgroupSize[axis]);
        groups[axis] = (threads[axis] + size - 1) / size;
    }
    return groups;
}

DispatchTiming ComputeProgram::dispatchThreads(const VulkanContext& context, std::array<uint32_t, 3> threads) {
    if (threads[0] == 0 || threads[1] == 0 || threads[2] == 0)
        throw VulkanError("dispatch of zero size: " + std::to_string(threads[0]) + "x" + std::to_string(threads[1]) +
                          "x" + std::to_string(threads[2]) + " threads");
    return dispatchGroups(context, groupsForThreads(threads));
}

DispatchTiming ComputeProgram::dispatchGroups(const VulkanContext& context, std::array<uint32_t, 3> groups) {
    if (groups[0] == 0 || groups[1] == 0 || groups[2] == 0)
        throw VulkanError("dispatch of zero size: " + std::to_string(groups[0]) + "x" + std::to_string(groups[1]) +
                          "x" + std::to_string(groups[2]) + " groups");
    const auto limits = context.physicalDevice().getProperties().limits;
    for (int axis = 0; axis < 3; ++axis)
        if (groups[axis] > limits.maxComputeWorkGroupCount[axis])
            throw VulkanError("dispatch of " + std::to_string(groups[axis]) + " groups on axis " + std::to_string(axis) +
                              " exceeds the device's limit of " + std::to_string(limits.maxComputeWorkGroupCount[axis]));
    bindings_.writeDescriptorSets();
    const auto timing = submitTimed(
        context,
        [&](const vk::raii::CommandBuffer& commands) {
            commands.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline_);
            bindings_.record(commands, vk::PipelineBindPoint::eCompute);
        },
        [&](const vk::raii::CommandBuffer& commands) {
            const auto regions = dispatchRegions(groups, context.mostGroupsPerDispatch());
            if (regions.size() == 1) return commands.dispatch(groups[0], groups[1], groups[2]);
            for (const auto& [base, count] : regions)
                commands.dispatchBase(base[0], base[1], base[2], count[0], count[1], count[2]);
        },
        [](const vk::raii::CommandBuffer& commands) {
            const vk::MemoryBarrier written(vk::AccessFlagBits::eShaderWrite,
                                            vk::AccessFlagBits::eTransferRead | vk::AccessFlagBits::eHostRead |
                                                vk::AccessFlagBits::eShaderRead);
            commands.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                                     vk::PipelineStageFlagBits::eTransfer | vk::PipelineStageFlagBits::eHost |
                                         vk::PipelineStageFlagBits::eComputeShader,
                                     {}, written, {}, {});
        });
    return {groups, timing.deviceMilliseconds, timing.wallMilliseconds};
}

} // namespace iblkit::vulkan
