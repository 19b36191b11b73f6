#pragma once

#include <vulkan/vulkan_raii.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::vulkan {

// The optional shader features an HLSL compute shader may need: 64-bit floats and integers
// (double, uint64_t), 16-bit and 8-bit arithmetic (-enable-16bit-types) and 16-bit values in
// buffers and push constants. A device gets every one of them it has.
struct ShaderFeatures {
    bool float64 = false, int64 = false, int16 = false, float16 = false, int8 = false;
    bool storageBuffer16 = false, uniformBuffer16 = false, pushConstant16 = false;
    // VK_EXT_descriptor_indexing: arrays of resources indexed non-uniformly (NonUniformResourceIndex).
    bool sampledImageNonUniform = false, storageImageNonUniform = false, storageBufferNonUniform = false,
         uniformBufferNonUniform = false;
    bool descriptorIndexing() const {
        return sampledImageNonUniform || storageImageNonUniform || storageBufferNonUniform || uniformBufferNonUniform;
    }
};

// What `device` has, asked with vkGetPhysicalDeviceFeatures2; 16-bit and 8-bit arithmetic
// need VK_KHR_shader_float16_int8 on a Vulkan 1.1 instance (hasFloat16Int8Extension), non-uniform
// indexing VK_EXT_descriptor_indexing (hasDescriptorIndexingExtension).
ShaderFeatures supportedShaderFeatures(const vk::raii::PhysicalDevice& device, bool hasFloat16Int8Extension,
                                       bool hasDescriptorIndexingExtension = false);

// The feature structures that enable `features` at device creation: chain() is the pNext of
// vk::DeviceCreateInfo.
class ShaderFeatureChain {
public:
    explicit ShaderFeatureChain(const ShaderFeatures& features);
    const void* chain() const { return &chain_.get<vk::PhysicalDeviceFeatures2>(); }

private:
    vk::StructureChain<vk::PhysicalDeviceFeatures2, vk::PhysicalDevice16BitStorageFeatures,
                       vk::PhysicalDeviceShaderFloat16Int8Features, vk::PhysicalDeviceDescriptorIndexingFeatures>
        chain_;
};

// The first capability of `spirv` that needs a feature `enabled` lacks, named with the feature
// ("Float16 (shaderFloat16)"), or "" when the device has all it needs.
std::string missingShaderFeature(const std::vector<uint32_t>& spirv, const ShaderFeatures& enabled);

} // namespace iblkit::vulkan
