#pragma once

namespace iblkit::compiler {

class SpirvModule;

// NonUniformResourceIndex(i), which glslang's HLSL frontend lacks, honoured on the SPIR-V: the
// lowering leaves the bare index, and here every access into an array of resources at an index
// that is not a constant is decorated NonUniform, with the loads and sampled images made from
// it, and the module declares the capabilities and extension that allow it. After glslang one
// index can no longer be told from another, so this is conservative: an index the shader did not
// mark is decorated too, which is never wrong, only possibly slower on a GPU.
// Returns whether a decoration was added.
bool decorateNonUniformResourceIndexing(SpirvModule& module);

} // namespace iblkit::compiler
