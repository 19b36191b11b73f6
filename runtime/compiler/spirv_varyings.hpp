#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::compiler {

class SpirvModule;

// One input or output of an entry point, as its HLSL signature names it.
struct Varying {
    std::string semantic;      // upper case, with its index: "POSITION0", "TEXCOORD1", "SV_TARGET0", "SV_POSITION"
    bool input = true;
    int32_t location = -1;     // -1 for a built-in
    std::string builtIn;       // "Position", "FragDepth", "VertexIndex", ...; empty for a user varying
    std::string componentType; // "float", "int" or "uint"
    uint32_t components = 1;
    uint32_t locations = 1;    // more than one for an array or matrix
    bool matrix = false;       // a matrix: each location one HLSL row, as glslang lays it out
};

// "TEXCOORD" -> "TEXCOORD0", "sv_target" -> "SV_TARGET0": a semantic as Direct3D matches it
// (case-insensitive, index 0 when none is written). System values that take no index
// (SV_POSITION, SV_DEPTH, SV_VERTEXID) are only upper-cased.
std::string canonicalSemantic(const std::string& semantic);

// The entry point's inputs and outputs, read from glslang's SPIR-V before legalization strips
// the UserSemantic decorations hlsl_functionality1 writes.
std::vector<Varying> readVaryings(const SpirvModule& module);

// The warning for a vertex shader's matrix input, which glslang reads by rows (a location per
// row) where Direct3D's input layout gives a column-major matrix's columns; "" when none is.
std::string matrixInputWarning(const std::vector<Varying>& varyings, bool vertexShader, const std::string& sourceName);

} // namespace iblkit::compiler
