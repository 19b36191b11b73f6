#pragma once

#include <iblkit/error.hpp>

namespace iblkit::api {

// Throws the exception being handled again as Error: the compiler's and the lowering's as
// CompileFailed, Vulkan's as DeviceFailed, an Error and std::bad_alloc as they are, and every other
// as `kind`, the step's: what the internal types do not tell apart, the step does (a BakeError
// while the settings are checked is BadInput, while the device works BakeFailed). The message is
// kept as it is.
[[noreturn]] void rethrowAs(ErrorKind kind);

// `step()`, its exceptions rethrown by rethrowAs(kind).
template <typename Step>
auto translated(ErrorKind kind, Step&& step) -> decltype(step()) {
    try {
        return step();
    } catch (...) {
        rethrowAs(kind);
    }
}

} // namespace iblkit::api
