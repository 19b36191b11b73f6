#pragma once

namespace iblkit::compiler {

class SpirvModule;

// A storage image the shader only writes gets NonReadable, one it only reads NonWritable (glslang
// states neither for an RWTexture), so that the GLSL and ESSL forms declare it writeonly or
// readonly: ESSL 3.10 requires one of them for every format but r32f, r32i and r32ui.
// Returns whether a decoration was added.
bool decorateStorageImageAccess(SpirvModule& module);

} // namespace iblkit::compiler
