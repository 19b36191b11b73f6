#pragma once

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

// Collects what the validation layer says, including what it says while the context is
// being destroyed (leaked objects), so it must outlive the context.
class ValidationLog {
public:
    void add(std::string message);
    std::vector<std::string> messages() const;

private:
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
};

struct DeviceInfo {
    uint32_t index;
    std::string name;
    std::string type; // "cpu", "discrete-gpu", "integrated-gpu", "virtual-gpu", "other"
    std::string driver;
    std::string apiVersion;
    bool isLavapipe;
};

struct ContextOptions {
    // A device index or a case-insensitive part of its name; empty: $IBLKIT_DEVICE, else
    // lavapipe when present, else the first device.
    std::string device;
    // VK_LAYER_KHRONOS_validation; also on with $IBLKIT_VALIDATION=1, and in debug builds
    // whenever the layer is installed.
    bool validation = false;
    std::shared_ptr<ValidationLog> validationLog;
    // How long one submission may run before the wait for it gives up: a shader that never ends.
    std::chrono::milliseconds submissionTimeout = std::chrono::minutes(10);
    // Called with the message when a submission times out or the device is lost, before
    // VulkanError is thrown. The device may still be running that submission, so what was made
    // on the context cannot safely be destroyed; a program may end here (the command-line tool
    // does). The context is unusable afterwards.
    std::function<void(const std::string& message)> onDeviceFailure = {};
    // The most workgroups one vkCmdDispatch may hold (dispatch_regions.hpp: lavapipe counts them
    // in 32 bits); larger dispatches run as several regions. Smaller only for tests.
    uint64_t mostGroupsPerDispatch = 0xFFFFFFFFu;
};

// Every Vulkan device the loader sees. Throws VulkanError when there is none.
std::vector<DeviceInfo> listDevices();

// The device a context would choose for `selector` (see ContextOptions::device; empty reads
// $IBLKIT_DEVICE). Throws VulkanError when nothing matches.
size_t chooseDevice(const std::vector<DeviceInfo>& devices, const std::string& selector);

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
    ShaderFeatures shaderFeatures_;
    double timestampPeriod_ = 0;
    vk::raii::Device device_{nullptr};
    vk::raii::Queue queue_{nullptr};
    vk::raii::CommandPool commandPool_{nullptr};
    vk::raii::PipelineCache pipelineCache_{nullptr};
};

} // namespace iblkit::vulkan
