#include "slurm_script.hpp"

#include <fmt/format.h>

namespace iblkit::batch {

std::string shellQuoted(const std::string& word) {
    if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789@%_+=:,./-") ==
                             std::string::npos)
        return word;
    std::string quoted = "'";
    for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string slurmScript(const SlurmScript& script) {
    std::string command = shellQuoted(script.program.string());
    for (const auto& argument : script.arguments) command += " " + shellQuoted(argument);
    std::string text = "#!/bin/sh\n";
    text += fmt::format("#SBATCH --job-name={}\n", shellQuoted(script.jobName));
    text += fmt::format("#SBATCH --array=0-{}\n", script.shards - 1);
    if (script.cpusPerTask) text += fmt::format("#SBATCH --cpus-per-task={}\n", script.cpusPerTask);
    text += fmt::format("#SBATCH --output={}\n", shellQuoted((script.logFolder / "slurm-%A_%a.out").string()));
    if (!script.workingFolder.empty()) text += fmt::format("#SBATCH --chdir={}\n", shellQuoted(script.workingFolder.string()));
    text += "# Each task bakes its part of the list (iblkit batch reads $SLURM_ARRAY_TASK_ID and\n"
            "# $SLURM_ARRAY_TASK_COUNT) into the shared folder and cache, and writes its own record there;\n"
            "# `iblkit batch --merge DIR` gives the whole status. A task runs Mesa's CPU device on the\n"
            "# CPUs Slurm gave it.\n";
    text += "if [ -n \"${SLURM_CPUS_PER_TASK:-}\" ]; then export LP_NUM_THREADS=\"$SLURM_CPUS_PER_TASK\"; fi\n";
    text += "exec " + command + "\n";
    return text;
}

} // namespace iblkit::batch
