// The sbatch script: an array over the parts, each task the same command, every word quoted.
#include "slurm_script.hpp"

#include <gtest/gtest.h>

namespace iblkit::batch {
namespace {

TEST(SlurmScript, WordsAreQuotedForTheShell) {
    EXPECT_EQ(shellQuoted("/data/hdri/forest.exr"), "/data/hdri/forest.exr");
    EXPECT_EQ(shellQuoted("studio lights.exr"), "'studio lights.exr'");
    EXPECT_EQ(shellQuoted("it's"), "'it'\\''s'");
    EXPECT_EQ(shellQuoted("$HOME"), "'$HOME'");
    EXPECT_EQ(shellQuoted(""), "''");
}

TEST(SlurmScript, AnArrayOverThePartsRunningOneCommand) {
    const auto text = slurmScript({"/usr/bin/iblkit", {"batch", "/w/list.txt", "-o", "/w/out dir"}, "/w/out dir/batch-shards",
                                   "/w", 5, 4, "iblkit-batch"});
    EXPECT_TRUE(text.starts_with("#!/bin/sh\n"));
    EXPECT_NE(text.find("#SBATCH --array=0-4\n"), std::string::npos) << text;
    EXPECT_NE(text.find("#SBATCH --cpus-per-task=4\n"), std::string::npos) << text;
    EXPECT_NE(text.find("#SBATCH --output='/w/out dir/batch-shards/slurm-%A_%a.out'\n"), std::string::npos) << text;
    EXPECT_NE(text.find("#SBATCH --chdir=/w\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\nexec /usr/bin/iblkit batch /w/list.txt -o '/w/out dir'\n"), std::string::npos) << text;
    EXPECT_EQ(slurmScript({"/usr/bin/iblkit", {"batch"}, "/w", "", 1, 0, "x"}).find("--cpus-per-task"), std::string::npos);
}

} // namespace
} // namespace iblkit::batch
