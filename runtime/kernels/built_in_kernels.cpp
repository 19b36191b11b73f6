#include "kernels/built_in_kernels.hpp"

#include <atomic>
#include <memory>
#include <system_error>
#include <utility>

namespace iblkit::kernels {
namespace {

std::atomic<size_t> builtInCount{0}, compiledCount{0};
thread_local bool builtInIgnored = false;

} // namespace

std::filesystem::path builtInKernelFolder() {
    std::error_code error;
    const auto program = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : program.parent_path() / "kernels";
}

CompiledKernelCache* builtInKernels() {
    static const std::unique_ptr<CompiledKernelCache> store = []() -> std::unique_ptr<CompiledKernelCache> {
        const auto folder = builtInKernelFolder();
        std::error_code error;
        if (folder.empty() || !std::filesystem::is_directory(folder / "objects", error)) return nullptr;
        return std::make_unique<CompiledKernelCache>(folder, true);
    }();
    return builtInIgnored ? nullptr : store.get();
}

WithoutBuiltInKernels::WithoutBuiltInKernels() : previous_(std::exchange(builtInIgnored, true)) {}

WithoutBuiltInKernels::~WithoutBuiltInKernels() { builtInIgnored = previous_; }

KernelCompileCounts kernelCompileCounts() { return {builtInCount.load(), compiledCount.load()}; }
void countBuiltInKernel() { ++builtInCount; }
void countCompiledKernel() { ++compiledCount; }

} // namespace iblkit::kernels
