#include "stress_command.hpp"

#include "atomic_output.hpp"
#include "bake_progress.hpp"
#include "bench_environments.hpp"
#include "reference_cache.hpp"
#include "run_command.hpp"
#include "stress.hpp"
#include "vulkan_context.hpp"

#include <fmt/core.h>

#include <memory>

namespace iblkit::cli {

void addStressCommand(CLI::App& app) {
    struct Arguments {
        std::string out;
        std::string device;
        std::string cache;
        bool reduced = false;
        bool quiet = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand("stress", "Run every kernel at its numerical extremes on every path and compare with the C++ double reference");
    command->add_option("--out", arguments->out, "Write the report (Markdown) to this file");
    command->add_option("--device", arguments->device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("--reduced", arguments->reduced, "The test suite's smaller set: no Blender HDRIs, fewer sizes and sample counts");
    command->add_option("--cache", arguments->cache, "Folder Blender's HDRIs are fetched into "
                                                     "(default $XDG_CACHE_HOME/iblkit or ~/.cache/iblkit)");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr");
    command->callback([arguments] {
        if (!arguments->out.empty()) { // before a minute of work
            files::requireWritableFile(arguments->out, "--out");
            files::requireNotAnInputIn(arguments->out, "hlsl");
        }
        auto log = std::make_shared<vulkan::ValidationLog>();
        const vulkan::VulkanContext context({arguments->device, false, log});
        stress::StressOptions options{arguments->reduced, {}};
        if (!arguments->reduced)
            options.blenderWorlds = bench::blenderWorlds(arguments->cache.empty() ? bench::ReferenceCache::defaultFolder()
                                                                                  : std::filesystem::path(arguments->cache));
        bake::BakeProgress progress(arguments->quiet);
        const auto report = stress::runStress(context, options, &progress);
        std::string invocation = "iblkit stress";
        if (arguments->reduced) invocation += " --reduced";
        if (!arguments->out.empty()) invocation += " --out " + arguments->out;
        const auto markdown = stress::renderStabilityMarkdown(report, context, invocation);
        if (arguments->out.empty()) fmt::print("{}", markdown);
        else files::writeFileAtomically(arguments->out, markdown);
        const auto messages = log->messages();
        for (const auto& message : messages) fmt::print(stderr, "validation: {}\n", message);
        if (!report.passed() || !messages.empty()) throw ExpectationsFailed{};
    });
}

} // namespace iblkit::cli
