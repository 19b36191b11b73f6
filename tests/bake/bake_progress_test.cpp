// BakeProgress: each step's and each part's times, as --json reports them.
#include "bake_progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace iblkit::bake {
namespace {

TEST(BakeProgress, PartsTakeTheDeviceTimeAddedWhileTheyRun) {
    BakeProgress progress(true);
    progress.begin("prefilter");
    progress.addDeviceTime(1); // before any part: the step's alone
    progress.part("mip 1");
    progress.addDeviceTime(5);
    progress.addDeviceTime(2);
    progress.part("mip 2");
    progress.addDeviceTime(3);
    progress.addDeviceTime(-1); // no timestamp: nothing added
    progress.end();
    progress.begin("write");
    progress.end();
    const auto& steps = progress.steps();
    ASSERT_EQ(steps.size(), 2u);
    EXPECT_EQ(steps[0].deviceMilliseconds, 11);
    ASSERT_EQ(steps[0].parts.size(), 2u);
    EXPECT_EQ(steps[0].parts[0].name, "mip 1");
    EXPECT_EQ(steps[0].parts[0].deviceMilliseconds, 7);
    EXPECT_EQ(steps[0].parts[1].deviceMilliseconds, 3);
    EXPECT_TRUE(steps[1].parts.empty()) << "a part ends with its step";
    EXPECT_EQ(steps[1].deviceMilliseconds, 0);
}

TEST(BakeProgress, APartEndsWhereTheNextBeginsAndTheStepHoldsThemAll) {
    BakeProgress progress(true);
    progress.begin("source cube");
    progress.part("mip 0");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    progress.part("mip chain");
    progress.end();
    const auto& step = progress.steps().back();
    ASSERT_EQ(step.parts.size(), 2u);
    EXPECT_GE(step.parts[0].wallMilliseconds, 20);
    EXPECT_GE(step.wallMilliseconds, step.parts[0].wallMilliseconds + step.parts[1].wallMilliseconds);
}

} // namespace
} // namespace iblkit::bake
