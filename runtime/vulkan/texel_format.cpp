#include "texel_format.hpp"

#include "half_float.hpp"
#include "image_formats.hpp"
#include "vulkan_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace iblkit::vulkan {
namespace {

constexpr std::array kFormats{
    TexelFormat{vk::Format::eR32Sfloat, "R32_SFLOAT", 1, 4, ComponentKind::Float},
    TexelFormat{vk::Format::eR32G32Sfloat, "R32G32_SFLOAT", 2, 4, ComponentKind::Float},
    TexelFormat{vk::Format::eR32G32B32A32Sfloat, "R32G32B32A32_SFLOAT", 4, 4, ComponentKind::Float},
    TexelFormat{vk::Format::eR16Sfloat, "R16_SFLOAT", 1, 2, ComponentKind::Float},
    TexelFormat{vk::Format::eR16G16Sfloat, "R16G16_SFLOAT", 2, 2, ComponentKind::Float},
    TexelFormat{vk::Format::eR16G16B16A16Sfloat, "R16G16B16A16_SFLOAT", 4, 2, ComponentKind::Float},
    TexelFormat{vk::Format::eR8G8B8A8Unorm, "R8G8B8A8_UNORM", 4, 1, ComponentKind::UNorm},
    TexelFormat{vk::Format::eR32Uint, "R32_UINT", 1, 4, ComponentKind::UInt},
    TexelFormat{vk::Format::eR32Sint, "R32_SINT", 1, 4, ComponentKind::SInt},
    TexelFormat{vk::Format::eR32G32Uint, "R32G32_UINT", 2, 4, ComponentKind::UInt},
    TexelFormat{vk::Format::eR32G32Sint, "R32G32_SINT", 2, 4, ComponentKind::SInt},
    TexelFormat{vk::Format::eR32G32B32A32Uint, "R32G32B32A32_UINT", 4, 4, ComponentKind::UInt},
    TexelFormat{vk::Format::eR32G32B32A32Sint, "R32G32B32A32_SINT", 4, 4, ComponentKind::SInt},
    TexelFormat{vk::Format::eD32Sfloat, "D32_SFLOAT", 1, 4, ComponentKind::Float},
};

double decodeOne(const TexelFormat& format, const std::byte* bytes) {
    switch (format.kind) {
    case ComponentKind::Float:
        if (format.bytesPerChannel == 2) {
            uint16_t half;
            std::memcpy(&half, bytes, 2);
            return numeric::fromHalfBits(half);
        } else {
            float value;
            std::memcpy(&value, bytes, 4);
            return value;
        }
    case ComponentKind::UNorm: return std::to_integer<uint8_t>(bytes[0]) / 255.0f; // the float a shader reads
    case ComponentKind::UInt: {
        uint32_t value;
        std::memcpy(&value, bytes, 4);
        return value;
    }
    case ComponentKind::SInt: {
        int32_t value;
        std::memcpy(&value, bytes, 4);
        return value;
    }
    }
    return 0;
}

// Integers out of the format's range are clamped, and NaN is 0 (callers that take values from
// users refuse them first: integerValueProblem).
void encodeOne(const TexelFormat& format, double value, std::byte* bytes) {
    if (std::isnan(value) && format.kind != ComponentKind::Float) value = 0; // casting NaN to an integer is undefined
    switch (format.kind) {
    case ComponentKind::Float:
        if (format.bytesPerChannel == 2) {
            const uint16_t half = numeric::toHalfBits(static_cast<float>(value));
            std::memcpy(bytes, &half, 2);
        } else {
            const auto single = static_cast<float>(value);
            std::memcpy(bytes, &single, 4);
        }
        return;
    case ComponentKind::UNorm:
        bytes[0] = static_cast<std::byte>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
        return;
    case ComponentKind::UInt: {
        const auto integer = static_cast<uint32_t>(std::clamp(value, 0.0, double(UINT32_MAX)));
        std::memcpy(bytes, &integer, 4);
        return;
    }
    case ComponentKind::SInt: {
        const auto integer = static_cast<int32_t>(std::clamp(value, double(INT32_MIN), double(INT32_MAX)));
        std::memcpy(bytes, &integer, 4);
        return;
    }
    }
}

// 32-bit float components are stored as they are: a whole image is one copy, not a conversion per
// channel (at 1024², a cube's mip 0 took 0.23 s a way).
bool isSingleFloat(const TexelFormat& format) { return format.kind == ComponentKind::Float && format.bytesPerChannel == 4; }

void copySingles(const void* from, void* to, size_t count) { std::memcpy(to, from, count * sizeof(float)); }

} // namespace

const TexelFormat& texelFormatNamed(std::string_view name) {
    for (const auto& format : kFormats)
        if (format.name == name) return format;
    // The short names of GLSL and [[vk::image_format]]: "rgba32f", and "d32f" for depth.
    const auto* known = compiler::findImageFormatByGlslName(name);
    const std::string_view vulkanName = name == "d32f" ? "D32_SFLOAT" : known ? known->vulkanName : "";
    for (const auto& format : kFormats)
        if (!vulkanName.empty() && format.name == vulkanName) return format;
    throw VulkanError("unsupported format '" + std::string(name) + "' (supported: " + supportedFormatNames() + ")");
}

const TexelFormat& rgba32Float() {
    static const TexelFormat& format = texelFormatNamed("R32G32B32A32_SFLOAT");
    return format;
}

std::string supportedFormatNames() {
    std::string names;
    for (const auto& format : kFormats) names += (names.empty() ? "" : ", ") + std::string(format.name);
    return names;
}

void encodeTexels(const TexelFormat& format, std::span<const float> values, std::span<std::byte> bytes) {
    if (isSingleFloat(format)) return copySingles(values.data(), bytes.data(), values.size());
    for (size_t i = 0; i < values.size(); ++i) encodeOne(format, values[i], bytes.data() + i * format.bytesPerChannel);
}

void encodeTexels(const TexelFormat& format, std::span<const double> values, std::span<std::byte> bytes) {
    for (size_t i = 0; i < values.size(); ++i) encodeOne(format, values[i], bytes.data() + i * format.bytesPerChannel);
}

void decodeTexels(const TexelFormat& format, std::span<const std::byte> bytes, std::span<float> values) {
    if (isSingleFloat(format)) return copySingles(bytes.data(), values.data(), values.size());
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = static_cast<float>(decodeOne(format, bytes.data() + i * format.bytesPerChannel));
}

void decodeTexels(const TexelFormat& format, std::span<const std::byte> bytes, std::span<double> values) {
    for (size_t i = 0; i < values.size(); ++i) values[i] = decodeOne(format, bytes.data() + i * format.bytesPerChannel);
}

std::string integerValueProblem(const TexelFormat& format, double value) {
    if (format.kind != ComponentKind::UInt && format.kind != ComponentKind::SInt) return "";
    const bool unsignedInteger = format.kind == ComponentKind::UInt;
    const double least = unsignedInteger ? 0.0 : double(INT32_MIN), most = unsignedInteger ? double(UINT32_MAX) : double(INT32_MAX);
    if (value == std::floor(value) && value >= least && value <= most) return "";
    char text[64];
    std::snprintf(text, sizeof text, "%.17g is not a%s 32-bit integer", value, unsignedInteger ? "n unsigned" : " signed");
    return text;
}

} // namespace iblkit::vulkan
