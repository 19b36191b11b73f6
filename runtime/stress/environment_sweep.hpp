#pragma once

#include "environment_cases.hpp"
#include "suite_run.hpp"

#include <string>
#include <vector>

namespace iblkit::stress {

// One output of one cube kernel on one path over one environment.
struct EnvironmentRow {
    std::string environment;
    uint32_t size = 0;
    std::string kernel, output, path;
    size_t nonFinite = 0; // NaN/Inf values: must be 0
    // The largest error of the colour values against the double reference over the largest of
    // them (ConsistencyRow::colourError).
    double relativeError = 0;
    double bound = 0;
    std::string knownIssue = {}; // the consistency suite's known divergence: finite, its error reported
    bool passed = false;
    bool diverges() const { return relativeError > bound; }
};

// Whether the consistency suite's known divergences show in the sweep: none is known, or at least
// one known row is past its bound. A known divergence that no longer shows is stale.
bool knownDivergencesShow(const std::vector<EnvironmentRow>& rows);

// Every output of the consistency suite that reads an environment (addEnvironmentOutputs), on
// every path, over each case; the prefilter kernels at roughness 0, the smallest denormal,
// 1e-4, 0.01, 0.5 and 1. Then the kernels that read no environment (the LUTs and the built-in
// sky) at sizes 1², 2² and 3², where a texel centre lies nearest the LUT's edges.
std::vector<EnvironmentRow> sweepEnvironments(consistency::SuiteRun& run, consistency::SuiteOptions& options,
                                              const std::vector<EnvironmentCase>& cases);

} // namespace iblkit::stress
