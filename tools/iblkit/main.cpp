#include "bake_command.hpp"
#include "batch_command.hpp"
#include "bench_command.hpp"
#include "command_line.hpp"
#include "compile_all_command.hpp"
#include "compile_command.hpp"
#include "consistency_command.hpp"
#include "stress_command.hpp"
#include "devices_command.hpp"
#include "error_words.hpp"
#include "lut_fit_command.hpp"
#include "plan_command.hpp"
#include "porting_command.hpp"
#include "precompile_kernels_command.hpp"
#include "render_command.hpp"
#include "shading_command.hpp"
#include "run_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <filesystem>
#include <stdexcept>

// A bake allocates and frees buffers of megabytes (readbacks, host passes, lavapipe's memory). By
// default glibc maps each one fresh and unmaps it when freed, so every use pays a page fault per
// 4 KiB (in a virtual machine, microseconds each: a fifth of the default bake). Kept in the heap
// instead, a freed buffer's pages are reused by the next; peak memory is unchanged.
void keepFreedBuffersInTheHeap() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20); // glibc's most
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

namespace {

int runCommand(int argc, char** argv) {
    CLI::App app{"iblkit: HLSL image-based-lighting shaders in every form, and the proof that they agree"};
    app.name("iblkit");
    app.set_version_flag("--version", std::string("iblkit ") + IBLKIT_VERSION);
    app.require_subcommand(1);
    iblkit::cli::addCompileCommand(app);
    iblkit::cli::addCompileAllCommand(app);
    iblkit::cli::addDevicesCommand(app);
    iblkit::cli::addRunCommand(app);
    iblkit::cli::addConsistencyCommand(app);
    iblkit::cli::addStressCommand(app);
    iblkit::cli::addBakeCommand(app);
    iblkit::cli::addBatchCommand(app);
    iblkit::cli::addPlanCommand(app);
    iblkit::cli::addBenchCommand(app);
    iblkit::cli::addLutFitCommand(app);
    iblkit::cli::addPortingCommand(app);
    iblkit::cli::addRenderCommand(app);
    iblkit::cli::addRenderReportCommand(app);
    iblkit::cli::addShadingCommand(app);
    iblkit::cli::addPrecompileKernelsCommand(app);
    // CLI11 calls a word it does not know "A subcommand is required"; name it and the commands.
    const auto commands = app.get_subcommands({});
    const auto known = [&](const std::string& word) {
        return std::any_of(commands.begin(), commands.end(), [&](const CLI::App* command) { return command->get_name() == word; });
    };
    if (argc > 1 && argv[1][0] != '-' && !known(argv[1])) {
        std::string names;
        for (const auto* command : commands)
            if (!command->get_group().empty()) names += (names.empty() ? "" : ", ") + command->get_name();
        fmt::print(stderr, "iblkit: error: unknown command '{}' (commands: {})\n", argv[1], names);
        return 2;
    }
    try {
        app.parse(iblkit::cli::normalizeArguments(argc, argv));
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForAllHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    } catch (const CLI::ParseError& error) {
        fmt::print(stderr, "iblkit: error: {}\n", error.what());
        return 2;
    } catch (const iblkit::cli::ExpectationsFailed&) {
        return 3;
    } catch (const iblkit::cli::FormsRefused&) {
        return 4;
    } catch (const std::filesystem::filesystem_error& error) {
        fmt::print(stderr, "{}\n", iblkit::files::filesystemErrorInWords(error));
        return 1;
    } catch (const std::exception& error) {
        fmt::print(stderr, "{}\n", error.what());
        return 1;
    }
    return 0;
}

} // namespace

// The process ends without the libraries' static destructors: a bake that opened a Vulkan instance
// has lavapipe's LLVM loaded, whose registered options and tables are torn down for nothing (a
// cached bake ended 4 % sooner, in whole-process medians). Every object of the command is gone by
// now; only the streams are left to flush.
int main(int argc, char** argv) {
    keepFreedBuffersInTheHeap();
    const int code = runCommand(argc, argv);
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::_Exit(code);
}
