#include "device_memory.hpp"

#include "vulkan_error.hpp"

namespace iblkit::vulkan {

vk::raii::DeviceMemory allocateMemory(const VulkanContext& context, const vk::MemoryRequirements& requirements,
                                      vk::MemoryPropertyFlags properties, const std::string& what) {
    const vk::DeviceSize heap = context.largestHeapSize();
    if (requirements.size > heap)
        throw VulkanError("cannot allocate " + std::to_string(requirements.size) + " bytes for " + what +
                          ": the device's largest memory heap holds " + std::to_string(heap));
    try {
        return vk::raii::DeviceMemory(
            context.device(),
            vk::MemoryAllocateInfo(requirements.size, context.memoryTypeIndex(requirements.memoryTypeBits, properties)));
    } catch (const vk::OutOfDeviceMemoryError&) {
        throw VulkanError("cannot allocate " + std::to_string(requirements.size) + " bytes for " + what +
                          ": out of device memory");
    } catch (const vk::OutOfHostMemoryError&) {
        throw VulkanError("cannot allocate " + std::to_string(requirements.size) + " bytes for " + what +
                          ": out of host memory");
    }
}

} // namespace iblkit::vulkan
