#pragma once

#include "reflection.hpp"

#include <string>

namespace iblkit::compiler {

// Direct3D's limits on a compute shader's [numthreads], which DXC holds every shader to: each
// dimension at least 1, x and y at most 1024, z at most 64, and at most 1024 threads in all. A
// group past them would reach the device only to fail there (lavapipe crashed on
// numthreads(1024, 1024, 64) and dispatched "workgroup 0x1x1"). Throws CompileError naming the
// attribute and the limit. A size given by specialization constants is the device's to judge.
void requireDirect3DThreadGroup(const ShaderReflection& reflection, const std::string& sourceName);

} // namespace iblkit::compiler
