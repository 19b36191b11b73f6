#pragma once

#include "vulkan_context.hpp"

#include <string>

namespace iblkit::vulkan {

// Allocates memory for a buffer or image, first checking that it can fit at all, so that an
// impossible size is a clear error naming the resource rather than a driver failure.
vk::raii::DeviceMemory allocateMemory(const VulkanContext& context, const vk::MemoryRequirements& requirements,
                                      vk::MemoryPropertyFlags properties, const std::string& what);

} // namespace iblkit::vulkan
