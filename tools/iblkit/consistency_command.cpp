#include "consistency_command.hpp"

#include "atomic_output.hpp"
#include "consistency_suite.hpp"
#include "egl_context.hpp"
#include "run_command.hpp"

#include <fmt/core.h>

#include <memory>

namespace iblkit::cli {

void addConsistencyCommand(CLI::App& app) {
    struct Arguments {
        std::string out;
        std::string device;
        uint32_t samples = 1024;
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand("consistency", "Run every form of the seed shaders and compare with the C++ reference");
    command->add_option("--out", arguments->out, "Write the report (Markdown) to this file");
    command->add_option("--device", arguments->device, "Device index or part of its name (default: lavapipe)");
    command->add_option("--samples", arguments->samples, "Samples per texel (default 1024, the documents')");
    command->callback([arguments] {
        const vulkan::VulkanContext context({arguments->device, false, nullptr});
        const auto options = consistency::defaultSuiteOptions("hlsl/shaders.json", arguments->samples);
        const auto rows = consistency::runConsistency(context, options);
        std::string invocation = "iblkit consistency";
        if (arguments->samples != 1024) invocation += fmt::format(" --samples {}", arguments->samples);
        if (!arguments->out.empty()) invocation += " --out " + arguments->out;
        const auto report = consistency::renderMarkdown(rows, context, opengl::EglContext().renderer(), options, invocation);
        if (arguments->out.empty()) fmt::print("{}", report);
        else files::writeFileAtomically(arguments->out, report);
        size_t failed = 0;
        for (const auto& row : rows) failed += !row.passed;
        fmt::print(stderr, "{} of {} results within their bounds\n", rows.size() - failed, rows.size());
        if (failed) throw ExpectationsFailed{};
    });
}

} // namespace iblkit::cli
