#pragma once

#include "buffer.hpp"
#include "image.hpp"
#include "vulkan_context.hpp"

#include "reflection.hpp"

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace iblkit::vulkan {

// The descriptor sets and push constants of one pipeline: set layouts made from the reflection
// of its shaders, resources bound by their HLSL names, written before each use. Shared by the
// compute and the graphics programs.
class ResourceBindings {
public:
    ResourceBindings(const VulkanContext& context, compiler::ShaderReflection reflection, vk::ShaderStageFlags stages);

    const compiler::ShaderReflection& reflection() const { return reflection_; }
    const vk::raii::PipelineLayout& pipelineLayout() const { return pipelineLayout_; }

    // Each checks that the shaders have a resource of that name and kind, with a matching
    // format and dimension, and throws VulkanError naming the problem otherwise. Images are
    // bound whole when sampled, and at one mip when written.
    void bind(const std::string& name, const Buffer& buffer, uint32_t element = 0);
    void bind(const std::string& name, Image& image, uint32_t mip = 0, uint32_t element = 0);
    void bind(const std::string& name, const Sampler& sampler, uint32_t element = 0);
    void setPushConstants(std::span<const std::byte> bytes);

    // Writes every descriptor (throws VulkanError naming what is not bound) and records their
    // binding and the push constants into `commands`.
    void record(const vk::raii::CommandBuffer& commands, vk::PipelineBindPoint bindPoint) const;
    void writeDescriptorSets() const;

private:
    struct Bound {
        vk::DescriptorType type;
        vk::DescriptorBufferInfo buffer;
        vk::DescriptorImageInfo image;
    };
    const compiler::ReflectedResource& resource(const std::string& name) const;
    void store(const std::string& name, uint32_t element, Bound bound);

    compiler::ShaderReflection reflection_;
    vk::ShaderStageFlags stages_;
    const vk::raii::Device* device_;
    std::map<uint32_t, vk::raii::DescriptorSetLayout> setLayouts_;
    vk::raii::PipelineLayout pipelineLayout_{nullptr};
    vk::raii::DescriptorPool descriptorPool_{nullptr};
    std::map<uint32_t, vk::raii::DescriptorSet> sets_;
    std::map<std::string, std::vector<std::optional<Bound>>> bound_; // by name, one per element
    std::vector<std::byte> pushConstants_;
};

// Specialization constants by name as the bytes and map entries of a vk::SpecializationInfo;
// throws VulkanError for a name the shader lacks.
std::vector<std::byte> specializationBytes(const compiler::ShaderReflection& reflection,
                                           const std::map<std::string, double>& values,
                                           std::vector<vk::SpecializationMapEntry>& entries);

} // namespace iblkit::vulkan
