#pragma once

#include "buffer.hpp"
#include "image.hpp"

#include <span>
#include <string>

namespace iblkit::vulkan {

// A layout with the accesses and stages that use an image in it (internal to the image files).
struct LayoutUse {
    vk::ImageLayout layout;
    vk::AccessFlags access;
    vk::PipelineStageFlags stages;
};

// Between copies the image rests in GENERAL, where shaders sample and write it.
inline const LayoutUse kResting{vk::ImageLayout::eGeneral, vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite,
                                vk::PipelineStageFlagBits::eComputeShader};
inline const LayoutUse kCopyingFrom{vk::ImageLayout::eTransferSrcOptimal, vk::AccessFlagBits::eTransferRead,
                                    vk::PipelineStageFlagBits::eTransfer};
inline const LayoutUse kCopyingTo{vk::ImageLayout::eTransferDstOptimal, vk::AccessFlagBits::eTransferWrite,
                                  vk::PipelineStageFlagBits::eTransfer};

void transition(const vk::raii::CommandBuffer& commands, const Image& image, const LayoutUse& from, const LayoutUse& to);

// The regions of an image copied into a new host-visible buffer of `bytes`, for the host to read.
Buffer readback(const VulkanContext& context, const Image& image, std::span<const vk::BufferImageCopy> regions, size_t bytes);

// The other way: `bytes` through a new staging buffer into the regions of an image.
void writeRegions(const VulkanContext& context, Image& image, std::span<const vk::BufferImageCopy> regions,
                  std::span<const std::byte> bytes, const std::string& stagingName);

} // namespace iblkit::vulkan
