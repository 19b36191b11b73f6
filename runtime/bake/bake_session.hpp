#pragma once

#include "bake_plan.hpp"
#include "bake_settings.hpp"
#include "gpu_steps.hpp"

#include <exception>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace iblkit::cache {
class ContentStore;
}
namespace iblkit::vulkan {
class VulkanContext;
}

namespace iblkit::bake {

class BakeKernels;
class DeviceCaches;
struct BakedTexture;

// What many bakes in one process share (`iblkit batch`): one device, made on a thread as the
// session starts; the kernels each set of settings needs, made once; the compiled-kernel and
// pipeline caches of one content store; and each LUT, computed once (its values depend on the
// LUT's settings alone, never on the environment). A bake without a session makes and tears down
// its own. Not thread-safe: one bake's device work at a time, on the thread that made the session.
class BakeSession {
public:
    explicit BakeSession(vulkan::ContextOptions options);
    ~BakeSession();
    BakeSession(const BakeSession&) = delete;
    BakeSession& operator=(const BakeSession&) = delete;

    const vulkan::VulkanContext& context();
    const vulkan::DeviceInfo& device() { return deviceInfo(); }
    // The caches of `store` (none without one); a store in another folder replaces them.
    DeviceCaches& caches(cache::ContentStore* store);
    // The kernels of `settings` for a source of `sourceSize`, made at the first bake that needs them.
    BakeKernels& kernels(const ResolvedSettings& settings, const NeededOutputs& outputs, uint32_t sourceSize);

    // The LUT of `settings` an earlier bake of the session computed, if any.
    const BakedTexture* lut(const ResolvedSettings& settings) const;
    void keepLut(const ResolvedSettings& settings, const BakedTexture& lut);

private:
    const vulkan::DeviceInfo& deviceInfo();

    vulkan::ContextOptions options_;
    std::future<std::unique_ptr<const vulkan::VulkanContext>> contextFuture_;
    std::unique_ptr<const vulkan::VulkanContext> context_;
    std::exception_ptr contextError_;
    std::optional<vulkan::DeviceInfo> device_;
    std::unique_ptr<DeviceCaches> caches_;
    std::string cachesFolder_;
    std::map<std::string, std::unique_ptr<BakeKernels>> kernels_;
    std::map<std::string, std::unique_ptr<BakedTexture>> luts_;
};

} // namespace iblkit::bake
