#include "image_formats.hpp"

#include <spirv_cross/spirv.hpp>

#include <array>
#include <string>

namespace iblkit::compiler {
namespace {

constexpr std::array kFormats{
    ImageFormatInfo{spv::ImageFormatRgba32f, "rgba32f", "R32G32B32A32_SFLOAT", "rgba32f"},
    ImageFormatInfo{spv::ImageFormatRgba16f, "rgba16f", "R16G16B16A16_SFLOAT", "rgba16f"},
    ImageFormatInfo{spv::ImageFormatR32f, "r32f", "R32_SFLOAT", "r32f"},
    ImageFormatInfo{spv::ImageFormatRgba8, "rgba8", "R8G8B8A8_UNORM", "rgba8"},
    ImageFormatInfo{spv::ImageFormatRgba8Snorm, "rgba8_snorm", "R8G8B8A8_SNORM", "rgba8_snorm"},
    ImageFormatInfo{spv::ImageFormatRg32f, "rg32f", "R32G32_SFLOAT", "rgba32f"},
    ImageFormatInfo{spv::ImageFormatRg16f, "rg16f", "R16G16_SFLOAT", "rgba16f"},
    ImageFormatInfo{spv::ImageFormatR11fG11fB10f, "r11f_g11f_b10f", "B10G11R11_UFLOAT_PACK32", ""},
    ImageFormatInfo{spv::ImageFormatR16f, "r16f", "R16_SFLOAT", "rgba16f"},
    ImageFormatInfo{spv::ImageFormatRgba16, "rgba16", "R16G16B16A16_UNORM", ""},
    ImageFormatInfo{spv::ImageFormatRgb10A2, "rgb10_a2", "A2B10G10R10_UNORM_PACK32", ""},
    ImageFormatInfo{spv::ImageFormatRg16, "rg16", "R16G16_UNORM", ""},
    ImageFormatInfo{spv::ImageFormatRg8, "rg8", "R8G8_UNORM", "rgba8"},
    ImageFormatInfo{spv::ImageFormatR16, "r16", "R16_UNORM", ""},
    ImageFormatInfo{spv::ImageFormatR8, "r8", "R8_UNORM", "rgba8"},
    ImageFormatInfo{spv::ImageFormatRgba16Snorm, "rgba16_snorm", "R16G16B16A16_SNORM", ""},
    ImageFormatInfo{spv::ImageFormatRg16Snorm, "rg16_snorm", "R16G16_SNORM", ""},
    ImageFormatInfo{spv::ImageFormatRg8Snorm, "rg8_snorm", "R8G8_SNORM", "rgba8_snorm"},
    ImageFormatInfo{spv::ImageFormatR16Snorm, "r16_snorm", "R16_SNORM", ""},
    ImageFormatInfo{spv::ImageFormatR8Snorm, "r8_snorm", "R8_SNORM", "rgba8_snorm"},
    ImageFormatInfo{spv::ImageFormatRgba32i, "rgba32i", "R32G32B32A32_SINT", "rgba32i"},
    ImageFormatInfo{spv::ImageFormatRgba16i, "rgba16i", "R16G16B16A16_SINT", "rgba16i"},
    ImageFormatInfo{spv::ImageFormatRgba8i, "rgba8i", "R8G8B8A8_SINT", "rgba8i"},
    ImageFormatInfo{spv::ImageFormatR32i, "r32i", "R32_SINT", "r32i"},
    ImageFormatInfo{spv::ImageFormatRg32i, "rg32i", "R32G32_SINT", "rgba32i"},
    ImageFormatInfo{spv::ImageFormatRg16i, "rg16i", "R16G16_SINT", "rgba16i"},
    ImageFormatInfo{spv::ImageFormatRg8i, "rg8i", "R8G8_SINT", "rgba8i"},
    ImageFormatInfo{spv::ImageFormatR16i, "r16i", "R16_SINT", "rgba16i"},
    ImageFormatInfo{spv::ImageFormatR8i, "r8i", "R8_SINT", "rgba8i"},
    ImageFormatInfo{spv::ImageFormatRgba32ui, "rgba32ui", "R32G32B32A32_UINT", "rgba32ui"},
    ImageFormatInfo{spv::ImageFormatRgba16ui, "rgba16ui", "R16G16B16A16_UINT", "rgba16ui"},
    ImageFormatInfo{spv::ImageFormatRgba8ui, "rgba8ui", "R8G8B8A8_UINT", "rgba8ui"},
    ImageFormatInfo{spv::ImageFormatR32ui, "r32ui", "R32_UINT", "r32ui"},
    ImageFormatInfo{spv::ImageFormatRgb10a2ui, "rgb10_a2ui", "A2B10G10R10_UINT_PACK32", ""},
    ImageFormatInfo{spv::ImageFormatRg32ui, "rg32ui", "R32G32_UINT", "rgba32ui"},
    ImageFormatInfo{spv::ImageFormatRg16ui, "rg16ui", "R16G16_UINT", "rgba16ui"},
    ImageFormatInfo{spv::ImageFormatRg8ui, "rg8ui", "R8G8_UINT", "rgba8ui"},
    ImageFormatInfo{spv::ImageFormatR16ui, "r16ui", "R16_UINT", "rgba16ui"},
    ImageFormatInfo{spv::ImageFormatR8ui, "r8ui", "R8_UINT", "rgba8ui"},
};

} // namespace

const ImageFormatInfo* findImageFormat(unsigned spirvFormat) {
    for (const auto& format : kFormats)
        if (format.spirvFormat == spirvFormat) return &format;
    return nullptr;
}

const ImageFormatInfo* findImageFormatByGlslName(std::string_view glslName) {
    for (const auto& format : kFormats)
        if (format.glslName == glslName) return &format;
    return nullptr;
}

const ImageFormatInfo* findImageFormatByAttributeName(std::string_view attributeName) {
    if (attributeName == "r11g11b10f") return findImageFormat(spv::ImageFormatR11fG11fB10f);
    for (const auto& format : kFormats) {
        std::string unseparated(format.glslName);
        std::erase(unseparated, '_');
        if (unseparated == attributeName) return &format;
    }
    return nullptr;
}

bool isEssl310Format(std::string_view glslName) {
    const auto* format = findImageFormatByGlslName(glslName);
    return format && format->esslStandIn == glslName;
}

} // namespace iblkit::compiler
