#include "precompile_kernels_command.hpp"

#include "bake_kernels.hpp"

#include <filesystem>
#include <memory>

namespace iblkit::cli {

void addPrecompileKernelsCommand(CLI::App& app) {
    auto* command = app.add_subcommand("precompile-kernels", "Compile the bake's kernels into the program's built-in store");
    command->group(""); // hidden
    auto folder = std::make_shared<std::filesystem::path>();
    command->add_option("folder", *folder, "The store's folder")->required();
    command->callback([folder] { bake::precompileBakeKernels(*folder); });
}

} // namespace iblkit::cli
