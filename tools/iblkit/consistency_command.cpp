#include "consistency_command.hpp"

#include "atomic_output.hpp"
#include "bake_progress.hpp"
#include "consistency_suite.hpp"
#include "run_command.hpp"
#include "vulkan_context.hpp"

#include <fmt/core.h>

#include <memory>
#include <stdexcept>

namespace iblkit::cli {

void addConsistencyCommand(CLI::App& app) {
    struct Arguments {
        std::string out;
        std::string device;
        uint32_t samples = 1024;
        bool quiet = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand("consistency", "Run every kernel of hlsl/shaders.json in every form and compare with the C++ reference");
    command->add_option("--out", arguments->out, "Write the report (Markdown) to this file");
    command->add_option("--device", arguments->device, "Device index or part of its name (default: lavapipe)");
    // The suite runs the sampled kernels in one dispatch each, one loop over the samples: past
    // 65535 llvmpipe would end that loop early (the bake splits such counts; the suite does not).
    command->add_option("--samples", arguments->samples, "Samples per texel, 1 to 65535 (default 1024, the documents')");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr");
    command->callback([arguments] {
        if (arguments->samples < 1 || arguments->samples > 65535)
            throw std::invalid_argument(fmt::format("--samples {} is out of range (1 to 65535)", arguments->samples));
        if (!arguments->out.empty()) { // before a minute of work
            files::requireWritableFile(arguments->out, "--out");
            files::requireNotAnInputIn(arguments->out, "hlsl");
        }
        auto log = std::make_shared<vulkan::ValidationLog>();
        const vulkan::VulkanContext context({arguments->device, false, log});
        const auto options = consistency::defaultSuiteOptions("hlsl/shaders.json", arguments->samples);
        bake::BakeProgress progress(arguments->quiet);
        const auto [rows, openGlRenderer] = consistency::runConsistency(context, options, &progress);
        std::string invocation = "iblkit consistency";
        if (arguments->samples != 1024) invocation += fmt::format(" --samples {}", arguments->samples);
        if (!arguments->out.empty()) invocation += " --out " + arguments->out;
        const auto report = consistency::renderMarkdown(rows, context, openGlRenderer, options, invocation);
        if (arguments->out.empty()) fmt::print("{}", report);
        else files::writeFileAtomically(arguments->out, report);
        size_t failed = 0;
        for (const auto& row : rows) failed += !row.asExpected();
        // Debug builds, and IBLKIT_VALIDATION=1, run with the validation layer: what it says fails the run.
        const auto messages = log->messages();
        for (const auto& message : messages) fmt::print(stderr, "validation: {}\n", message);
        fmt::print(stderr, "{} of {} results as expected (within their bounds, or a known divergence)\n", rows.size() - failed, rows.size());
        if (failed && arguments->samples != 1024)
            fmt::print(stderr, "the bounds were measured at 1024 samples per texel; at {} the sampled kernels' errors "
                               "differ, so these failures are not findings\n", arguments->samples);
        if (failed || !messages.empty()) throw ExpectationsFailed{};
    });
}

} // namespace iblkit::cli
