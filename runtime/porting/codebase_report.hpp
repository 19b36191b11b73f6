#pragma once

#include "codebase_run.hpp"

#include <string>
#include <vector>

namespace iblkit::porting {

// The totals a report gives, over every configuration but the whole stages the kit refuses.
struct PortingTotals {
    size_t configurations = 0; // all of them
    size_t refusedStages = 0;  // ray tracing, mesh, amplification
    size_t reachedSpirv = 0, everyForm = 0, allSixForms = 0;
    // Seeded runs: run on Vulkan with every other path that could take it agreeing; on all three agreeing;
    // run at all; and differing (or crashing).
    size_t sameWhereRun = 0, sameEveryPath = 0, ran = 0, differ = 0;
    size_t counted() const { return configurations - refusedStages; }
};
PortingTotals portingTotals(const std::vector<CodeBaseResults>& results);

// Failures grouped by cause (failureCause), the most frequent first: cause, count, code bases.
struct CauseCount {
    std::string cause;
    size_t count = 0;
    std::vector<std::string> codeBases;
};
std::vector<CauseCount> causesOf(const std::vector<CodeBaseResults>& results);

// The report in markdown: the totals, the causes, which of the kit's edits each code base needed,
// and every configuration with its forms. `command` is what regenerates it.
std::string codeBaseMarkdown(const std::vector<CodeBaseResults>& results, const std::string& command);

// The same as JSON, for CI.
std::string codeBaseJson(const std::vector<CodeBaseResults>& results);

} // namespace iblkit::porting
