#pragma once

#include <iblkit/bake.hpp>

#include <CLI/CLI.hpp>

#include <string>

namespace iblkit::cli {

// The options that decide what a bake computes (--size, --mips, --method, --samples, the LUT's and
// the irradiance's), shared by `bake` and `plan` so that a plan is of the bake it describes.
void addBakeSettingOptions(CLI::App& command, BakeRequest& request, std::string& lutFormat);

// The request's LUT format as --lut-format names it (rg16f or rg32f).
LutFormat lutFormatNamed(const std::string& name);

} // namespace iblkit::cli
