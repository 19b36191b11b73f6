#pragma once

#include "run_engine.hpp"
#include "run_executor.hpp"

namespace iblkit::run {

// Runs the SPIR-V on a Vulkan device (lavapipe unless RunOptions names another).
std::unique_ptr<RunEngine> makeVulkanEngine(const RunOptions& options);

} // namespace iblkit::run
