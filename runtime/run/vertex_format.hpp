#pragma once

#include "texel_format.hpp"

#include <string>
#include <string_view>

namespace iblkit::run {

// A per-vertex attribute's format, as Direct3D's input layout gives it: 32-bit floats or
// integers of one to four components, or four 8-bit normalized ones.
struct VertexFormat {
    std::string_view name; // "rgb32f", "rg32ui", "rgba8"
    uint32_t components;
    vulkan::ComponentKind kind;
    uint32_t bytesPerComponent;

    uint32_t bytesPerVertex() const { return components * bytesPerComponent; }
    // The texel format of one component: how the run's values become bytes.
    const vulkan::TexelFormat& componentFormat() const;
};

// nullptr for a name that is none of them.
const VertexFormat* findVertexFormat(std::string_view name);
std::string vertexFormatNames();

} // namespace iblkit::run
