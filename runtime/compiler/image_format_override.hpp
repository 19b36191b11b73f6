#pragma once

#include <map>
#include <string>

namespace glslang {
class TIntermediate;
}

namespace iblkit::compiler {

// Gives the named storage images the stated formats (glslang's names: "rg16f", "rgba8", ...)
// before SPIR-V is generated — the per-resource counterpart of DXC's [[vk::image_format]],
// which glslang ignores. Throws CompileError for an unknown format or resource, a resource
// that is not a storage image, or a format with more channels than the HLSL element type
// (RWTexture2D<float2> cannot hold rgba16f) or another component type.
void overrideImageFormats(glslang::TIntermediate& intermediate, const std::map<std::string, std::string>& formats,
                          const std::string& sourceName);

} // namespace iblkit::compiler
