#pragma once

#include "bake_settings.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace iblkit::cli {

// The options that decide what a bake computes (--size, --mips, --method, --samples, the LUT's and
// the irradiance's), shared by `bake` and `plan` so that a plan is of the bake it describes.
void addBakeSettingOptions(CLI::App& command, bake::BakeSettings& s, std::string& lutFormat);

} // namespace iblkit::cli
