#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace iblkit::vulkan {

// lavapipe counts a dispatch's workgroups in 32 bits: 65535³ groups ran 65535³ mod 2^32 = 196607
// of them, and reported success. A dispatch of more groups is split into regions of at most
// this many, each recorded with vkCmdDispatchBase so that SV_GroupID is the same as unsplit.
inline constexpr uint64_t kMostGroupsPerDispatch = 0xFFFFFFFFu;

struct DispatchRegion {
    std::array<uint32_t, 3> base;
    std::array<uint32_t, 3> groups;
};

// Regions that cover `groups` exactly once, each of at most `mostGroups` groups (at least 1):
// slabs along z, then rows along y, then runs along x.
std::vector<DispatchRegion> dispatchRegions(std::array<uint32_t, 3> groups, uint64_t mostGroups = kMostGroupsPerDispatch);

} // namespace iblkit::vulkan
