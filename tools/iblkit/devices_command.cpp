#include "devices_command.hpp"

#include "vulkan_context.hpp"

#include <fmt/core.h>

namespace iblkit::cli {

void addDevicesCommand(CLI::App& app) {
    auto* command = app.add_subcommand("devices", "List the Vulkan devices (the default one is marked *)");
    command->callback([] {
        const auto devices = vulkan::listDevices();
        const size_t chosen = vulkan::chooseDevice(devices, "");
        for (const auto& device : devices) {
            const bool isDefault = device.index == chosen;
            fmt::print("{} {}  {}  {}  Vulkan {}  {}\n", isDefault ? '*' : ' ', device.index, device.name, device.type,
                       device.apiVersion, device.driver);
        }
    });
}

} // namespace iblkit::cli
