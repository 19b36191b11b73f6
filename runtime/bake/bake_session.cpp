#include "bake_session.hpp"

#include "bake_kernels.hpp"
#include "bake_outputs.hpp"
#include "content_store.hpp"
#include "device_caches.hpp"
#include "vulkan_context.hpp"

#include <fmt/format.h>

namespace iblkit::bake {
namespace {

std::string kernelsKey(const ResolvedSettings& settings, const NeededOutputs& outputs, uint32_t sourceSize) {
    return fmt::format("{} {} {} {} {} {} {}", settings.specularMethod, settings.sampleCount, sourceSize,
                       outputs.specular, outputs.lut, settings.lutMethod, settings.lutSampleCount);
}

std::string lutKey(const ResolvedSettings& settings) {
    return fmt::format("{} {} {}", settings.lutMethod, settings.lutSampleCount, settings.lutSize);
}

} // namespace

BakeSession::BakeSession(vulkan::ContextOptions options) : options_(std::move(options)) {
    contextFuture_ = std::async(std::launch::async, [options = options_] {
        return std::make_unique<const vulkan::VulkanContext>(options);
    });
}

BakeSession::~BakeSession() {
    // The kernels before the caches that compiled them, the caches before the context they serve.
    kernels_.clear();
    caches_.reset();
    if (contextFuture_.valid()) contextFuture_.wait();
}

const vulkan::VulkanContext& BakeSession::context() {
    // A device that cannot be made fails here every bake that needs it, with the same error.
    if (contextError_) std::rethrow_exception(contextError_);
    if (!context_) {
        try {
            context_ = contextFuture_.get();
        } catch (...) {
            contextError_ = std::current_exception();
            throw;
        }
    }
    return *context_;
}

const vulkan::DeviceInfo& BakeSession::deviceInfo() {
    if (!device_) device_ = context().deviceInfo();
    return *device_;
}

DeviceCaches& BakeSession::caches(cache::ContentStore* store) {
    const std::string folder = store ? store->folder().string() : std::string();
    if (!caches_ || folder != cachesFolder_) {
        kernels_.clear(); // made with the earlier caches' kernels in use
        caches_.reset();
        caches_ = std::make_unique<DeviceCaches>(store, context());
        cachesFolder_ = folder;
    }
    return *caches_;
}

BakeKernels& BakeSession::kernels(const ResolvedSettings& settings, const NeededOutputs& outputs, uint32_t sourceSize) {
    auto& kernels = kernels_[kernelsKey(settings, outputs, sourceSize)];
    if (!kernels) kernels = std::make_unique<BakeKernels>(context(), settings, outputs, sourceSize);
    return *kernels;
}

const BakedTexture* BakeSession::lut(const ResolvedSettings& settings) const {
    const auto found = luts_.find(lutKey(settings));
    return found == luts_.end() ? nullptr : found->second.get();
}

void BakeSession::keepLut(const ResolvedSettings& settings, const BakedTexture& lut) {
    luts_[lutKey(settings)] = std::make_unique<BakedTexture>(lut);
}

} // namespace iblkit::bake
