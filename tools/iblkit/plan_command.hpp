#pragma once

#include <CLI/CLI.hpp>

namespace iblkit::cli {

// iblkit plan SCENE [ENV] [bake settings] [--json]: what `iblkit bake --scene SCENE` computes,
// and what each step should cost; see docs/bake.md.
void addPlanCommand(CLI::App& app);

} // namespace iblkit::cli
