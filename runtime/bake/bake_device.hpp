#pragma once

#include "bake_plan.hpp"
#include "bake_settings.hpp"

#include <cstdint>
#include <memory>

namespace iblkit::cache {
class ContentStore;
}
namespace iblkit::vulkan {
class VulkanContext;
}

namespace iblkit::bake {

class BakeKernels;
class BakeProgress;
class BakeSession;
class DeviceCaches;

// A bake's device, its caches and its kernels: a session's (bake_session.hpp), shared with the
// other bakes of a batch, or the bake's own, made here and torn down by tearDown (or with this).
class BakeDevice {
public:
    BakeDevice(BakeSession* session, const ResolvedSettings& settings, cache::ContentStore* cache, const NeededOutputs& needed,
               uint32_t sourceSize, BakeProgress& progress);
    ~BakeDevice();
    BakeDevice(const BakeDevice&) = delete;
    BakeDevice& operator=(const BakeDevice&) = delete;

    const vulkan::VulkanContext& context();
    DeviceCaches& caches() { return *caches_; }
    BakeKernels& kernels() { return *kernels_; }
    void tearDown(); // the bake's own kernels, caches and device, in that order

private:
    BakeSession* session_;
    // Declared so that they are destroyed kernels first, context last.
    std::unique_ptr<const vulkan::VulkanContext> ownContext_;
    std::unique_ptr<DeviceCaches> ownCaches_;
    std::unique_ptr<BakeKernels> ownKernels_;
    DeviceCaches* caches_ = nullptr;
    BakeKernels* kernels_ = nullptr;
};

} // namespace iblkit::bake
