#pragma once

// What a caller chooses a Vulkan context by, in std types alone: the many headers that carry
// these settings do not pay for vulkan_raii.hpp (seconds a file), which vulkan_context.hpp needs.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace iblkit::vulkan {

class VulkanContext; // vulkan_context.hpp

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

} // namespace iblkit::vulkan
