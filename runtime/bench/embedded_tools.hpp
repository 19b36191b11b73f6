#pragma once

#include <map>
#include <string>

namespace iblkit::bench {

// tools/bench_plot.py and tools/shading_plot.py as they were when the program was built, by path
// ("tools/bench_plot.py"): the plots need no source tree.
const std::map<std::string, std::string>& embeddedBenchTools();

} // namespace iblkit::bench
