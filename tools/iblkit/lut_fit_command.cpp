#include "lut_fit_command.hpp"

#include "atomic_output.hpp"
#include "lut_fit.hpp"

#include <fmt/core.h>

#include <memory>

namespace iblkit::cli {

void addLutFitCommand(CLI::App& app) {
    auto out = std::make_shared<std::string>();
    auto* command = app.add_subcommand(
        "lut-fit", "Fit the polynomial LUT to the converged LUT at every degree and write its HLSL include");
    command->add_option("-o,--out", *out, "Write the include to this file (hlsl/Common/BrdfLutFit.fxh)");
    command->callback([out] {
        if (!out->empty()) files::requireWritableFile(*out, "--out"); // before the fit's seconds of quadrature
        const auto include = reference::brdfLutFitInclude();
        if (out->empty()) fmt::print("{}", include);
        else files::writeFileAtomically(*out, include);
    });
}

} // namespace iblkit::cli
