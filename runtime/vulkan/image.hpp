#pragma once

#include "texel_format.hpp"
#include "timed_submission.hpp"
#include "vulkan_context.hpp"

#include <map>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace iblkit::vulkan {

struct ImageDesc {
    std::string name;
    const TexelFormat* format = nullptr;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t layers = 1; // 6 for a cube
    uint32_t mips = 1;
    bool cube = false;
    bool storage = false; // usable as a storage image (RWTexture*)
    bool attachment = false; // a render target (a depth target for a depth format)
};

// The number of mips of a full chain down to 1x1.
uint32_t fullMipCount(uint32_t width, uint32_t height);

// A 2D image, 2D array or cube with its mips, always in the GENERAL layout, so it can be
// sampled, written by a shader and copied without layout tracking. Texel data crosses the
// API as floats in the order mip, layer (cube face), row, column, channel.
class Image {
public:
    Image(const VulkanContext& context, ImageDesc desc);

    const ImageDesc& desc() const { return desc_; }
    vk::Image handle() const { return *image_; }
    uint32_t mipWidth(uint32_t mip) const;
    uint32_t mipHeight(uint32_t mip) const;
    size_t valueCount() const; // texels of every mip and layer, times channels
    size_t valueOffset(uint32_t mip, uint32_t layer) const; // where a mip's layer starts in that order

    // A view of some mips and layers, made once and kept.
    vk::ImageView view(vk::ImageViewType type, uint32_t baseMip, uint32_t mipCount, uint32_t baseLayer,
                       uint32_t layerCount);

    void upload(const VulkanContext& context, std::span<const float> values);
    void uploadBytes(const VulkanContext& context, std::span<const std::byte> bytes);
    std::vector<float> download(const VulkanContext& context) const;
    // Copies every layer of one mip of `source`, which must have this image's format and
    // that mip's size, into the same mip of this image; the device time is the copy's alone.
    SubmissionTiming copyMipFrom(const VulkanContext& context, const Image& source, uint32_t mip);
    std::vector<std::byte> downloadBytes(const VulkanContext& context) const;

private:
    ImageDesc desc_;
    const vk::raii::Device* device_;
    vk::raii::Image image_{nullptr};
    vk::raii::DeviceMemory memory_{nullptr};
    std::map<std::tuple<vk::ImageViewType, uint32_t, uint32_t, uint32_t, uint32_t>, vk::raii::ImageView> views_;
};

struct SamplerDesc {
    vk::Filter filter = vk::Filter::eLinear;
    vk::SamplerMipmapMode mipmap = vk::SamplerMipmapMode::eLinear;
    vk::SamplerAddressMode address = vk::SamplerAddressMode::eClampToEdge;
};

class Sampler {
public:
    Sampler(const VulkanContext& context, const SamplerDesc& desc);
    vk::Sampler handle() const { return *sampler_; }

private:
    vk::raii::Sampler sampler_;
};

} // namespace iblkit::vulkan
