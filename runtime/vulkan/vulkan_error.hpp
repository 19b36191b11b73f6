#pragma once

#include <stdexcept>

namespace iblkit::vulkan {

// Every failure of the runtime: no device, an allocation that cannot fit, a resource missing
// or of the wrong kind, a Vulkan call that failed. The message is one line, ready to print.
class VulkanError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::vulkan
