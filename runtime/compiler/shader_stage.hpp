#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace iblkit::compiler {

enum class ShaderStage { Vertex, TessControl, TessEvaluation, Geometry, Fragment, Compute };

std::string_view stageName(ShaderStage stage);
// Accepts glslang's short names (vert, frag, comp, ...) and the long ones (vertex, pixel, ...).
std::optional<ShaderStage> parseStageName(std::string_view name);

// Whether preprocessed HLSL defines a function named entryPoint (what deduceStage reads).
bool definesEntryPoint(const std::string& preprocessedSource, const std::string& entryPoint);

// Reads the stage from the attributes and semantics of the entry point's definition in
// preprocessed HLSL: [numthreads] is compute, [maxvertexcount] geometry, [domain] with
// [outputcontrolpoints] hull, [domain] alone domain, [shader("...")] names it, and otherwise
// an SV_Target in the signature means pixel and an SV_Position vertex. A mesh shader
// ([outputtopology], out vertices/indices/primitives) and an amplification shader (DispatchMesh)
// are recognized without [shader("...")] and refused by name.
// Throws CompileError when the entry point is missing, its stage is not one of ShaderStage, or
// nothing tells the stage.
ShaderStage deduceStage(const std::string& preprocessedSource, const std::string& entryPoint,
                        const std::string& sourceName);

} // namespace iblkit::compiler
