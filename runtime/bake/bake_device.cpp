#include "bake_device.hpp"

#include "bake_kernels.hpp"
#include "bake_progress.hpp"
#include "bake_session.hpp"
#include "device_caches.hpp"
#include "vulkan_context.hpp"

namespace iblkit::bake {

BakeDevice::BakeDevice(BakeSession* session, const ResolvedSettings& settings, cache::ContentStore* cache,
                       const NeededOutputs& needed, uint32_t sourceSize, BakeProgress& progress)
    : session_(session) {
    progress.part("instance and device");
    if (!session) ownContext_ = std::make_unique<const vulkan::VulkanContext>(settings.context);
    progress.part("pipeline cache");
    if (!session) ownCaches_ = std::make_unique<DeviceCaches>(cache, context());
    progress.part("kernel threads");
    if (!session) ownKernels_ = std::make_unique<BakeKernels>(context(), settings, needed, sourceSize);
    caches_ = session ? &session->caches(cache) : ownCaches_.get(); // first: new caches make the kernels anew
    kernels_ = session ? &session->kernels(settings, needed, sourceSize) : ownKernels_.get();
}

BakeDevice::~BakeDevice() { tearDown(); }

const vulkan::VulkanContext& BakeDevice::context() { return session_ ? session_->context() : *ownContext_; }

void BakeDevice::tearDown() {
    ownKernels_.reset();
    ownCaches_.reset();
    ownContext_.reset();
}

} // namespace iblkit::bake
