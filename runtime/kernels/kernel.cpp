#include "kernels/kernel.hpp"

#include "block_writer.hpp"
#include "vulkan_error.hpp"

#include <algorithm>
#include <regex>
#include <utility>

namespace iblkit::kernels {
namespace {

const compiler::ReflectedResource* constantBuffer(const compiler::ShaderReflection& reflection) {
    const compiler::ReflectedResource* found = nullptr;
    for (const auto& resource : reflection.resources) {
        if (resource.kind != compiler::ResourceKind::ConstantBuffer) continue;
        if (found) throw vulkan::VulkanError("a kernel has more than one cbuffer: " + resource.name);
        found = &resource;
    }
    return found;
}

// SPIRV-Cross's HLSL output prefixes cbuffer members with their block's id: "_21_Roughness".
std::string originalMemberName(const std::string& name) {
    static const std::regex renamed("^_[0-9]+_(.+)$");
    std::smatch match;
    return std::regex_match(name, match, renamed) ? match[1].str() : name;
}

} // namespace

Kernel::Kernel(const vulkan::VulkanContext& context, const KernelProgram& program)
    : context_(context), program_(context, program.spirv, program.reflection) {
    if (const auto* block = constantBuffer(program.reflection)) {
        parameters_ = std::make_unique<vulkan::Buffer>(context, block->blockSize, vk::BufferUsageFlagBits::eUniformBuffer,
                                                       block->name);
        program_.bind(block->name, *parameters_);
    }
}

void Kernel::setParameters(const NamedValues& values) {
    const auto* block = constantBuffer(program_.reflection());
    if (!block) throw vulkan::VulkanError("this kernel has no cbuffer to take parameters");
    // Every member gets a value and every value a member: a renamed field must not stay 0.
    NamedValues byReflectedName;
    for (const auto& member : block->members) {
        const auto value = values.find(originalMemberName(member.name));
        if (value == values.end())
            throw vulkan::VulkanError(block->name + "." + member.name + " is not a parameter of this kernel's role");
        byReflectedName[member.name] = value->second;
    }
    if (byReflectedName.size() != values.size())
        throw vulkan::VulkanError(block->name + " lacks a member for some of its role's parameters");
    parameters_->write(vulkan::packBlock(block->name, block->members, block->blockSize, byReflectedName));
}

void Kernel::run(std::array<uint32_t, 3> threads) { runGroups(program_.groupsForThreads(threads)); }

void Kernel::runGroups(std::array<uint32_t, 3> groups) {
    const auto timing = program_.dispatchGroups(context_, groups);
    totals_.deviceMilliseconds += std::max(0.0, timing.deviceMilliseconds);
    totals_.wallMilliseconds += timing.wallMilliseconds;
    ++totals_.dispatches;
}

DispatchTotals Kernel::takeTotals() { return std::exchange(totals_, {}); }

} // namespace iblkit::kernels
