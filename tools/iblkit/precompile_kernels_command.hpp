#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit-program precompile-kernels FOLDER: the program's built-in kernels
// (runtime/kernels/built_in_kernels.hpp), made by the build beside the program. Not listed in
// --help: only the build runs it.
void addPrecompileKernelsCommand(CLI::App& app);

} // namespace iblkit::cli
