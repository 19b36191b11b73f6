#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace iblkit::compiler {

// Gives the named storage images the stated formats (GLSL names: "rg16f", "rgba8", ...) — the
// per-resource counterpart of DXC's [[vk::image_format]], which glslang ignores. Works on
// legalized SPIR-V, where every image is loaded straight from its global variable: the
// variable gets its own image type (shared types are split) and the capability an extended
// format needs. Throws CompileError for an unknown format or resource, a resource that is not
// a storage image, or a format with more channels than the texels the shader writes
// (RWTexture2D<float2> cannot hold rgba16f) or another component type.
std::vector<uint32_t> applyImageFormats(const std::vector<uint32_t>& spirv,
                                        const std::map<std::string, std::string>& formats,
                                        const std::string& sourceName);

} // namespace iblkit::compiler
