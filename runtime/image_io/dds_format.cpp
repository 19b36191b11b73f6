#include "dds_format.hpp"

namespace iblkit::image_io::dds {

uint32_t dxgiFormatOf(PixelFormat format) {
    switch (format) {
    case PixelFormat::Rgba16Float: return 10; // DXGI_FORMAT_R16G16B16A16_FLOAT
    case PixelFormat::Rgba32Float: return 2;  // DXGI_FORMAT_R32G32B32A32_FLOAT
    case PixelFormat::Rg16Float: return 34;   // DXGI_FORMAT_R16G16_FLOAT
    case PixelFormat::Rg32Float: return 16;   // DXGI_FORMAT_R32G32_FLOAT
    }
    return 0;
}

std::optional<PixelFormat> formatOfDxgiFormat(uint32_t dxgiFormat) {
    for (auto format : {PixelFormat::Rgba16Float, PixelFormat::Rgba32Float, PixelFormat::Rg16Float, PixelFormat::Rg32Float})
        if (dxgiFormatOf(format) == dxgiFormat) return format;
    return std::nullopt;
}

std::optional<PixelFormat> formatOfLegacyFourCc(uint32_t fourCc) {
    // D3D9 names list channels from the most significant bits, so A16B16G16R16F is R, G, B, A in memory.
    switch (fourCc) {
    case 113: return PixelFormat::Rgba16Float; // D3DFMT_A16B16G16R16F
    case 116: return PixelFormat::Rgba32Float; // D3DFMT_A32B32G32R32F
    case 112: return PixelFormat::Rg16Float;   // D3DFMT_G16R16F
    case 115: return PixelFormat::Rg32Float;   // D3DFMT_G32R32F
    }
    return std::nullopt;
}

} // namespace iblkit::image_io::dds
