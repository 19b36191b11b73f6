#include "image.hpp"

#include "buffer.hpp"
#include "image_layout.hpp"
#include "device_memory.hpp"
#include "vulkan_error.hpp"

#include <algorithm>
#include <bit>

namespace iblkit::vulkan {
namespace {

vk::ImageUsageFlags usageOf(const ImageDesc& desc) {
    vk::ImageUsageFlags usage = vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferSrc |
                                vk::ImageUsageFlagBits::eTransferDst;
    if (desc.storage) usage |= vk::ImageUsageFlagBits::eStorage;
    if (desc.attachment)
        usage |= desc.format->depth() ? vk::ImageUsageFlagBits::eDepthStencilAttachment : vk::ImageUsageFlagBits::eColorAttachment;
    return usage;
}

void validate(const VulkanContext& context, const ImageDesc& desc) {
    const auto fail = [&](const std::string& why) { throw VulkanError("image '" + desc.name + "': " + why); };
    if (!desc.format) fail("no format");
    if (desc.width == 0 || desc.height == 0 || desc.layers == 0 || desc.mips == 0) fail("a size of zero");
    if (desc.cube && (desc.layers != 6 || desc.width != desc.height)) fail("a cube has 6 square faces");
    if (desc.mips > fullMipCount(desc.width, desc.height))
        fail(std::to_string(desc.mips) + " mips, but a " + std::to_string(desc.width) + "x" +
             std::to_string(desc.height) + " image has at most " + std::to_string(fullMipCount(desc.width, desc.height)));
    const auto limits = context.physicalDevice().getProperties().limits;
    const uint32_t limit = desc.cube ? limits.maxImageDimensionCube : limits.maxImageDimension2D;
    if (std::max(desc.width, desc.height) > limit)
        fail(std::to_string(desc.width) + "x" + std::to_string(desc.height) + " exceeds the device's limit of " +
             std::to_string(limit));
    if (desc.layers > limits.maxImageArrayLayers) fail("more layers than the device's limit");
    vk::ImageFormatProperties properties;
    try {
        properties = context.physicalDevice().getImageFormatProperties(
            desc.format->format, vk::ImageType::e2D, vk::ImageTiling::eOptimal, usageOf(desc),
            desc.cube ? vk::ImageCreateFlagBits::eCubeCompatible : vk::ImageCreateFlags());
    } catch (const vk::FormatNotSupportedError&) {
        fail("the device does not support " + std::string(desc.format->name) +
             (desc.storage ? " as a storage image" : desc.attachment ? " as a render target" : " as a sampled image"));
    }
    if (desc.width > properties.maxExtent.width || desc.height > properties.maxExtent.height ||
        desc.mips > properties.maxMipLevels || desc.layers > properties.maxArrayLayers)
        fail("the device's limits for " + std::string(desc.format->name) + " are " +
             std::to_string(properties.maxExtent.width) + "x" + std::to_string(properties.maxExtent.height) + ", " +
             std::to_string(properties.maxMipLevels) + " mips, " + std::to_string(properties.maxArrayLayers) + " layers");
}

std::vector<vk::BufferImageCopy> copyRegions(const Image& image) {
    std::vector<vk::BufferImageCopy> regions;
    const auto& desc = image.desc();
    for (uint32_t mip = 0; mip < desc.mips; ++mip)
        regions.emplace_back(image.valueOffset(mip, 0) / desc.format->channels * desc.format->bytesPerTexel(), 0, 0,
                             vk::ImageSubresourceLayers(desc.format->aspect(), mip, 0, desc.layers),
                             vk::Offset3D(0, 0, 0), vk::Extent3D(image.mipWidth(mip), image.mipHeight(mip), 1));
    return regions;
}

vk::ImageSubresourceRange wholeImage(const ImageDesc& desc) {
    return {desc.format->aspect(), 0, desc.mips, 0, desc.layers};
}

} // namespace

void transition(const vk::raii::CommandBuffer& commands, const Image& image, const LayoutUse& from, const LayoutUse& to) {
    const vk::ImageMemoryBarrier barrier(from.access, to.access, from.layout, to.layout, VK_QUEUE_FAMILY_IGNORED,
                                         VK_QUEUE_FAMILY_IGNORED, image.handle(), wholeImage(image.desc()));
    commands.pipelineBarrier(from.stages, to.stages, {}, {}, {}, barrier);
}

Buffer readback(const VulkanContext& context, const Image& image, std::span<const vk::BufferImageCopy> regions, size_t bytes) {
    Buffer staging(context, bytes, vk::BufferUsageFlagBits::eTransferDst, image.desc().name + " (readback)");
    context.submitAndWait([&](const vk::raii::CommandBuffer& commands) {
        transition(commands, image, kResting, kCopyingFrom);
        commands.copyImageToBuffer(image.handle(), kCopyingFrom.layout, staging.handle(), regions);
        transition(commands, image, kCopyingFrom, kResting);
        const vk::MemoryBarrier toHost(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead);
        commands.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {}, toHost, {}, {});
    });
    return staging;
}

