#pragma once

#include "context_options.hpp"
#include "shader_features.hpp"

#include <vulkan/vulkan_raii.hpp>

#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

namespace iblkit::vulkan {

// Instance, the chosen device, its compute queue, a command pool and a pipeline cache.
class VulkanContext {
public:
    explicit VulkanContext(const ContextOptions& options = {});
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    const DeviceInfo& deviceInfo() const { return deviceInfo_; }
    const vk::raii::Device& device() const { return device_; }
    const vk::raii::PhysicalDevice& physicalDevice() const { return physicalDevice_; }
    const vk::raii::PipelineCache& pipelineCache() const { return pipelineCache_; }
    // The pipeline cache's contents (vkGetPipelineCacheData), for a later context on this device.
    std::vector<std::byte> pipelineCacheData() const;
    // Merges what an earlier context's pipelineCacheData gave into this one's cache, before any
    // pipeline is made. Data whose header names another device, driver build or header version
    // is not given to the driver: false.
    bool addPipelineCacheData(std::span<const std::byte> data) const;
    // The device and driver build a pipeline cache's data is for: vendor, device and the
    // pipelineCacheUUID, in hex.
    std::string pipelineCacheIdentity() const;
    bool validationEnabled() const { return validationEnabled_; }
    bool canDraw() const { return canDraw_; } // the queue draws as well as dispatches
    const ShaderFeatures& shaderFeatures() const { return shaderFeatures_; } // enabled: all the device has
    uint64_t mostGroupsPerDispatch() const { return mostGroupsPerDispatch_; }
    // Nanoseconds per timestamp tick, 0 when the queue has no timestamps.
    double timestampPeriod() const { return timestampPeriod_; }

    uint32_t memoryTypeIndex(uint32_t allowedTypes, vk::MemoryPropertyFlags properties) const;
    vk::DeviceSize largestHeapSize() const;
    // Records commands into a fresh command buffer, submits it and waits for it.
    void submitAndWait(const std::function<void(const vk::raii::CommandBuffer&)>& record) const;

private:
    [[noreturn]] void failDevice(const std::string& message) const;

    std::chrono::milliseconds submissionTimeout_;
    uint64_t mostGroupsPerDispatch_;
    std::function<void(const std::string&)> onDeviceFailure_;

    vk::raii::Context loader_;
    std::shared_ptr<ValidationLog> validationLog_;
    bool validationEnabled_ = false;
    vk::raii::Instance instance_{nullptr};
    vk::raii::DebugUtilsMessengerEXT messenger_{nullptr};
    vk::raii::PhysicalDevice physicalDevice_{nullptr};
    DeviceInfo deviceInfo_;
    uint32_t queueFamily_ = 0;
    bool canDraw_ = false;
    ShaderFeatures shaderFeatures_;
    double timestampPeriod_ = 0;
    vk::raii::Device device_{nullptr};
    vk::raii::Queue queue_{nullptr};
    vk::raii::CommandPool commandPool_{nullptr};
    vk::raii::PipelineCache pipelineCache_{nullptr};
};

} // namespace iblkit::vulkan
