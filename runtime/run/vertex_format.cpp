#include "vertex_format.hpp"

#include <array>

namespace iblkit::run {
namespace {

using vulkan::ComponentKind;

constexpr std::array kVertexFormats{
    VertexFormat{"r32f", 1, ComponentKind::Float, 4},   VertexFormat{"rg32f", 2, ComponentKind::Float, 4},
    VertexFormat{"rgb32f", 3, ComponentKind::Float, 4}, VertexFormat{"rgba32f", 4, ComponentKind::Float, 4},
    VertexFormat{"r32ui", 1, ComponentKind::UInt, 4},   VertexFormat{"rg32ui", 2, ComponentKind::UInt, 4},
    VertexFormat{"rgb32ui", 3, ComponentKind::UInt, 4}, VertexFormat{"rgba32ui", 4, ComponentKind::UInt, 4},
    VertexFormat{"r32i", 1, ComponentKind::SInt, 4},    VertexFormat{"rg32i", 2, ComponentKind::SInt, 4},
    VertexFormat{"rgb32i", 3, ComponentKind::SInt, 4},  VertexFormat{"rgba32i", 4, ComponentKind::SInt, 4},
    VertexFormat{"rgba8", 4, ComponentKind::UNorm, 1},
};

} // namespace

const vulkan::TexelFormat& VertexFormat::componentFormat() const {
    switch (kind) {
    case ComponentKind::UInt: return vulkan::texelFormatNamed("R32_UINT");
    case ComponentKind::SInt: return vulkan::texelFormatNamed("R32_SINT");
    case ComponentKind::UNorm: return vulkan::texelFormatNamed("R8G8B8A8_UNORM");
    case ComponentKind::Float: break;
    }
    return vulkan::texelFormatNamed("R32_SFLOAT");
}

const VertexFormat* findVertexFormat(std::string_view name) {
    for (const auto& format : kVertexFormats)
        if (format.name == name) return &format;
    return nullptr;
}

std::string vertexFormatNames() {
    std::string names;
    for (const auto& format : kVertexFormats) names += (names.empty() ? "" : ", ") + std::string(format.name);
    return names;
}

} // namespace iblkit::run
