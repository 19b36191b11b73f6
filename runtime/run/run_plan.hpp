#pragma once

#include "run_engine.hpp"

namespace iblkit::run {

// Compiles the run file's shaders (HLSL, or SPIR-V for a dispatch). Throws RunError or
// compiler::CompileError.
RunPrograms loadPrograms(const RunSpec& spec);
// The same shaders through their HLSL form: each written by SPIRV-Cross and compiled again by the
// kit, as a port would take them. Throws compiler::CompileError when the form is refused or does
// not compile.
RunPrograms hlslFormPrograms(const RunSpec& spec, const RunPrograms& programs);

// Everything a run needs that no API decides, checked against the shaders before any device
// work: every failure is RunError("<run file>: error: <key>: <why>").
struct RunPlan {
    std::vector<ResourcePlan> resources;
    std::optional<DrawPlan> draw;
    std::vector<std::byte> pushConstants; // empty when the shaders have none
    // What the shaders can write, by the name expectations and saves use: RW buffers, storage
    // images and targets. The APIs are compared on these.
    std::vector<std::string> written;
};
RunPlan planRun(const RunSpec& spec, const RunPrograms& programs);
// The draw's vertex attributes and targets, bound to the shaders' semantics (draw_plan.cpp).
DrawPlan planDraw(const RunSpec& spec, const RunPrograms& programs);
// The vertex shader's inputs other than system values, one per location: a matrix or array input
// of semantic NAMEn takes NAMEn, NAMEn+1, ... for its rows, as Direct3D's input layout gives them.
std::vector<compiler::Varying> inputSlots(const compiler::ShaderReflection& vertex);

// The buffer element format of a "buffer" resource.
const vulkan::TexelFormat& bufferFormat(const ResourceSpec& spec);

// The values of a fill, a list or a file, for a resource or an expectation of `count` values;
// `fail` reports a problem under `where`.
std::vector<double> valuesOf(const RunSpec& spec, const ValueSource& source, const std::string& where,
                             const vulkan::TexelFormat& format, size_t count, uint32_t channels);

// What the run reads: no save may be one of them.
std::vector<std::filesystem::path> inputFiles(const RunSpec& spec);

} // namespace iblkit::run
