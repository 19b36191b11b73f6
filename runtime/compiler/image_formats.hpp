#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace iblkit::compiler {

// A storage image format under its three names. spirvFormat is the spv::ImageFormat value.
struct ImageFormatInfo {
    unsigned spirvFormat;
    std::string_view glslName;   // "rg16f", as in GLSL layout qualifiers and glslang
    std::string_view vulkanName; // "R16G16_SFLOAT", VkFormat without the prefix
    // The ESSL 3.10 format that can stand in for it (4 channels of the same component type
    // and size), or empty when ESSL 3.10 has none.
    std::string_view esslStandIn;
};

const ImageFormatInfo* findImageFormat(unsigned spirvFormat);
const ImageFormatInfo* findImageFormatByGlslName(std::string_view glslName);
// A format as [[vk::image_format("...")]] spells it (DXC's names: glslang's without '_', and
// "r11g11b10f").
const ImageFormatInfo* findImageFormatByAttributeName(std::string_view attributeName);
bool isEssl310Format(std::string_view glslName);

} // namespace iblkit::compiler
