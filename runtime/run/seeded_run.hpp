#pragma once

#include "compile_options.hpp"
#include "reflection.hpp"
#include "run_file.hpp"

#include <string>
#include <variant>

namespace iblkit::run {

// A run of a shader that has no run file: every resource made and filled with seeded values in
// its valid range (floats in [0, 1), integers in [0, 4), positions in [-0.9, 0.9]), so that the
// paths of RunApi::All can be compared on what it writes. A compute shader is dispatched as 2x2x1
// groups over 64x64 storage images and buffers of 4096 elements per element of their declared
// size; a vertex shader alone draws two seeded triangles into a pixel shader the kit writes to pass
// its outputs on to targets; a pixel shader alone is drawn over a 16x16 target by a full-screen
// triangle whose vertex shader the kit writes to give it every input. No expectations: the paths
// are compared. Either the run file's contents, or why the shader cannot be run this way.
std::variant<RunSpec, std::string> seededRun(const compiler::CompileOptions& options, const compiler::ShaderReflection& reflection);

} // namespace iblkit::run
