#pragma once

#include <iblkit/bake.hpp>

#include <CLI/CLI.hpp>

#include <string>

namespace iblkit::cli {

// The options that decide what a bake computes (--size, --mips, --method, --samples, the LUT's and
// the irradiance's), shared by `bake` and `plan` so that a plan is of the bake it describes.
void addBakeSettingOptions(CLI::App& command, BakeRequest& request, std::string& lutFormat);

// What one bake is, as `bake` and each line of a `batch` list take it: ENV, the settings above,
// --scene and the input and output policies (--dds, --exr, --sanitize, --strict). The flags of
// the process (the output, the cache, the device, validation, quiet, JSON) are each command's own.
struct BakeLineArguments {
    BakeRequest request;
    std::string environment;
    std::string lutFormat = "rg16f";
    // The request with ENV and the LUT format in it.
    BakeRequest resolved() const;
};
void addBakeLineOptions(CLI::App& command, BakeLineArguments& line);

// The request's LUT format as --lut-format names it (rg16f or rg32f).
LutFormat lutFormatNamed(const std::string& name);

} // namespace iblkit::cli
