#pragma once

#include "kernels/compiled_kernel_cache.hpp"

#include <atomic>
#include <cstddef>
#include <optional>

namespace iblkit::kernels {

// The kernels compiled when the program was built: `iblkit-program precompile-kernels` keeps the
// bake's in a content store beside the program, in its folder `kernels` (the build tree's
// tools/iblkit/kernels, the installed libexec/iblkit/kernels). compileKernel looks there first and
// never writes there. Its entries are keyed as every compiled kernel's (compiled_kernel_cache.hpp),
// the program's build among the rest, so a store another build made is never read: each of its
// entries is a miss, and the kernel is compiled as without one.
//
// The built-in store's kernel for `options`, if it holds one; never one where the program has no
// store beside it (a test program, or a program using the library), nor on a thread where a
// WithoutBuiltInKernels lives.
std::optional<KernelProgram> builtInKernel(const compiler::CompileOptions& options);

// While one lives, compileKernel on this thread ignores the built-in kernels: what makes a store
// compiles every kernel, whatever the program already has.
class WithoutBuiltInKernels {
public:
    WithoutBuiltInKernels();
    ~WithoutBuiltInKernels();
    WithoutBuiltInKernels(const WithoutBuiltInKernels&) = delete;
    WithoutBuiltInKernels& operator=(const WithoutBuiltInKernels&) = delete;

private:
    bool previous_;
};

// What compileKernel did: kernels taken from the built-in store, and kernels compiled from their
// source (with or without a cache to keep them in).
struct KernelCompileCounts {
    size_t builtIn = 0, compiled = 0;
};
struct KernelCompileCounter {
    std::atomic<size_t> builtIn{0}, compiled{0};
    KernelCompileCounts counts() const { return {builtIn.load(), compiled.load()}; }
};

// While one lives, compileKernel on this thread counts in `counter` (null: nowhere); the one in
// use before it is restored when it goes. A thread that compiles for another takes the other's
// kernelCompileCounterInUse() (BakeKernels does for its workers), so a bake counts its own kernels
// whatever else the process compiles.
class CountKernelCompiles {
public:
    explicit CountKernelCompiles(KernelCompileCounter* counter);
    ~CountKernelCompiles();
    CountKernelCompiles(const CountKernelCompiles&) = delete;
    CountKernelCompiles& operator=(const CountKernelCompiles&) = delete;

private:
    KernelCompileCounter* previous_;
};
KernelCompileCounter* kernelCompileCounterInUse();

} // namespace iblkit::kernels
