#include "run_command.hpp"

#include <iblkit/run.hpp>

#include <fmt/core.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace iblkit::cli {

void addRunCommand(CLI::App& app) {
    struct Arguments {
        std::string runFile;
        RunRequest request;
        double timeoutSeconds = 60;
        std::string api = "vulkan";
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand("run", "Run a dispatch or a draw as a run file describes, and check its results");
    command->add_option("run_file", arguments->runFile, "Run file (JSON)")->required();
    command->add_option("--api", arguments->api,
                        "vulkan (the SPIR-V), opengl (the GLSL form, through EGL) or all (both, compared; default vulkan)")
        ->check(CLI::IsMember({"vulkan", "opengl", "all"}));
    command->add_option("--device", arguments->request.device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("--validate", arguments->request.validation, "Turn on the Vulkan validation layer; any message fails the run");
    command->add_option("--timeout", arguments->timeoutSeconds, "Seconds the device may take for the dispatch (default 60)")
        ->check(CLI::Range(0.001, 86400.0));
    command->callback([arguments] {
        auto request = arguments->request;
        request.runFile = arguments->runFile;
        request.api = arguments->api == "opengl" ? RunApi::OpenGl : arguments->api == "all" ? RunApi::All : RunApi::Vulkan;
        request.timeout = std::chrono::milliseconds(int64_t(arguments->timeoutSeconds * 1000));
        // The device may still be running the shader: nothing made for it can be freed, so the
        // run ends here rather than unwinding.
        request.onDeviceFailure = [runFile = arguments->runFile](const std::string& message) {
            std::cout.flush();
            fmt::print(stderr, "{}: error: {} (--timeout sets the limit)\n", runFile, message);
            std::fflush(stderr);
            _exit(1);
        };
        request.reportStream = &std::cout;
        if (!executeRunFile(request).passed) throw ExpectationsFailed{};
    });
}

} // namespace iblkit::cli
