// A dispatch of more workgroups than the driver counts (lavapipe: 2^32 - 1) runs as regions
// that cover every group exactly once, with the SV_GroupID an unsplit dispatch gives.
#include "buffer.hpp"
#include "compute_program.hpp"
#include "dispatch_regions.hpp"
#include "vulkan_test_support.hpp"

#include <cstring>
#include <set>
#include <tuple>

namespace iblkit::vulkan {
namespace {

uint64_t groupsIn(const DispatchRegion& region) {
    return uint64_t(region.groups[0]) * region.groups[1] * region.groups[2];
}

TEST(DispatchRegions, ADispatchTheDriverCanCountStaysWhole) {
    const auto regions = dispatchRegions({65535, 65535, 1});
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_EQ(regions[0].groups, (std::array<uint32_t, 3>{65535, 65535, 1}));
}

// 65535³ groups once ran 196607 of them: now 65535 slabs of 65535² groups each.
TEST(DispatchRegions, TheLargestDispatchIsSplitIntoRegionsTheDriverCanCount) {
    const auto regions = dispatchRegions({65535, 65535, 65535});
    uint64_t total = 0;
    for (const auto& region : regions) {
        EXPECT_LE(groupsIn(region), kMostGroupsPerDispatch);
        total += groupsIn(region);
    }
    EXPECT_EQ(total, uint64_t(65535) * 65535 * 65535);
    EXPECT_EQ(regions.size(), 65535u);
}

TEST(DispatchRegions, EveryGroupIsCoveredExactlyOnceWhateverTheLimit) {
    for (const uint64_t most : {1u, 2u, 3u, 7u, 14u, 29u, 31u})
        for (const auto groups : {std::array<uint32_t, 3>{5, 3, 2}, std::array<uint32_t, 3>{31, 1, 1},
                                  std::array<uint32_t, 3>{1, 1, 30}}) {
            std::multiset<std::tuple<uint32_t, uint32_t, uint32_t>> covered;
            for (const auto& [base, count] : dispatchRegions(groups, most)) {
                EXPECT_LE(uint64_t(count[0]) * count[1] * count[2], most);
                for (uint32_t k = 0; k < count[2]; ++k)
                    for (uint32_t j = 0; j < count[1]; ++j)
                        for (uint32_t i = 0; i < count[0]; ++i) covered.emplace(base[0] + i, base[1] + j, base[2] + k);
            }
            EXPECT_EQ(covered.size(), size_t(groups[0]) * groups[1] * groups[2]) << most;
            EXPECT_EQ(std::set(covered.begin(), covered.end()).size(), covered.size()) << "a group ran twice";
        }
}

// With a limit of 1000 groups, 64 x 64 groups run as 5 regions; each group writes its own
// SV_GroupID where an unsplit dispatch would.
class SplitDispatch : public testing::VulkanTest {};

TEST_F(SplitDispatch, RegionsSeeTheGroupIdsOfTheWholeDispatch) {
    ContextOptions options;
    options.mostGroupsPerDispatch = 1000;
    const VulkanContext small(options);
    const auto shader = testing::compileTestShader("groups", R"(
RWStructuredBuffer<uint> Ids;
[numthreads(2, 1, 1)]
void main(uint3 group : SV_GroupID, uint index : SV_GroupIndex)
{
    if (index == 0) Ids[group.y * 64 + group.x] = group.x + 1000 * group.y + 1;
}
)");
    Buffer ids(small, 64 * 64 * 4, vk::BufferUsageFlagBits::eStorageBuffer, "Ids");
    ComputeProgram program(small, shader.spirv, shader.reflection);
    program.bind("Ids", ids);
    program.dispatchGroups(small, {64, 64, 1});
    const auto bytes = ids.read();
    std::vector<uint32_t> values(64 * 64);
    std::memcpy(values.data(), bytes.data(), bytes.size());
    for (uint32_t y = 0; y < 64; ++y)
        for (uint32_t x = 0; x < 64; ++x) ASSERT_EQ(values[y * 64 + x], x + 1000 * y + 1) << x << ", " << y;
}

} // namespace
} // namespace iblkit::vulkan
