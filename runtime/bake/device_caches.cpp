#include "device_caches.hpp"

#include "cache_error.hpp"
#include "cache_key.hpp"
#include "content_store.hpp"
#include "vulkan_context.hpp"

namespace iblkit::bake {
namespace {

// No program digest: the driver judges its own data, and the header names the driver's build.
std::string pipelineCacheKey(const vulkan::VulkanContext& context) {
    const auto& device = context.deviceInfo();
    return cache::CacheKey()
        .add("entry", "vulkan pipeline cache")
        .add("device", device.name)
        .add("driver", device.driver)
        .add("identity", context.pipelineCacheIdentity())
        .hex();
}

std::span<const std::byte> bytesOf(const std::string& text) { return std::as_bytes(std::span(text.data(), text.size())); }

} // namespace

DeviceCaches::DeviceCaches(cache::ContentStore* store, const vulkan::VulkanContext& context) : context_(context) {
    if (!store) return;
    store_ = std::make_unique<cache::ContentStore>(store->folder());
    kernels_.emplace(store->folder());
    useKernels_.emplace(&*kernels_);
    pipelineKey_ = pipelineCacheKey(context_);
    if (auto data = store_->get(pipelineKey_); data && context_.addPipelineCacheData(bytesOf(*data))) loaded_ = std::move(*data);
}

void DeviceCaches::keepPipelineCache(std::vector<std::string>& warnings) {
    if (!store_) return;
    const auto data = context_.pipelineCacheData();
    const std::string bytes(reinterpret_cast<const char*>(data.data()), data.size());
    if (bytes == loaded_) return;
    try {
        store_->put(pipelineKey_, bytes);
    } catch (const cache::CacheError& error) {
        if (warnings.empty()) warnings.push_back(std::string(error.what()) + " (the bake goes on without caching it)");
    }
}

DeviceCaches::~DeviceCaches() = default;

kernels::CompiledKernelCache::Counts DeviceCaches::compiledKernels() const {
    return kernels_ ? kernels_->counts() : kernels::CompiledKernelCache::Counts{};
}

} // namespace iblkit::bake
