#pragma once

#include "vulkan_context.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace iblkit::vulkan {

// A buffer in host-visible, coherent memory: storage and uniform buffers of a compute run,
// and the staging buffers of image transfers. (On lavapipe all memory is host memory; on a
// GPU such memory is what a harness wants for its small inputs and readbacks.)
class Buffer {
public:
    Buffer(const VulkanContext& context, vk::DeviceSize size, vk::BufferUsageFlags usage, const std::string& name);

    vk::Buffer handle() const { return *buffer_; }
    vk::DeviceSize size() const { return size_; }
    const std::string& name() const { return name_; }

    void write(std::span<const std::byte> bytes, vk::DeviceSize offset = 0);
    std::vector<std::byte> read() const;
    // The mapped bytes, read in place: a readback decoded from here needs no copy.
    std::span<const std::byte> contents() const { return {static_cast<const std::byte*>(mapped_), size_t(size_)}; }

private:
    std::string name_;
    vk::DeviceSize size_;
    vk::raii::Buffer buffer_{nullptr};
    vk::raii::DeviceMemory memory_{nullptr};
    void* mapped_ = nullptr;
};

// A storage buffer of `size` bytes (at least `bytes`' and 4: Vulkan has no empty buffer) that
// starts with `bytes`.
Buffer storageBuffer(const VulkanContext& context, std::span<const std::byte> bytes, const std::string& name,
                     vk::DeviceSize size = 0);

} // namespace iblkit::vulkan
