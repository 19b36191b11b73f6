#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit devices: every Vulkan device, and which one runs by default.
void addDevicesCommand(CLI::App& app);

} // namespace iblkit::cli
