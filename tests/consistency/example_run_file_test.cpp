// docs/examples/pbr_functions.run.json states PBR.fxh's values at two arguments; they were written
// from the C++ float twin. Here they are tied to it: computed again by the twin (and by the double
// reference) from the run file's own arguments, so a change to either the file or the twin shows.
#include "probe_bake.hpp"
#include "read_file.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace iblkit::consistency {
namespace {

TEST(ExampleRunFile, PbrFunctionsStatesWhatTheFloatTwinComputes) {
    const auto run = nlohmann::json::parse(testing::readFile("docs/examples/pbr_functions.run.json"));
    const auto& resources = run.at("resources");
    const auto arguments = resources.at("Arguments").at("values").get<std::vector<float>>();
    const auto indices = resources.at("SampleIndices").at("values").get<std::vector<uint32_t>>();
    ASSERT_EQ(resources.at("ProbeParameter").at("members").at("ArgumentCount").get<size_t>() * 4, arguments.size());
    ProbeArguments probe;
    for (size_t i = 0; i + 3 < arguments.size(); i += 4)
        probe.values.emplace_back(arguments[i], arguments[i + 1], arguments[i + 2], arguments[i + 3]);
    for (size_t i = 0; i + 1 < indices.size(); i += 2) probe.sampleIndices.emplace_back(indices[i], indices[i + 1]);

    const auto& expectation = run.at("expect").at(0);
    const auto stated = expectation.at("values").get<std::vector<double>>();
    const double tolerance = expectation.at("tolerance").at("abs").get<double>();
    const auto twin = pbrProbeReference<float>(probe);
    const auto truth = pbrProbeReference<double>(probe);
    ASSERT_EQ(stated.size(), twin.size());
    for (size_t i = 0; i < stated.size(); ++i) {
        // The file writes 8 significant digits: within half a unit of the last one.
        EXPECT_NEAR(stated[i], twin[i], 5e-8 * std::max(1.0, std::abs(stated[i]))) << "Results[" << i << "]";
        // And its tolerance holds the ground truth too: the file passes for the right reason.
        EXPECT_NEAR(stated[i], truth[i], tolerance) << "Results[" << i << "] against the double reference";
    }
}

} // namespace
} // namespace iblkit::consistency
