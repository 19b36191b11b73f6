#include "texel_format.hpp"

#include "half_float.hpp"
#include "vulkan_error.hpp"

#include <array>
#include <cmath>
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
};

float decodeOne(const TexelFormat& format, const std::byte* bytes) {
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
    case ComponentKind::UNorm: return std::to_integer<uint8_t>(bytes[0]) / 255.0f;
    case ComponentKind::UInt: {
        uint32_t value;
        std::memcpy(&value, bytes, 4);
        return static_cast<float>(value);
    }
    case ComponentKind::SInt: {
        int32_t value;
        std::memcpy(&value, bytes, 4);
        return static_cast<float>(value);
    }
    }
    return 0;
}

void encodeOne(const TexelFormat& format, float value, std::byte* bytes) {
    switch (format.kind) {
    case ComponentKind::Float:
        if (format.bytesPerChannel == 2) {
            const uint16_t half = numeric::toHalfBits(value);
            std::memcpy(bytes, &half, 2);
        } else {
            std::memcpy(bytes, &value, 4);
        }
        return;
    case ComponentKind::UNorm:
        bytes[0] = static_cast<std::byte>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
        return;
    case ComponentKind::UInt: {
        const auto integer = static_cast<uint32_t>(value);
        std::memcpy(bytes, &integer, 4);
        return;
    }
    case ComponentKind::SInt: {
        const auto integer = static_cast<int32_t>(value);
        std::memcpy(bytes, &integer, 4);
        return;
    }
    }
}

} // namespace

const TexelFormat& texelFormatNamed(std::string_view name) {
    for (const auto& format : kFormats)
        if (format.name == name) return format;
    throw VulkanError("unsupported format '" + std::string(name) + "' (supported: " + supportedFormatNames() + ")");
}

std::string supportedFormatNames() {
    std::string names;
    for (const auto& format : kFormats) names += (names.empty() ? "" : ", ") + std::string(format.name);
    return names;
}

void encodeTexels(const TexelFormat& format, std::span<const float> values, std::span<std::byte> bytes) {
    for (size_t i = 0; i < values.size(); ++i) encodeOne(format, values[i], bytes.data() + i * format.bytesPerChannel);
}

void decodeTexels(const TexelFormat& format, std::span<const std::byte> bytes, std::span<float> values) {
    for (size_t i = 0; i < values.size(); ++i) values[i] = decodeOne(format, bytes.data() + i * format.bytesPerChannel);
}

} // namespace iblkit::vulkan
