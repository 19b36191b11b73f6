#pragma once

#include <filesystem>
#include <string>

namespace iblkit::bench {

// A path as one word of a POSIX shell command, whatever characters it holds.
std::string shellQuoted(const std::filesystem::path& path);

// Runs a shell command; throws BenchError "could not <what>" when it fails.
void runShell(const std::string& command, const std::string& what);

// Runs `command` with `input` on its standard input; its exit status (-1 when it could not
// start). A command that exits early does not kill this process with SIGPIPE.
int runWithInput(const std::string& command, const std::string& input);

} // namespace iblkit::bench
