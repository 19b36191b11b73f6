#pragma once

#include "kernels/compiled_kernel_cache.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::cache {
class ContentStore;
}
namespace iblkit::vulkan {
class VulkanContext;
}

namespace iblkit::bake {

// What a bake's device work keeps between bakes besides its outputs, in the bake's content store:
// the compiled kernels (compiled_kernel_cache.hpp), in use from construction on, and the Vulkan
// pipeline cache, merged into the context's at construction, before any pipeline is made. Made
// before a bake's kernels and gone after them. Without a store it does nothing.
class DeviceCaches {
public:
    DeviceCaches(cache::ContentStore* store, const vulkan::VulkanContext& context);
    ~DeviceCaches();
    DeviceCaches(const DeviceCaches&) = delete;
    DeviceCaches& operator=(const DeviceCaches&) = delete;

    // Puts the pipeline cache back when the driver added to it. A store that cannot be written
    // is one warning.
    void keepPipelineCache(std::vector<std::string>& warnings);

    kernels::CompiledKernelCache::Counts compiledKernels() const;
    size_t pipelineCacheBytesLoaded() const { return loaded_.size(); }

private:
    std::unique_ptr<cache::ContentStore> store_; // its own, so the outputs' hits and misses count outputs alone
    const vulkan::VulkanContext& context_;
    std::string pipelineKey_;
    std::string loaded_;
    std::optional<kernels::CompiledKernelCache> kernels_;
    std::optional<kernels::UseCompiledKernelCache> useKernels_;
};

} // namespace iblkit::bake
