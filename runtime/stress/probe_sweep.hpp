#pragma once

#include "suite_run.hpp"

#include <string>
#include <vector>

namespace iblkit::stress {

// One function of a probe kernel on one path over the stress arguments (probe_sweep.cpp).
struct ProbeRow {
    std::string kernel; // PbrProbeCS, LutProbeCS or BsdfProbeCS
    std::string function;
    std::string path;
    size_t values = 0;
    // Where the double reference itself is NaN/Inf: the math's singular points.
    size_t singularInMath = 0;
    // Where the C++ float (the shader's arithmetic) is NaN/Inf and the double is not: the
    // formula's float singular points. The path's values there are not judged.
    size_t singularInFloat = 0;
    // The path's NaN/Inf everywhere else: must be 0.
    size_t nonFinite = 0;
    // Against the double, where neither is singular: where the bake calls the function (judged)
    // and at the other arguments (reported).
    double maxError = 0;
    double maxErrorElsewhere = 0;
    bool relative = false; // maxError is relative (D, whose values span 1e-20 to 1e15), else absolute
    double bound = 0;
    bool passed = false;
};

// Where a function is singular, for the report: its arguments and the bake's nearest.
struct SingularPoint {
    std::string function;
    std::string arguments; // "c = 1, r = 0"
    std::string inMath;    // "NaN" / "Inf" / "finite"
    std::string inFloat;
    bool calledByBake; // must be false
};

struct ProbeSweep {
    std::vector<ProbeRow> rows;
    std::vector<SingularPoint> singular;
    size_t pbrArguments = 0, lutArguments = 0, bsdfArguments = 0;
};

// PbrProbeCS and LutProbeCS over every combination of N.V (or N.H) in {0, the smallest
// denormal, 1e-7, 1e-4, 0.5, 1 - 1e-7, 1}, roughness in {0, the smallest denormal, 1e-4, 0.01,
// 0.5, 1} and N.L, V.H (or the GGX sample's xi) at their edges, and BsdfProbeCS with N.L and N.V
// in the first set and roughness in the second, on every path of `run`.
ProbeSweep sweepProbes(consistency::SuiteRun& run);

} // namespace iblkit::stress
