#include "porting_command.hpp"

#include "atomic_output.hpp"
#include "bake_progress.hpp"
#include "codebase_report.hpp"
#include "corpus_run.hpp"
#include "porting_markdown.hpp"
#include "run_command.hpp"
#include "vulkan_context.hpp"

#include <iblkit/error.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <memory>

namespace iblkit::cli {

constexpr const char* kDefaultCorpus = "hlsl/porting";

struct PortingArguments {
    std::string corpus = kDefaultCorpus;
    std::string out;
    std::string device;
    bool quiet = false;
    // A code base of the user's: manifests (with --source or --sources), or a folder and a list.
    std::vector<std::string> manifests;
    std::string source;  // the one manifest's code base on disk
    std::string sources; // a folder holding each manifest's code base by its name
    std::string entries; // a list of FILE ENTRY PROFILE [flags] lines, with --source
    std::string json;
    unsigned seconds = 60;
};

std::vector<porting::CodeBase> codeBasesOf(const PortingArguments& arguments) {
    namespace fs = std::filesystem;
    if (!arguments.entries.empty()) {
        if (arguments.source.empty()) throw Error(ErrorKind::BadInput, "error: --entries needs --source, the folder its files are in");
        return {porting::readEntryList(arguments.entries, arguments.source)};
    }
    if (arguments.source.empty() == arguments.sources.empty())
        throw Error(ErrorKind::BadInput, "error: --manifest needs --source DIR (its code base) or --sources DIR (a folder "
                                         "holding each code base by its name)");
    if (!arguments.source.empty() && arguments.manifests.size() > 1)
        throw Error(ErrorKind::BadInput, "error: --source names one code base's folder: with several manifests, use --sources");
    std::vector<porting::CodeBase> codeBases;
    const bool byName = arguments.source.empty();
    for (const auto& manifest : arguments.manifests)
        codeBases.push_back(porting::readCodeBaseManifest(
            manifest, byName ? arguments.sources : arguments.source,
            byName ? porting::CodeBaseFolder::HoldsCodeBasesByName : porting::CodeBaseFolder::IsTheCodeBase));
    for (const auto& codeBase : codeBases)
        if (!fs::is_directory(codeBase.root))
            throw Error(ErrorKind::BadInput, "error: " + codeBase.root.string() + ": no such folder: the code base " +
                                                 codeBase.name + " is not on disk there (" + codeBase.repository + " at " +
                                                 codeBase.commit + ")");
    return codeBases;
}

std::string progressLine(const porting::ConfigurationOutcome& outcome) {
    if (outcome.everyForm()) return "every form";
    if (outcome.reachedSpirv()) return "SPIR-V; " + porting::failureCause(outcome);
    return "refused: " + porting::failureCause(outcome);
}

void portCodeBases(const PortingArguments& arguments) {
    if (!arguments.out.empty()) files::requireWritableFile(arguments.out, "--out");
    if (!arguments.json.empty()) files::requireWritableFile(arguments.json, "--json");
    const auto codeBases = codeBasesOf(arguments);
    porting::ConfigurationLimits limits;
    limits.cpuSeconds = arguments.seconds;
    limits.wallSeconds = 2 * arguments.seconds;
    std::vector<porting::CodeBaseResults> results;
    for (const auto& codeBase : codeBases)
        results.push_back(porting::portCodeBase(codeBase, limits, [&](const auto& outcome, size_t done, size_t total) {
            if (!arguments.quiet)
                fmt::print(stderr, "[{}/{}] {} {}: {}\n", done, total, codeBase.name, outcome.label, progressLine(outcome));
        }));
    const auto totals = porting::portingTotals(results);
    fmt::print("{} configurations ({} ray tracing or mesh): {} of {} reach SPIR-V, {} every form\n", totals.configurations,
               totals.refusedStages, totals.reachedSpirv, totals.counted(), totals.everyForm);
    for (const auto& cause : porting::causesOf(results)) fmt::print("  {:4} {}\n", cause.count, cause.cause);
    std::string command = "iblkit porting";
    for (const auto& manifest : arguments.manifests) command += " --manifest " + manifest;
    if (!arguments.entries.empty()) command += " --entries " + arguments.entries;
    if (!arguments.sources.empty()) command += " --sources CODE_BASES";
    if (!arguments.source.empty()) command += " --source " + arguments.source;
    if (!arguments.out.empty()) {
        files::writeFileAtomically(arguments.out, porting::codeBaseMarkdown(results, command + " --out " + arguments.out));
        fmt::print("wrote {}\n", arguments.out);
    }
    if (!arguments.json.empty()) {
        files::writeFileAtomically(arguments.json, porting::codeBaseJson(results));
        fmt::print("wrote {}\n", arguments.json);
    }
}

void addPortingCommand(CLI::App& app) {
    auto arguments = std::make_shared<PortingArguments>();
    auto* command = app.add_subcommand("porting", "Compile the porting corpus into every form, run it, judge each feature "
                                                  "against the corpus manifest and write the feature table");
    command->add_option("--corpus", arguments->corpus, "Corpus folder holding corpus.json (default hlsl/porting)");
    command->add_option("--out", arguments->out, "Write the feature table (markdown) here, e.g. docs/porting.md");
    command->add_option("--device", arguments->device, "Device index or part of its name (default: lavapipe)");
    command->add_flag("-q,--quiet", arguments->quiet, "No progress on stderr");
    command->add_option("--manifest", arguments->manifests, "A code base's manifest (docs/porting-real-code.md): port its "
                                                            "configurations instead of the feature corpus")
        ->check(CLI::ExistingFile);
    command->add_option("--source", arguments->source, "The folder of the code base (one --manifest, or --entries)");
    command->add_option("--sources", arguments->sources, "A folder holding each --manifest's code base in a folder of its name");
    command->add_option("--entries", arguments->entries, "A list of FILE ENTRY PROFILE [-D NAME=VALUE] [-I DIR] [flags] "
                                                         "lines, files relative to --source")
        ->check(CLI::ExistingFile);
    command->add_option("--json", arguments->json, "With a code base: write the results as JSON here");
    command->add_option("--seconds", arguments->seconds, "With a code base: CPU seconds one configuration may take "
                                                         "(default 60; twice that in wall time)")
        ->check(CLI::Range(1u, 3600u));
    command->callback([arguments] {
        if (!arguments->manifests.empty() || !arguments->entries.empty()) return portCodeBases(*arguments);
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
