#include "buffer.hpp"

#include "device_memory.hpp"
#include "vulkan_error.hpp"

#include <algorithm>
#include <cstring>

namespace iblkit::vulkan {

Buffer::Buffer(const VulkanContext& context, vk::DeviceSize size, vk::BufferUsageFlags usage, const std::string& name)
    : name_(name), size_(size) {
    if (size == 0) throw VulkanError("buffer '" + name + "' has size 0");
    try {
        buffer_ = vk::raii::Buffer(context.device(), vk::BufferCreateInfo({}, size, usage, vk::SharingMode::eExclusive));
    } catch (const vk::SystemError& error) {
        throw VulkanError("buffer '" + name + "' of " + std::to_string(size) + " bytes cannot be made on this device (" +
                          error.what() + ")");
    }
    memory_ = allocateMemory(context, buffer_.getMemoryRequirements(),
                             vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent,
                             "buffer '" + name + "'");
    buffer_.bindMemory(*memory_, 0);
    mapped_ = memory_.mapMemory(0, VK_WHOLE_SIZE);
}

void Buffer::write(std::span<const std::byte> bytes, vk::DeviceSize offset) {
    if (offset + bytes.size() > size_)
        throw VulkanError("writing " + std::to_string(bytes.size()) + " bytes at offset " + std::to_string(offset) +
                          " overflows buffer '" + name_ + "' of " + std::to_string(size_) + " bytes");
    std::memcpy(static_cast<std::byte*>(mapped_) + offset, bytes.data(), bytes.size());
}

std::vector<std::byte> Buffer::read() const {
    std::vector<std::byte> bytes(size_);
    std::memcpy(bytes.data(), mapped_, size_);
    return bytes;
}

Buffer storageBuffer(const VulkanContext& context, std::span<const std::byte> bytes, const std::string& name,
                     vk::DeviceSize size) {
    Buffer buffer(context, std::max<vk::DeviceSize>({size, bytes.size(), 4}), vk::BufferUsageFlagBits::eStorageBuffer, name);
    if (!bytes.empty()) buffer.write(bytes);
    return buffer;
}

} // namespace iblkit::vulkan
