#pragma once

#include <map>
#include <string>

namespace iblkit::compiler {

class SpirvModule;

// Gives the named storage images the stated formats (GLSL names: "rg16f", "rgba8", ...) — the
// per-resource counterpart of DXC's [[vk::image_format]], which glslang ignores. Works on
// legalized SPIR-V, where every image is loaded straight from its global variable: the
// variable gets its own image type (shared types are split) and the capability an extended
// format needs. A format wider than the texels the shader writes is fine: the writes are widened
// after (spirv_texel_widening.hpp). Throws CompileError for an unknown format or resource, a
// resource that is not a storage image, or another component type (float/int/uint).
void applyImageFormats(SpirvModule& module, const std::map<std::string, std::string>& formats,
                       const std::string& sourceName);

} // namespace iblkit::compiler
