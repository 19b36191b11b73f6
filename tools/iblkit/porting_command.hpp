#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit porting [--corpus DIR] [--out FILE] [--device D]: the porting corpus run, each feature
// judged against its manifest, and the feature table written (docs/porting.md).
void addPortingCommand(CLI::App& app);

} // namespace iblkit::cli
