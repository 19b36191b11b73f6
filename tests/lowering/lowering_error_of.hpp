#pragma once

#include "lowering.hpp"
#include "lowering_error.hpp"

#include <string>

namespace iblkit::lowering {

// The one-line message lowering `text` (as a.hlsl) is refused with, or "(no error)".
inline std::string errorOf(const std::string& text, HlslVersion version = HlslVersion::Hlsl2021) {
    try {
        lowerHlsl(text, "a.hlsl", version);
    } catch (const LoweringError& error) {
        return error.what();
    }
    return "(no error)";
}

} // namespace iblkit::lowering
