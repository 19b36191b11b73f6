#include "vulkan_context.hpp"

#include <cstdio>
#include <cstring>

namespace iblkit::vulkan {
namespace {

// VkPipelineCacheHeaderVersionOne, as the specification lays it out in the data's first 32 bytes.
struct CacheHeader {
    uint32_t headerSize;
    uint32_t headerVersion;
    uint32_t vendorID;
    uint32_t deviceID;
    uint8_t pipelineCacheUUID[VK_UUID_SIZE];
};
static_assert(sizeof(CacheHeader) == 32);

// Drivers are to ignore data for another device, yet some crash on it: the header is checked here.
bool headerMatches(std::span<const std::byte> data, const vk::PhysicalDeviceProperties& properties) {
    CacheHeader header;
    if (data.size() < sizeof header) return false;
    std::memcpy(&header, data.data(), sizeof header);
    return header.headerSize >= sizeof header && header.headerSize <= data.size() &&
           header.headerVersion == uint32_t(vk::PipelineCacheHeaderVersion::eOne) && header.vendorID == properties.vendorID &&
           header.deviceID == properties.deviceID &&
           std::memcmp(header.pipelineCacheUUID, properties.pipelineCacheUUID.data(), VK_UUID_SIZE) == 0;
}

} // namespace

std::vector<std::byte> VulkanContext::pipelineCacheData() const {
    const auto bytes = pipelineCache_.getData();
    const auto* first = reinterpret_cast<const std::byte*>(bytes.data());
    return {first, first + bytes.size()};
}

bool VulkanContext::addPipelineCacheData(std::span<const std::byte> data) const {
    if (!headerMatches(data, physicalDevice_.getProperties())) return false;
    const vk::raii::PipelineCache earlier(device_, vk::PipelineCacheCreateInfo({}, data.size(), data.data()));
    pipelineCache_.merge(*earlier);
    return true;
}

std::string VulkanContext::pipelineCacheIdentity() const {
    const auto properties = physicalDevice_.getProperties();
    char text[2 * 9 + 2 * VK_UUID_SIZE + 1];
    int length = std::snprintf(text, sizeof text, "%08x-%08x-", properties.vendorID, properties.deviceID);
    for (const uint8_t byte : properties.pipelineCacheUUID)
        length += std::snprintf(text + length, sizeof text - size_t(length), "%02x", byte);
    return text;
}

} // namespace iblkit::vulkan
