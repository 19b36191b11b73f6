#pragma once

#include "bench_options.hpp"

namespace iblkit::bench {

// Runs every environment x method x sample count of `options` and measures each against the
// converged references. Throws BenchError, or the bake's, compiler's and runtime's errors.
BenchRun runBench(const BenchOptions& options);

} // namespace iblkit::bench
