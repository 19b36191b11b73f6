#pragma once

#include "image.hpp"

#include <span>
#include <vector>

namespace iblkit::vulkan {

// One mip of an image on the host, every layer, in Image's order (layer, row, column, channel):
// the whole chain's readback costs a third more for a cube's mip 0.
std::vector<float> downloadMip(const VulkanContext& context, const Image& image, uint32_t mip);

// Texels of one mip replaced from the host, the rest left as they are: `values` holds the
// format's channels for each texel of `where`, in its order.
struct TexelAt {
    uint32_t layer, row, column;
};
void writeTexels(const VulkanContext& context, Image& image, uint32_t mip, std::span<const TexelAt> where,
                 std::span<const float> values);

} // namespace iblkit::vulkan
