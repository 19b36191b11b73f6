#include "shader_features.hpp"

#include <spirv/unified1/spirv.hpp>

namespace iblkit::vulkan {

ShaderFeatures supportedShaderFeatures(const vk::raii::PhysicalDevice& device, bool hasFloat16Int8Extension,
                                       bool hasDescriptorIndexingExtension) {
    // The float16/int8 structure is asked about only where the device has its extension.
    const auto chain = device.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDevice16BitStorageFeatures>();
    const auto& core = chain.get<vk::PhysicalDeviceFeatures2>().features;
    const auto& storage = chain.get<vk::PhysicalDevice16BitStorageFeatures>();
    ShaderFeatures features;
    features.float64 = core.shaderFloat64;
    features.int64 = core.shaderInt64;
    features.int16 = core.shaderInt16;
    features.storageBuffer16 = storage.storageBuffer16BitAccess;
    features.uniformBuffer16 = storage.uniformAndStorageBuffer16BitAccess;
    features.pushConstant16 = storage.storagePushConstant16;
    if (hasFloat16Int8Extension) {
        const auto withArithmetic = device.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceShaderFloat16Int8Features>();
        const auto& arithmetic = withArithmetic.get<vk::PhysicalDeviceShaderFloat16Int8Features>();
        features.float16 = arithmetic.shaderFloat16;
        features.int8 = arithmetic.shaderInt8;
    }
    if (hasDescriptorIndexingExtension) {
        const auto withIndexing = device.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceDescriptorIndexingFeatures>();
        const auto& indexing = withIndexing.get<vk::PhysicalDeviceDescriptorIndexingFeatures>();
        features.sampledImageNonUniform = indexing.shaderSampledImageArrayNonUniformIndexing;
        features.storageImageNonUniform = indexing.shaderStorageImageArrayNonUniformIndexing;
        features.storageBufferNonUniform = indexing.shaderStorageBufferArrayNonUniformIndexing;
        features.uniformBufferNonUniform = indexing.shaderUniformBufferArrayNonUniformIndexing;
    }
    return features;
}

ShaderFeatureChain::ShaderFeatureChain(const ShaderFeatures& features) {
    auto& core = chain_.get<vk::PhysicalDeviceFeatures2>().features;
    core.shaderFloat64 = features.float64;
    core.shaderInt64 = features.int64;
    core.shaderInt16 = features.int16;
    auto& storage = chain_.get<vk::PhysicalDevice16BitStorageFeatures>();
    storage.storageBuffer16BitAccess = features.storageBuffer16;
    storage.uniformAndStorageBuffer16BitAccess = features.uniformBuffer16;
    storage.storagePushConstant16 = features.pushConstant16;
    auto& arithmetic = chain_.get<vk::PhysicalDeviceShaderFloat16Int8Features>();
    arithmetic.shaderFloat16 = features.float16;
    arithmetic.shaderInt8 = features.int8;
    if (!features.float16 && !features.int8) chain_.unlink<vk::PhysicalDeviceShaderFloat16Int8Features>();
    auto& indexing = chain_.get<vk::PhysicalDeviceDescriptorIndexingFeatures>();
    indexing.shaderSampledImageArrayNonUniformIndexing = features.sampledImageNonUniform;
    indexing.shaderStorageImageArrayNonUniformIndexing = features.storageImageNonUniform;
    indexing.shaderStorageBufferArrayNonUniformIndexing = features.storageBufferNonUniform;
    indexing.shaderUniformBufferArrayNonUniformIndexing = features.uniformBufferNonUniform;
    if (!features.descriptorIndexing()) chain_.unlink<vk::PhysicalDeviceDescriptorIndexingFeatures>();
}

std::string missingShaderFeature(const std::vector<uint32_t>& spirv, const ShaderFeatures& enabled) {
    constexpr size_t kHeaderWords = 5;
    for (size_t at = kHeaderWords; at < spirv.size();) {
        const uint32_t words = spirv[at] >> 16, opcode = spirv[at] & 0xFFFF;
        if (words == 0) break;
        if (opcode == spv::OpCapability && at + 1 < spirv.size()) {
            switch (spirv[at + 1]) {
            case spv::CapabilityFloat64: if (!enabled.float64) return "Float64 (shaderFloat64)"; break;
            case spv::CapabilityInt64: if (!enabled.int64) return "Int64 (shaderInt64)"; break;
            case spv::CapabilityInt16: if (!enabled.int16) return "Int16 (shaderInt16)"; break;
            case spv::CapabilityFloat16: if (!enabled.float16) return "Float16 (shaderFloat16)"; break;
            case spv::CapabilityInt8: if (!enabled.int8) return "Int8 (shaderInt8)"; break;
            case spv::CapabilityStorageBuffer16BitAccess:
                if (!enabled.storageBuffer16) return "StorageBuffer16BitAccess (storageBuffer16BitAccess)";
                break;
            case spv::CapabilityUniformAndStorageBuffer16BitAccess:
                if (!enabled.uniformBuffer16) return "UniformAndStorageBuffer16BitAccess (uniformAndStorageBuffer16BitAccess)";
                break;
            case spv::CapabilityStoragePushConstant16:
                if (!enabled.pushConstant16) return "StoragePushConstant16 (storagePushConstant16)";
                break;
            case spv::CapabilitySampledImageArrayNonUniformIndexing:
                if (!enabled.sampledImageNonUniform) return "SampledImageArrayNonUniformIndexing (shaderSampledImageArrayNonUniformIndexing)";
                break;
            case spv::CapabilityStorageImageArrayNonUniformIndexing:
                if (!enabled.storageImageNonUniform) return "StorageImageArrayNonUniformIndexing (shaderStorageImageArrayNonUniformIndexing)";
                break;
            case spv::CapabilityStorageBufferArrayNonUniformIndexing:
                if (!enabled.storageBufferNonUniform) return "StorageBufferArrayNonUniformIndexing (shaderStorageBufferArrayNonUniformIndexing)";
                break;
            case spv::CapabilityUniformBufferArrayNonUniformIndexing:
                if (!enabled.uniformBufferNonUniform) return "UniformBufferArrayNonUniformIndexing (shaderUniformBufferArrayNonUniformIndexing)";
                break;
            default: break;
            }
        }
        at += words;
    }
    return "";
}

} // namespace iblkit::vulkan
