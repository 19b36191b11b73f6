#include "lowering.hpp"

#include "enums.hpp"
#include "intrinsics.hpp"
#include "namespaces.hpp"
#include "refusals.hpp"
#include "sixteen_bit.hpp"

namespace iblkit::lowering {

LoweredSource lowerHlsl(const std::string& preprocessed, const std::string& sourceName, HlslVersion version,
                        bool enable16BitTypes) {
    LoweredSource lowered;
    auto tokens = lowerSixteenBitTypes(tokenize(preprocessed, sourceName), enable16BitTypes, lowered.warnings);
    if (version == HlslVersion::Hlsl2021) {
        refuseUnlowerable(tokens);
        tokens = lowerNamespaces(lowerEnums(tokens));
        tokens = lowerIntrinsics(tokens);
    }
    lowered.text = render(readVulkanAttributes(tokens, lowered.vulkan));
    lowered.warnings.insert(lowered.warnings.end(), lowered.vulkan.warnings.begin(), lowered.vulkan.warnings.end());
    lowered.changed = lowered.text != preprocessed;
    return lowered;
}

} // namespace iblkit::lowering
