#include "bake_kernel.hpp"

#include "bake_error.hpp"
#include "block_writer.hpp"

namespace iblkit::bake {

BakeKernel::BakeKernel(const vulkan::VulkanContext& context, const BakeShader& shader)
    : context_(context), program_(context, shader.spirv, shader.reflection) {
    for (const auto& resource : shader.reflection.resources) {
        if (resource.kind != compiler::ResourceKind::ConstantBuffer) continue;
        if (parameters_) throw BakeError("a bake shader has more than one cbuffer: " + resource.name);
        parameters_ = std::make_unique<vulkan::Buffer>(context, resource.blockSize,
                                                       vk::BufferUsageFlagBits::eUniformBuffer, resource.name);
        program_.bind(resource.name, *parameters_);
    }
}

void BakeKernel::setParameters(const std::map<std::string, std::vector<double>>& values) {
    for (const auto& resource : program_.reflection().resources)
        if (resource.kind == compiler::ResourceKind::ConstantBuffer)
            parameters_->write(vulkan::packBlock(resource.name, resource.members, resource.blockSize, values));
}

void BakeKernel::run(std::array<uint32_t, 3> threads, BakeProgress& progress) {
    runGroups(program_.groupsForThreads(threads), progress);
}

void BakeKernel::runGroups(std::array<uint32_t, 3> groups, BakeProgress& progress) {
    progress.addDeviceTime(program_.dispatchGroups(context_, groups).deviceMilliseconds);
}

} // namespace iblkit::bake
