#include "dispatch_regions.hpp"

#include <algorithm>

namespace iblkit::vulkan {

std::vector<DispatchRegion> dispatchRegions(std::array<uint32_t, 3> groups, uint64_t mostGroups) {
    const uint64_t x = groups[0], y = groups[1], z = groups[2];
    if (x * y * z <= mostGroups) return {{{0, 0, 0}, groups}};
    const uint64_t runX = std::min<uint64_t>(x, std::max<uint64_t>(1, mostGroups));
    const uint64_t rowsY = runX < x ? 1 : std::min<uint64_t>(y, std::max<uint64_t>(1, mostGroups / x));
    const uint64_t slabsZ = rowsY < y || runX < x ? 1 : std::min<uint64_t>(z, std::max<uint64_t>(1, mostGroups / (x * y)));
    std::vector<DispatchRegion> regions;
    for (uint64_t k = 0; k < z; k += slabsZ)
        for (uint64_t j = 0; j < y; j += rowsY)
            for (uint64_t i = 0; i < x; i += runX)
                regions.push_back({{uint32_t(i), uint32_t(j), uint32_t(k)},
                                   {uint32_t(std::min(runX, x - i)), uint32_t(std::min(rowsY, y - j)),
                                    uint32_t(std::min(slabsZ, z - k))}});
    return regions;
}

} // namespace iblkit::vulkan