void writeRegions(const VulkanContext& context, Image& image, std::span<const vk::BufferImageCopy> regions,
                  std::span<const std::byte> bytes, const std::string& stagingName) {
    Buffer staging(context, bytes.size(), vk::BufferUsageFlagBits::eTransferSrc, stagingName);
    staging.write(bytes);
    context.submitAndWait([&](const vk::raii::CommandBuffer& commands) {
        transition(commands, image, kResting, kCopyingTo);
        commands.copyBufferToImage(staging.handle(), image.handle(), kCopyingTo.layout, regions);
        transition(commands, image, kCopyingTo, kResting);
    });
}

uint32_t fullMipCount(uint32_t width, uint32_t height) {
    return static_cast<uint32_t>(std::bit_width(std::max(width, height)));
}

Image::Image(const VulkanContext& context, ImageDesc desc) : desc_(std::move(desc)), device_(&context.device()) {
    validate(context, desc_);
    const vk::ImageUsageFlags usage = usageOf(desc_);
    image_ = vk::raii::Image(
        context.device(),
        vk::ImageCreateInfo(desc_.cube ? vk::ImageCreateFlagBits::eCubeCompatible : vk::ImageCreateFlags(),
                            vk::ImageType::e2D, desc_.format->format, vk::Extent3D(desc_.width, desc_.height, 1),
                            desc_.mips, desc_.layers, vk::SampleCountFlagBits::e1, vk::ImageTiling::eOptimal, usage));
    memory_ = allocateMemory(context, image_.getMemoryRequirements(), vk::MemoryPropertyFlagBits::eDeviceLocal,
                             "image '" + desc_.name + "'");
    image_.bindMemory(*memory_, 0);
    context.submitAndWait([&](const vk::raii::CommandBuffer& commands) {
        const vk::ImageMemoryBarrier toGeneral({}, vk::AccessFlagBits::eTransferWrite | vk::AccessFlagBits::eShaderRead |
                                                       vk::AccessFlagBits::eShaderWrite,
                                               vk::ImageLayout::eUndefined, vk::ImageLayout::eGeneral,
                                               VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, *image_,
                                               wholeImage(desc_));
        commands.pipelineBarrier(vk::PipelineStageFlagBits::eTopOfPipe, vk::PipelineStageFlagBits::eAllCommands, {}, {},
                                 {}, toGeneral);
    });
}

uint32_t Image::mipWidth(uint32_t mip) const { return std::max(1u, desc_.width >> mip); }
uint32_t Image::mipHeight(uint32_t mip) const { return std::max(1u, desc_.height >> mip); }

size_t Image::valueOffset(uint32_t mip, uint32_t layer) const {
    size_t offset = 0;
    for (uint32_t level = 0; level < mip; ++level)
        offset += size_t(mipWidth(level)) * mipHeight(level) * desc_.layers;
    offset += size_t(mipWidth(mip)) * mipHeight(mip) * layer;
    return offset * desc_.format->channels;
}

