#pragma once

namespace iblkit::compiler {

class SpirvModule;

// HLSL's WavePrefixSum, WavePrefixProduct and WavePrefixCountBits are exclusive scans (the
// current lane is left out), but glslang 11 emits them as InclusiveScan (glslang issue 2929),
// so every lane got its own value added. HLSL has no inclusive scan at all, so every scan in a
// module from HLSL is made exclusive here.
// Returns whether a scan was changed.
bool makeWavePrefixScansExclusive(SpirvModule& module);

} // namespace iblkit::compiler
