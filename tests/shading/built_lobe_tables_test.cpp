// The lobe tables built with the kit (lobe_tables_main.cpp) against lobeTable run here: every
// texel of both weightings, exactly.
#include "shading/built_lobe_tables.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace iblkit::shading {
namespace {

TEST(BuiltLobeTables, AreTheLobeTablesOfBothWeightings) {
    for (const auto weighting : {LobeWeighting::NdotL, LobeWeighting::G1}) {
        const auto built = builtLobeTable(weighting);
        const auto computed = lobeTable(kLobeTableSize, weighting);
        EXPECT_EQ(std::vector<float>(built.begin(), built.end()), computed) << nameOf(weighting);
    }
    EXPECT_NE(builtLobeTable(LobeWeighting::NdotL)[1], builtLobeTable(LobeWeighting::G1)[1]) << "each weighting its own";
}

} // namespace
} // namespace iblkit::shading
