#pragma once

#include <vulkan/vulkan.hpp>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace iblkit::vulkan {

enum class ComponentKind { Float, UNorm, UInt, SInt };

// A format the runtime can create, fill from floats and read back to floats.
struct TexelFormat {
    vk::Format format;
    std::string_view name; // "R16G16_SFLOAT": VkFormat without its prefix
    uint32_t channels;
    uint32_t bytesPerChannel;
    ComponentKind kind;

    uint32_t bytesPerTexel() const { return channels * bytesPerChannel; }
    bool depth() const { return format == vk::Format::eD32Sfloat; }
    vk::ImageAspectFlags aspect() const { return depth() ? vk::ImageAspectFlagBits::eDepth : vk::ImageAspectFlagBits::eColor; }
};

// Throws VulkanError naming the supported formats.
const TexelFormat& texelFormatNamed(std::string_view name);
// R32G32B32A32_SFLOAT: what every float cube and table of the kit is made of.
const TexelFormat& rgba32Float();
std::string supportedFormatNames();

// Converts channel values (channels per texel, in order) to the format's bytes and back.
// Halves round to nearest even; values out of a half's range become infinities, which the
// caller checks for where it matters. In doubles, every 32-bit integer is exact.
void encodeTexels(const TexelFormat& format, std::span<const float> values, std::span<std::byte> bytes);
void encodeTexels(const TexelFormat& format, std::span<const double> values, std::span<std::byte> bytes);
void decodeTexels(const TexelFormat& format, std::span<const std::byte> bytes, std::span<float> values);
void decodeTexels(const TexelFormat& format, std::span<const std::byte> bytes, std::span<double> values);

// For an integer format, why `value` cannot be one of its components ("-1 is not an unsigned
// 32-bit integer"); "" when it can, and for every other format.
std::string integerValueProblem(const TexelFormat& format, double value);

} // namespace iblkit::vulkan
