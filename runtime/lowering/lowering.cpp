#include "lowering.hpp"

#include "enums.hpp"
#include "intrinsics.hpp"
#include "namespaces.hpp"
#include "refusals.hpp"

namespace iblkit::lowering {

LoweredSource lowerHlsl(const std::string& preprocessed, const std::string& sourceName, HlslVersion version) {
    auto tokens = tokenize(preprocessed, sourceName);
    if (version == HlslVersion::Hlsl2021) {
        refuseUnlowerable(tokens);
        tokens = lowerNamespaces(lowerEnums(tokens));
        tokens = lowerIntrinsics(tokens);
    }
    LoweredSource lowered;
    lowered.text = render(readVulkanAttributes(tokens, lowered.vulkan));
    lowered.changed = lowered.text != preprocessed;
    return lowered;
}

} // namespace iblkit::lowering
