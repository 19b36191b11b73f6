// The time-error frontier: each budget's lowest error, and who owns it.
#include "bench_frontier.hpp"

#include <gtest/gtest.h>

namespace iblkit::bench {
namespace {

BenchResult specular(const std::string& method, uint32_t samples, double milliseconds, double rms) {
    BenchResult result;
    result.output = BenchOutput::Specular;
    result.environment = "sky";
    result.method = method;
    result.samples = samples;
    result.deviceMilliseconds = milliseconds;
    result.errorRms = rms;
    result.errorMax = 10 * rms;
    return result;
}

double rms(const BenchResult& result) { return result.errorRms; }

TEST(BenchFrontier, KeepsWhatIsMoreAccurateThanEverythingFaster) {
    const std::vector<BenchResult> results{specular("document", 16, 20, 6.0), specular("table", 4, 8, 0.5),
                                           specular("table", 16, 30, 0.2), specular("document", 1024, 900, 0.7),
                                           specular("convolution", 128, 700, 0.003), specular("filtered", 16, 30, 0.9)};
    std::vector<const BenchResult*> all;
    for (const auto& result : results) all.push_back(&result);
    const auto frontier = timeErrorFrontier(all, rms);
    ASSERT_EQ(frontier.size(), 3u);
    EXPECT_EQ(frontier[0], &results[1]) << "the fastest comes first";
    EXPECT_EQ(frontier[1], &results[2]);
    EXPECT_EQ(frontier[2], &results[4]);
}

TEST(BenchFrontier, TheTableNamesTheDocumentsBudgets) {
    BenchRun run;
    run.results = {specular("document", 4, 5, 9.0), specular("table", 4, 8, 0.5), specular("convolution", 16, 500, 0.003)};
    const auto table = frontierTable(run, {"sky"});
    EXPECT_NE(table.find("| sky | document 4 (0.005 s, 900 %) → table 4 (0.008 s, 50 %) → convolution 16 (0.5 s, 0.3 %) "
                         "| 0.005 to 0.008 s |"),
              std::string::npos)
        << table;
    run.results.erase(run.results.begin());
    EXPECT_NE(frontierTable(run, {"sky"}).find("| none |"), std::string::npos);
}

} // namespace
} // namespace iblkit::bench
