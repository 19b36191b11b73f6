#pragma once

#include "content_store.hpp"
#include "kernels/kernel_table.hpp"

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>

namespace iblkit::compiler {
struct CompiledShader;
}

namespace iblkit::kernels {

// Compiled kernels kept in a content store (runtime/cache/), so that no kernel is compiled twice
// for the same program. An entry is named by the SHA-256 of what is known before compiling (the
// program's build, the source's path and text, the entry point, the defines, the image formats
// and every other compile option) and holds, beside the SPIR-V and its reflection, the SHA-256
// of each file the source #included: an entry whose includes now read differently is stale, a
// miss, and the new compile replaces it (as ccache's direct mode does). Safe on any thread.
class CompiledKernelCache {
public:
    // A read-only cache (built_in_kernels.hpp) is never written: keep counts it unwritable.
    explicit CompiledKernelCache(const std::filesystem::path& folder,
                                 cache::ContentStore::Access access = cache::ContentStore::Access::ReadWrite);
    ~CompiledKernelCache();

    // Empty on a miss; options without a source text are never cached.
    std::optional<KernelProgram> find(const compiler::CompileOptions& options);
    // A cache that cannot be written is counted, never thrown: the kernel was compiled all the same.
    void keep(const compiler::CompileOptions& options, const compiler::CompiledShader& shader);

    struct Counts {
        size_t hits = 0, misses = 0, stale = 0, damaged = 0, unwritable = 0;
    };
    Counts counts() const;

private:
    mutable std::mutex mutex_;
    std::unique_ptr<cache::ContentStore> store_;
    Counts counts_;
};

// While one lives, compileKernel on this thread looks in `cache` first and keeps what it compiles
// there; the one in use before it is restored when it goes. Per thread, as scopes nest only within
// one: a thread that compiles for another takes the other's compiledKernelCacheInUse() (BakeKernels
// does for its workers). A thread-wide setting rather than a parameter, because kernels are
// compiled deep inside each method's constructor.
class UseCompiledKernelCache {
public:
    explicit UseCompiledKernelCache(CompiledKernelCache* cache); // null: none
    ~UseCompiledKernelCache();
    UseCompiledKernelCache(const UseCompiledKernelCache&) = delete;
    UseCompiledKernelCache& operator=(const UseCompiledKernelCache&) = delete;

private:
    CompiledKernelCache* previous_;
};

// The cache compileKernel uses on this thread now, or null.
CompiledKernelCache* compiledKernelCacheInUse();

} // namespace iblkit::kernels
