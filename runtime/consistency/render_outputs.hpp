#pragma once

#include "suite_run.hpp"

namespace iblkit::consistency {

// RenderReferenceCS (both materials) and SplitSumSpheresCS over a small sphere grid lit by the
// suite's environment (and, for the reference, a directional, a point and an area light). No C++
// reference: the paths are compared with path a.
void addRenderOutputs(SuiteRun& run);

} // namespace iblkit::consistency
