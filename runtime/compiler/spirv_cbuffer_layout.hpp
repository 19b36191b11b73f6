#pragma once

#include <set>
#include <string>

namespace iblkit::compiler {

class SpirvModule;

// A constant buffer whose Direct3D packing Vulkan's uniform layout cannot hold, refused by name.
// HLSL packs a member into the unused end of the register an array, a struct or a matrix before
// it ends in (`float weights[3]; float scale;` puts scale at byte 36); a Vulkan uniform block
// cannot place a member inside the array before it, and glslang moves it (to 48), so the
// Direct3D application's bytes would be read at the wrong place. Every cbuffer's (and
// ConstantBuffer<T>'s) members are laid out by HLSL's packing rules and compared with the
// offsets in the SPIR-V; the first that differs throws CompileError naming the block, the
// member, both offsets and what to write instead. A member `packedMembers` names was placed by
// packoffset, where glslang puts it too.
void refuseUnportableConstantBufferPacking(const SpirvModule& module, const std::set<std::string>& packedMembers,
                                           const std::string& sourceName);

} // namespace iblkit::compiler
