#include "porting_command.hpp"

#include "atomic_output.hpp"
#include "bake_progress.hpp"
#include "corpus_run.hpp"
#include "porting_markdown.hpp"
#include "run_command.hpp"
#include "vulkan_context.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <memory>

namespace iblkit::cli {

constexpr const char* kDefaultCorpus = "hlsl/porting";

void addPortingCommand(CLI::App& app) {
    struct Arguments {
        std::string corpus = kDefaultCorpus;
        std::string out;
        std::string device;
        bool quiet = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand("porting", "Compile the porting corpus into every form, run it, judge each feature "
                                                  "against the corpus manifest and write the feature table");
    command->add_option("--corpus", arguments->corpus, "Corpus folder holding corpus.json (default hlsl/porting)");
    command->add_option("--out", arguments->out, "Write the feature table (markdown) here, e.g. docs/porting.md");
    command->add_option("--device", arguments->device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr");
    command->callback([arguments] {
        if (!arguments->out.empty()) files::requireWritableFile(arguments->out, "--out"); // before the corpus runs
        const auto manifest = porting::readCorpusManifest(arguments->corpus);
        if (!arguments->out.empty()) files::requireNotAnInputIn(arguments->out, arguments->corpus);
        run::RunOptions options;
        options.device = arguments->device;
        options.validation = true;
        // A missing device or validation layer is one line here, not a failed run per feature.
        vulkan::ContextOptions probe;
        probe.device = options.device;
        probe.validation = options.validation;
        vulkan::VulkanContext{probe};
        bake::BakeProgress progress(arguments->quiet);
        progress.begin("corpus");
        size_t done = 0;
        const auto results = porting::runCorpus(manifest, options, [&](const std::string& shader) {
            progress.advance(double(++done) / double(manifest.shaders.size()), shader);
        });
        progress.end();
        for (const auto& outcome : results.features) {
            fmt::print("{} {} ({})\n", outcome.mismatches.empty() ? "PASS" : "FAIL", outcome.feature.id,
                       porting::statusName(outcome.status));
            for (const auto& mismatch : outcome.mismatches) fmt::print("     {}\n", mismatch);
        }
        const auto agreeing = std::count_if(results.features.begin(), results.features.end(),
                                            [](const auto& outcome) { return outcome.mismatches.empty(); });
        fmt::print("{} of {} features as the manifest says\n", agreeing, results.features.size());
        // A table from a corpus that disagrees with its manifest would document a bug as a feature.
        if (!results.agrees()) throw ExpectationsFailed{};
        if (!arguments->out.empty()) {
            std::string command = "iblkit porting";
            if (arguments->corpus != kDefaultCorpus) command += " --corpus " + arguments->corpus;
            if (!arguments->device.empty()) command += " --device " + arguments->device;
            files::writeFileAtomically(arguments->out, porting::portingMarkdown(results, arguments->corpus, command));
            fmt::print("wrote {}\n", arguments->out);
        }
    });
}

} // namespace iblkit::cli
