#include "image_transfer.hpp"

#include "image_layout.hpp"
#include "vulkan_error.hpp"

#include <string>

namespace iblkit::vulkan {

std::vector<float> downloadMip(const VulkanContext& context, const Image& image, uint32_t mip) {
    const auto& desc = image.desc();
    if (mip >= desc.mips)
        throw VulkanError("image '" + desc.name + "' has no mip " + std::to_string(mip) + " (it has " +
                          std::to_string(desc.mips) + ")");
    const size_t texels = size_t(image.mipWidth(mip)) * image.mipHeight(mip) * desc.layers;
    const vk::BufferImageCopy region(0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, mip, 0, desc.layers),
                                     vk::Offset3D(0, 0, 0), vk::Extent3D(image.mipWidth(mip), image.mipHeight(mip), 1));
    const auto staging = readback(context, image, {&region, 1}, texels * desc.format->bytesPerTexel());
    std::vector<float> values(texels * desc.format->channels);
    decodeTexels(*desc.format, staging.contents(), values);
    return values;
}

void writeTexels(const VulkanContext& context, Image& image, uint32_t mip, std::span<const TexelAt> where,
                 std::span<const float> values) {
    const auto& desc = image.desc();
    const auto fail = [&](const std::string& why) { throw VulkanError("writing texels of image '" + desc.name + "': " + why); };
    if (values.size() != where.size() * desc.format->channels)
        fail(std::to_string(values.size()) + " values for " + std::to_string(where.size()) + " texels");
    if (mip >= desc.mips) fail("no mip " + std::to_string(mip));
    if (where.empty()) return;
    std::vector<vk::BufferImageCopy> regions;
    regions.reserve(where.size());
    for (size_t i = 0; i < where.size(); ++i) {
        const auto& texel = where[i];
        if (texel.layer >= desc.layers || texel.row >= image.mipHeight(mip) || texel.column >= image.mipWidth(mip))
            fail("texel (" + std::to_string(texel.layer) + ", " + std::to_string(texel.row) + ", " +
                 std::to_string(texel.column) + ") is outside mip " + std::to_string(mip));
        regions.emplace_back(i * desc.format->bytesPerTexel(), 0, 0,
                             vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, mip, texel.layer, 1),
                             vk::Offset3D(int32_t(texel.column), int32_t(texel.row), 0), vk::Extent3D(1, 1, 1));
    }
    std::vector<std::byte> bytes(values.size() * desc.format->bytesPerChannel);
    encodeTexels(*desc.format, values, bytes);
    writeRegions(context, image, regions, bytes, desc.name + " (texel upload)");
}

} // namespace iblkit::vulkan
