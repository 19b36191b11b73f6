#include "run_command.hpp"

#include "run_executor.hpp"
#include "run_file.hpp"

#include <fmt/core.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace iblkit::cli {

void addRunCommand(CLI::App& app) {
    struct Arguments {
        std::string runFile;
        run::RunOptions options;
        double timeoutSeconds = 60;
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand("run", "Run a compute shader as a run file describes, and check its results");
    command->add_option("run_file", arguments->runFile, "Run file (JSON)")->required();
    command->add_option("--device", arguments->options.device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("--validate", arguments->options.validation, "Turn on the Vulkan validation layer; any message fails the run");
    command->add_option("--timeout", arguments->timeoutSeconds, "Seconds the device may take for the dispatch (default 60)")
        ->check(CLI::Range(0.001, 86400.0));
    command->callback([arguments] {
        arguments->options.timeout = std::chrono::milliseconds(int64_t(arguments->timeoutSeconds * 1000));
        // The device may still be running the shader: nothing made for it can be freed, so the
        // run ends here rather than unwinding.
        arguments->options.onDeviceFailure = [runFile = arguments->runFile](const std::string& message) {
            std::cout.flush();
            fmt::print(stderr, "{}: error: {} (--timeout sets the limit)\n", runFile, message);
            std::fflush(stderr);
            _exit(1);
        };
        const auto spec = run::readRunFile(arguments->runFile);
        if (!run::executeRun(spec, arguments->options, std::cout)) throw ExpectationsFailed{};
    });
}

} // namespace iblkit::cli
