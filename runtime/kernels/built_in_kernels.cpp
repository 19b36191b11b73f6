#include "kernels/built_in_kernels.hpp"

#include <filesystem>
#include <memory>
#include <system_error>
#include <utility>

namespace iblkit::kernels {
namespace {

thread_local bool builtInIgnored = false;
thread_local KernelCompileCounter* counterInUse = nullptr;

// <the program's folder>/kernels: the build tree's tools/iblkit, the installed libexec/iblkit.
std::filesystem::path builtInKernelFolder() {
    std::error_code error;
    const auto program = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : program.parent_path() / "kernels";
}

// Opened once; null where the program has no store beside it.
CompiledKernelCache* builtInStore() {
    static const std::unique_ptr<CompiledKernelCache> store = []() -> std::unique_ptr<CompiledKernelCache> {
        const auto folder = builtInKernelFolder();
        std::error_code error;
        if (folder.empty() || !std::filesystem::is_directory(folder / "objects", error)) return nullptr;
        return std::make_unique<CompiledKernelCache>(folder, cache::ContentStore::Access::ReadOnly);
    }();
    return store.get();
}

} // namespace

std::optional<KernelProgram> builtInKernel(const compiler::CompileOptions& options) {
    auto* store = builtInIgnored ? nullptr : builtInStore();
    return store ? store->find(options) : std::nullopt;
}

WithoutBuiltInKernels::WithoutBuiltInKernels() : previous_(std::exchange(builtInIgnored, true)) {}

WithoutBuiltInKernels::~WithoutBuiltInKernels() { builtInIgnored = previous_; }

CountKernelCompiles::CountKernelCompiles(KernelCompileCounter* counter) : previous_(std::exchange(counterInUse, counter)) {}

CountKernelCompiles::~CountKernelCompiles() { counterInUse = previous_; }

KernelCompileCounter* kernelCompileCounterInUse() { return counterInUse; }

} // namespace iblkit::kernels
