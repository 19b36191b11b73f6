#pragma once

namespace iblkit::compiler {

class SpirvModule;

// Vulkan requires an image write to give at least as many components as the image's format
// has (VUID-RuntimeSpirv-OpImageWrite-07112): RWTexture2D<float3> is rgba32f, and glslang
// writes its float3 as it is. Every texel narrower than its storage image's format is widened
// to four components here, the missing colour channels 0 and alpha 1, as a texture read fills
// them. Reads need nothing: they always return four.
// Returns whether a write was widened.
bool widenStorageImageWrites(SpirvModule& module);

} // namespace iblkit::compiler
