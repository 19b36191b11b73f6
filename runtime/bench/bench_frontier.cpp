#include "bench_frontier.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace iblkit::bench {
namespace {

// The methods transcribed from the documents; every other method is the kit's.
constexpr const char* kDocumentMethod = "document";

double rmsError(const BenchResult& result) { return result.errorRms; }
double maxError(const BenchResult& result) { return result.errorMax; }

std::string errorText(double value, bool relative) {
    if (!relative) return fmt::format("{:.2g}", value);
    return value >= 0.1 ? fmt::format("{:.0f} %", 100 * value) : fmt::format("{:.2g} %", 100 * value);
}

// "method n (s, error) → …", and the budgets [its time, the next point's) the document owns.
std::string frontierRow(const std::string& name, const std::vector<const BenchResult*>& frontier,
                        double (*error)(const BenchResult&), bool relative) {
    std::string points, documentBudgets;
    for (size_t i = 0; i < frontier.size(); ++i) {
        const auto& result = *frontier[i];
        points += fmt::format("{}{} {} ({:.3g} s, {})", i ? " → " : "", result.method, result.samples,
                              result.deviceMilliseconds / 1e3, errorText(error(result), relative));
        if (result.method != kDocumentMethod) continue;
        const double until = i + 1 < frontier.size() ? frontier[i + 1]->deviceMilliseconds / 1e3
                                                     : std::numeric_limits<double>::infinity();
        documentBudgets += fmt::format("{}{:.3g} to {:.3g} s", documentBudgets.empty() ? "" : ", ",
                                       result.deviceMilliseconds / 1e3, until);
    }
    return fmt::format("| {} | {} | {} |\n", name, points, documentBudgets.empty() ? "none" : documentBudgets);
}

} // namespace

std::vector<const BenchResult*> resultsOf(const BenchRun& run, BenchOutput output, const std::string& environment) {
    std::vector<const BenchResult*> chosen;
    for (const auto& result : run.results)
        if (result.output == output && (output != BenchOutput::Specular || result.environment == environment))
            chosen.push_back(&result);
    return chosen;
}

std::vector<const BenchResult*> timeErrorFrontier(std::vector<const BenchResult*> results,
                                                  double (*error)(const BenchResult&)) {
    std::sort(results.begin(), results.end(), [&](const BenchResult* a, const BenchResult* b) {
        if (a->deviceMilliseconds != b->deviceMilliseconds) return a->deviceMilliseconds < b->deviceMilliseconds;
        return error(*a) < error(*b);
    });
    std::vector<const BenchResult*> frontier;
    double best = std::numeric_limits<double>::infinity();
    for (const auto* result : results)
        if (error(*result) < best) {
            best = error(*result);
            frontier.push_back(result);
        }
    return frontier;
}

std::string frontierTable(const BenchRun& run, const std::vector<std::string>& environments) {
    std::string text = "| output | fastest first, each more accurate than every faster configuration (device s, error) "
                       "| budgets where the documents' estimator is the lowest error |\n|---|---|---|\n";
    for (const auto& environment : environments)
        text += frontierRow(environment, timeErrorFrontier(resultsOf(run, BenchOutput::Specular, environment), rmsError),
                            rmsError, true);
    if (const auto lut = resultsOf(run, BenchOutput::Lut, {}); !lut.empty())
        text += frontierRow("LUT (max)", timeErrorFrontier(lut, maxError), maxError, false);
    return text;
}

} // namespace iblkit::bench
