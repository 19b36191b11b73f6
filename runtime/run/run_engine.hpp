#pragma once

#include "run_file.hpp"
#include "texel_format.hpp"
#include "vertex_format.hpp"

#include "reflection.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace iblkit::run {

// An image's extent, in the order its values cross the API: mip, layer (cube face), row,
// column, channel.
struct ImageShape {
    const vulkan::TexelFormat* format = nullptr;
    uint32_t width = 0, height = 0, layers = 1, mips = 1;
    bool cube = false;

    uint32_t mipWidth(uint32_t mip) const { return std::max(1u, width >> mip); }
    uint32_t mipHeight(uint32_t mip) const { return std::max(1u, height >> mip); }
    size_t valueOffset(uint32_t mip, uint32_t layer) const; // where a mip's layer starts
    size_t valueCount() const { return valueOffset(mips, 0); }
};

// A shader compiled for the run: what Vulkan runs and what the other forms come from.
struct ShaderProgram {
    std::vector<uint32_t> spirv;      // as Vulkan runs it
    std::vector<uint32_t> namedSpirv; // names kept: the GLSL form comes from it
    compiler::ShaderReflection reflection;
    std::string sourceName;
};

// The shaders of a run: one compute shader, or a vertex and a pixel shader.
struct RunPrograms {
    std::optional<ShaderProgram> compute, vertex, pixel;
    compiler::ShaderReflection resources; // every stage's resources and push constants, by name
};

// A resource ready to be made, the same for every API.
struct ResourcePlan {
    const ResourceSpec* spec = nullptr;
    const compiler::ReflectedResource* reflected = nullptr;
    // Buffers, cbuffers and images: the initial contents, worked out from the run file when the
    // engine has made the resource (so that a size the device refuses is named before gigabytes
    // of values are). Throws RunError for values that do not fit the resource.
    std::function<std::vector<std::byte>()> contents;
    size_t bufferSize = 0;            // buffers and cbuffers: bytes allocated (at least the contents')
    std::optional<ImageShape> image;  // images
    const vulkan::TexelFormat* format = nullptr; // buffers: what their elements are
};

// One attribute of a draw, located in the vertex shader.
struct AttributePlan {
    std::string semantic;
    uint32_t location = 0;
    const VertexFormat* format = nullptr;
    std::vector<std::byte> bytes;
};

// A render target of a draw, located in the pixel shader.
struct TargetPlan {
    const TargetSpec* spec = nullptr;
    uint32_t location = 0;
    ImageShape shape;
};

struct DrawPlan {
    const GraphicsSpec* spec = nullptr;
    std::vector<AttributePlan> attributes;
    std::vector<TargetPlan> targets;
    std::optional<ImageShape> depth;
    uint32_t count = 0; // vertices, or indices when indexed
};

// Values read back from a resource or a target.
struct Readback {
    std::vector<double> values;
    const vulkan::TexelFormat* format = nullptr;
    std::optional<ImageShape> image; // absent for buffers
};

// An API that carries out a run file: Vulkan from the SPIR-V, OpenGL from the GLSL form. The
// run's logic (names, values, expectations, saves) is the executor's and the same for each.
class RunEngine {
public:
    virtual ~RunEngine() = default;
    virtual std::string apiName() const = 0;   // "vulkan", "opengl"
    virtual std::string deviceLine() const = 0; // the device and driver
    virtual void makeProgram(const RunSpec& spec, const RunPrograms& programs, const DrawPlan* draw) = 0;
    virtual void makeResource(const ResourcePlan& plan) = 0;
    virtual void setPushConstants(std::span<const std::byte> bytes) = 0;
    // Dispatches or draws and waits; returns the line that reports it.
    virtual std::string execute(const RunSpec& spec, const DrawPlan* draw) = 0;
    // A resource by its run-file name, or a target by its semantic as the run file writes it.
    virtual Readback read(const std::string& name) = 0;
    virtual std::vector<std::string> validationMessages() const { return {}; }
};

} // namespace iblkit::run