size_t Image::valueCount() const { return valueOffset(desc_.mips, 0); }

vk::ImageView Image::view(vk::ImageViewType type, uint32_t baseMip, uint32_t mipCount, uint32_t baseLayer,
                          uint32_t layerCount) {
    const auto key = std::tuple(type, baseMip, mipCount, baseLayer, layerCount);
    auto found = views_.find(key);
    if (found == views_.end()) {
        const vk::ImageViewCreateInfo info({}, *image_, type, desc_.format->format, {},
                                           {desc_.format->aspect(), baseMip, mipCount, baseLayer, layerCount});
        found = views_.emplace(key, vk::raii::ImageView(*device_, info)).first;
    }
    return *found->second;
}

void Image::upload(const VulkanContext& context, std::span<const float> values) {
    if (values.size() != valueCount())
        throw VulkanError("image '" + desc_.name + "' holds " + std::to_string(valueCount()) + " values, not " +
                          std::to_string(values.size()));
    std::vector<std::byte> bytes(values.size() * desc_.format->bytesPerChannel);
    encodeTexels(*desc_.format, values, bytes);
    uploadBytes(context, bytes);
}

void Image::uploadBytes(const VulkanContext& context, std::span<const std::byte> bytes) {
    const size_t expected = valueCount() * desc_.format->bytesPerChannel;
    if (bytes.size() != expected)
        throw VulkanError("image '" + desc_.name + "' holds " + std::to_string(expected) + " bytes, not " +
                          std::to_string(bytes.size()));
    writeRegions(context, *this, copyRegions(*this), bytes, desc_.name + " (staging)");
}

std::vector<std::byte> Image::downloadBytes(const VulkanContext& context) const {
    return readback(context, *this, copyRegions(*this), valueCount() * desc_.format->bytesPerChannel).read();
}

SubmissionTiming Image::copyMipFrom(const VulkanContext& context, const Image& source, uint32_t mip) {
    if (source.desc().format != desc_.format || mip >= desc_.mips || mip >= source.desc().mips ||
        source.mipWidth(mip) != mipWidth(mip) || source.mipHeight(mip) != mipHeight(mip) ||
        source.desc().layers != desc_.layers)
        throw VulkanError("image '" + desc_.name + "': mip " + std::to_string(mip) + " of '" + source.desc().name +
                          "' differs in format, size or layers");
    const vk::ImageSubresourceLayers layers(desc_.format->aspect(), mip, 0, desc_.layers);
    const vk::ImageCopy region(layers, {}, layers, {}, vk::Extent3D(mipWidth(mip), mipHeight(mip), 1));
    return submitTimed(
        context,
        [&](const vk::raii::CommandBuffer& commands) {
            transition(commands, source, kResting, kCopyingFrom);
            transition(commands, *this, kResting, kCopyingTo);
        },
        [&](const vk::raii::CommandBuffer& commands) {
            commands.copyImage(source.handle(), kCopyingFrom.layout, *image_, kCopyingTo.layout, region);
        },
        [&](const vk::raii::CommandBuffer& commands) {
            transition(commands, source, kCopyingFrom, kResting);
            transition(commands, *this, kCopyingTo, kResting);
        });
}

std::vector<float> Image::download(const VulkanContext& context) const {
    const auto staging = readback(context, *this, copyRegions(*this), valueCount() * desc_.format->bytesPerChannel);
    std::vector<float> values(valueCount());
    decodeTexels(*desc_.format, staging.contents(), values);
    return values;
}

Sampler::Sampler(const VulkanContext& context, const SamplerDesc& desc)
    : sampler_(context.device(), vk::SamplerCreateInfo({}, desc.filter, desc.filter, desc.mipmap, desc.address,
                                                       desc.address, desc.address, 0.0f, VK_FALSE, 1.0f, VK_FALSE,
                                                       vk::CompareOp::eNever, 0.0f, VK_LOD_CLAMP_NONE)) {}

} // namespace iblkit::vulkan
