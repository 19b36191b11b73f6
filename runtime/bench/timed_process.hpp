#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::bench {

// Runs `arguments` (the program first, found as a path, not on PATH) with its standard output
// into `output` and its standard error into `errorLog`; returns its wall time in milliseconds,
// from the start to the end of the process. Throws BenchError naming `what` and the last line of
// its standard error when it cannot start or does not exit with 0.
double runTimed(const std::vector<std::string>& arguments, const std::filesystem::path& output,
                const std::filesystem::path& errorLog, const std::string& what);

} // namespace iblkit::bench
