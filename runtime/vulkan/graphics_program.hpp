#pragma once

#include "buffer.hpp"
#include "compute_program.hpp"
#include "image.hpp"
#include "resource_bindings.hpp"
#include "vulkan_context.hpp"

#include "reflection.hpp"

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace iblkit::vulkan {

// One vertex attribute: a buffer of its own, read per vertex at a shader input location.
struct VertexAttributeDesc {
    uint32_t location;
    vk::Format format;
    uint32_t stride; // bytes per vertex
};

enum class BlendMode { None, Alpha, Premultiplied, Additive };

struct ColorTargetDesc {
    uint32_t location; // SV_TargetN
    const TexelFormat* format;
    BlendMode blend = BlendMode::None;
};

struct DepthTargetDesc {
    vk::CompareOp test = vk::CompareOp::eLess;
    bool write = true;
};

// The fixed-function state of a draw. Direct3D's conventions: the viewport's y runs down from
// the target's first row, NDC y = +1 lands there, and depth is 0 to 1.
struct GraphicsStateDesc {
    std::vector<VertexAttributeDesc> attributes;
    std::vector<ColorTargetDesc> colorTargets;
    std::optional<DepthTargetDesc> depth; // a D32_SFLOAT target
    vk::PrimitiveTopology topology = vk::PrimitiveTopology::eTriangleList;
    vk::CullModeFlags cull = vk::CullModeFlagBits::eNone;
    bool frontClockwise = true; // as the triangle appears in the target
};

struct Viewport {
    float x, y, width, height, minDepth = 0.0f, maxDepth = 1.0f;
};

// What a draw writes: an image per colour target (in GraphicsStateDesc's order) and the depth
// image, each with the value it is cleared to first.
struct DrawTargets {
    std::vector<Image*> colors;
    std::vector<std::array<double, 4>> clearColors;
    Image* depth = nullptr;
    double clearDepth = 1.0;
};

struct DrawCall {
    uint32_t count = 0;       // vertices, or indices when an index buffer is given
    uint32_t instances = 1;
    uint32_t firstVertex = 0; // the first index when indexed
    uint32_t firstInstance = 0;
    int32_t baseVertex = 0;   // added to every index
    std::vector<const Buffer*> vertexBuffers; // one per attribute, in GraphicsStateDesc's order
    const Buffer* indices = nullptr;          // 32-bit indices
    std::optional<Viewport> viewport;         // the whole target when absent
};

// A vertex and a pixel shader ready to draw: one pipeline, its render pass, resources bound by
// their HLSL names in either stage.
class GraphicsProgram {
public:
    GraphicsProgram(const VulkanContext& context, const std::vector<uint32_t>& vertexSpirv,
                    const compiler::ShaderReflection& vertexReflection, const std::vector<uint32_t>& pixelSpirv,
                    const compiler::ShaderReflection& pixelReflection, const GraphicsStateDesc& state,
                    const std::map<std::string, double>& specialization = {});

    // The resources of both stages, by name.
    const compiler::ShaderReflection& reflection() const { return bindings_.reflection(); }
    void bind(const std::string& name, const Buffer& buffer, uint32_t element = 0) { bindings_.bind(name, buffer, element); }
    void bind(const std::string& name, Image& image, uint32_t mip = 0, uint32_t element = 0) {
        bindings_.bind(name, image, mip, element);
    }
    void bind(const std::string& name, const Sampler& sampler, uint32_t element = 0) { bindings_.bind(name, sampler, element); }
    void setPushConstants(std::span<const std::byte> bytes) { bindings_.setPushConstants(bytes); }

    // Clears the targets, draws and waits. Throws VulkanError for targets that do not match the
    // state the program was made with.
    SubmissionTiming draw(const VulkanContext& context, const DrawTargets& targets, const DrawCall& call);

private:
    GraphicsStateDesc state_;
    ResourceBindings bindings_;
    vk::raii::RenderPass renderPass_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
};

// The resources of a vertex and a pixel shader as one table: a resource both use must sit at
// the same set and binding in each. Throws VulkanError naming a clash.
compiler::ShaderReflection mergeStageReflections(const compiler::ShaderReflection& vertex,
                                                 const compiler::ShaderReflection& pixel);

} // namespace iblkit::vulkan
