#include "timed_submission.hpp"

#include <chrono>

namespace iblkit::vulkan {

SubmissionTiming submitTimed(const VulkanContext& context, const RecordCommands& before, const RecordCommands& timed,
                             const RecordCommands& after) {
    const bool hasTimestamps = context.timestampPeriod() > 0;
    vk::raii::QueryPool queries(nullptr);
    if (hasTimestamps)
        queries = vk::raii::QueryPool(context.device(), vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2));
    const auto started = std::chrono::steady_clock::now();
    context.submitAndWait([&](const vk::raii::CommandBuffer& commands) {
        if (hasTimestamps) commands.resetQueryPool(*queries, 0, 2);
        before(commands);
        if (hasTimestamps) commands.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *queries, 0);
        timed(commands);
        if (hasTimestamps) commands.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries, 1);
        after(commands);
    });
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    double device = -1;
    if (hasTimestamps) {
        const auto [result, ticks] = queries.getResults<uint64_t>(0, 2, 2 * sizeof(uint64_t), sizeof(uint64_t),
                                                                  vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        if (result == vk::Result::eSuccess) device = double(ticks[1] - ticks[0]) * context.timestampPeriod() * 1e-6;
    }
    return {device, wall};
}

} // namespace iblkit::vulkan
