#pragma once

#include "bench_options.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::bench {

// Writes results.csv and results.json into `folder`, then the plots (PNG, drawn by
// tools/bench_plot.py with matplotlib, from the copy inside the program). Returns the plot
// files' names, relative to `folder`. Throws BenchError when the plots cannot be drawn.
std::vector<std::string> writeBenchResults(const BenchRun& run, const std::string& command,
                                           const std::filesystem::path& folder);

// The Markdown report: the machine, device, date and command; per environment the error of
// every method and sample count per mip with its times; the LUT and irradiance tables; the
// time each method needs to reach the error targets; and the plots, linked relative to
// `markdownFile`'s folder.
std::string renderBenchMarkdown(const BenchRun& run, const std::string& command, const std::filesystem::path& folder,
                                const std::vector<std::string>& plots, const std::filesystem::path& markdownFile);

} // namespace iblkit::bench
