#pragma once

#include "bench_options.hpp"

#include <string>
#include <vector>

namespace iblkit::bench {

// The results of `output` (on `environment`, for the specular output), in run order.
std::vector<const BenchResult*> resultsOf(const BenchRun& run, BenchOutput output, const std::string& environment);

// The configurations more accurate than every faster one (device time; `error` of each), fastest
// first: the lowest error reached within each time budget.
std::vector<const BenchResult*> timeErrorFrontier(std::vector<const BenchResult*> results,
                                                  double (*error)(const BenchResult&));

// Per environment (specular, worst mip's RMS) and for the LUT (max error): the frontier, and the
// budgets where the documents' faithful method is the lowest error (where a kit method should be).
std::string frontierTable(const BenchRun& run, const std::vector<std::string>& environments);

} // namespace iblkit::bench
