#include "thread_group_limits.hpp"

#include "compile_error.hpp"

#include <cstdint>

namespace iblkit::compiler {

void requireDirect3DThreadGroup(const ShaderReflection& reflection, const std::string& sourceName) {
    if (reflection.stage != ShaderStage::Compute || !reflection.workgroupSizeFixed) return;
    const auto& [x, y, z] = reflection.workgroupSize;
    const auto refuse = [&](const std::string& why) {
        throw CompileError(sourceName + ": error: [numthreads(" + std::to_string(x) + ", " + std::to_string(y) + ", " +
                           std::to_string(z) + ")] on '" + reflection.entryPoint + "': " + why +
                           " (Direct3D's limit, which DXC holds shaders to)");
    };
    if (x == 0 || y == 0 || z == 0) refuse("every dimension must be at least 1");
    if (x > 1024 || y > 1024) refuse("x and y are at most 1024");
    if (z > 64) refuse("z is at most 64");
    const uint64_t threads = uint64_t(x) * y * z;
    if (threads > 1024) refuse(std::to_string(threads) + " threads in a group, where at most 1024 are allowed");
}

} // namespace iblkit::compiler
