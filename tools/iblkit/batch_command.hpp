#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit batch LIST -o DIR ...: many bakes in one process, a part of them per scheduler task; see docs/batch.md.
void addBatchCommand(CLI::App& app);

} // namespace iblkit::cli
