#pragma once

#include "buffer.hpp"
#include "image.hpp"
#include "resource_bindings.hpp"
#include "vulkan_context.hpp"

#include "reflection.hpp"

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace iblkit::vulkan {

struct DispatchTiming {
    std::array<uint32_t, 3> groups;
    double deviceMilliseconds; // from timestamp queries; negative when the queue has none
    double wallMilliseconds;   // submission to completion, as the host saw it
};

// A compute shader ready to run: descriptor set layouts made from its reflection, resources
// bound by their HLSL names, specialization constants by name, push constants as bytes.
class ComputeProgram {
public:
    ComputeProgram(const VulkanContext& context, const std::vector<uint32_t>& spirv,
                   compiler::ShaderReflection reflection, const std::map<std::string, double>& specialization = {});

    const compiler::ShaderReflection& reflection() const { return bindings_.reflection(); }

    // Each checks that the shader has a resource of that name and kind, with a matching
    // format and dimension, and throws VulkanError naming the problem otherwise. Images are
    // bound whole when sampled, and at one mip when written.
    // `element` is the index within an array of resources (Texture2D t[4]); each element of an
    // array must be bound before a dispatch.
    void bind(const std::string& name, const Buffer& buffer, uint32_t element = 0) { bindings_.bind(name, buffer, element); }
    void bind(const std::string& name, Image& image, uint32_t mip = 0, uint32_t element = 0) {
        bindings_.bind(name, image, mip, element);
    }
    void bind(const std::string& name, const Sampler& sampler, uint32_t element = 0) { bindings_.bind(name, sampler, element); }
    void setPushConstants(std::span<const std::byte> bytes) { bindings_.setPushConstants(bytes); }

    std::array<uint32_t, 3> groupsForThreads(std::array<uint32_t, 3> threads) const;
    DispatchTiming dispatchGroups(const VulkanContext& context, std::array<uint32_t, 3> groups);
    DispatchTiming dispatchThreads(const VulkanContext& context, std::array<uint32_t, 3> threads);

private:
    ResourceBindings bindings_;
    vk::raii::Pipeline pipeline_{nullptr};
};

} // namespace iblkit::vulkan
