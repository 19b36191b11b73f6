#pragma once

#include "vulkan_context.hpp"

#include <functional>

namespace iblkit::vulkan {

struct SubmissionTiming {
    double deviceMilliseconds; // from timestamp queries around the timed commands; negative when the queue has none
    double wallMilliseconds;   // submission to completion, as the host saw it
};

using RecordCommands = std::function<void(const vk::raii::CommandBuffer&)>;

// Records `before`, `timed` and `after` into one command buffer, submits it and waits. The device
// time brackets `timed` alone, so that layout transitions and barriers are not counted as work.
SubmissionTiming submitTimed(const VulkanContext& context, const RecordCommands& before, const RecordCommands& timed,
                             const RecordCommands& after);

} // namespace iblkit::vulkan
