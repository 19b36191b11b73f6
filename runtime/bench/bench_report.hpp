#pragma once

#include "bench_options.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::bench {

// What writeBenchResults needs, checked before a long run: Debian's python3 with matplotlib, an
// output folder that is absent, empty or an earlier bench's (its manifest.json says so, and it
// holds nothing else: bake::BakeDirectory's rule), the Markdown file's folder, and no output that
// is one of `environments` that name files (the bench's inputs). Throws BenchError.
void checkResultsWritable(const std::filesystem::path& folder, const std::filesystem::path& markdownFile,
                          const std::vector<std::string>& environments);

// Writes results.json, results.csv, the plots (PNG, drawn by tools/bench_plot.py with
// matplotlib from the copy inside the program) and manifest.json into `folder`, which it replaces
// as a whole, and the report to `markdownFile` unless it is empty — all or nothing: a failure
// leaves every earlier file as it was. Returns
// the plots' names, relative to `folder`. Throws BenchError or files::FileError.
std::vector<std::string> writeBenchResults(const BenchRun& run, const std::string& command,
                                           const std::filesystem::path& folder,
                                           const std::filesystem::path& markdownFile);

// The Markdown report: the machine, device, date and command; per environment the error of
// every method and sample count per mip with its times; the LUT and irradiance tables; the
// time each method needs to reach the error targets; the lowest error at each time budget and
// whether the documents' estimator holds any; and the plots, linked relative to
// `markdownFile`'s folder.
std::string renderBenchMarkdown(const BenchRun& run, const std::string& command, const std::filesystem::path& folder,
                                const std::vector<std::string>& plots, const std::filesystem::path& markdownFile);

} // namespace iblkit::bench
