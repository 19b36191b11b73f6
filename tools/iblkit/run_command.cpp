#include "run_command.hpp"

#include "run_executor.hpp"
#include "run_file.hpp"

#include <iostream>
#include <memory>

namespace iblkit::cli {

void addRunCommand(CLI::App& app) {
    struct Arguments {
        std::string runFile;
        run::RunOptions options;
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand("run", "Run a compute shader as a run file describes, and check its results");
    command->add_option("run_file", arguments->runFile, "Run file (JSON)")->required();
    command->add_option("--device", arguments->options.device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("--validate", arguments->options.validation, "Turn on the Vulkan validation layer; any message fails the run");
    command->callback([arguments] {
        const auto spec = run::readRunFile(arguments->runFile);
        if (!run::executeRun(spec, arguments->options, std::cout)) throw ExpectationsFailed{};
    });
}

} // namespace iblkit::cli
