#include "seeded_run.hpp"

#include "run_plan.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <set>

namespace iblkit::run {
namespace {

using compiler::ResourceKind;
using compiler::Varying;

// splitmix64: the same values from every compiler and library, unlike <random>'s distributions.
class Seeds {
public:
    double unit() {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return double((z ^ (z >> 31)) >> 11) / double(1ull << 53);
    }
    // Floats in [lo, hi) at a float's precision; integers in [0, 4).
    double value(const std::string& componentType, double lo = 0.0, double hi = 1.0) {
        if (componentType == "float") return double(float(lo + (hi - lo) * unit()));
        return std::floor(4.0 * unit());
    }
    std::vector<double> values(const std::string& componentType, size_t count, double lo = 0.0, double hi = 1.0) {
        std::vector<double> out(count);
        for (auto& v : out) v = value(componentType, lo, hi);
        return out;
    }

private:
    uint64_t state_ = 0x1B1C417;
};

// "float3" -> ("float", 3); types the block writer cannot set -> ("", 0).
std::pair<std::string, uint32_t> scalarAndCount(const std::string& type) {
    for (const char* scalar : {"float", "uint", "int"}) {
        const std::string prefix = scalar;
        if (type.rfind(prefix, 0) != 0) continue;
        const std::string rest = type.substr(prefix.size());
        if (rest.empty()) return {prefix, 1};
        if (rest.size() == 1 && rest[0] >= '2' && rest[0] <= '4') return {prefix, uint32_t(rest[0] - '0')};
    }
    return {"", 0};
}

std::map<std::string, std::vector<double>> seededMembers(const std::vector<compiler::BlockMember>& members, Seeds& seeds) {
    std::map<std::string, std::vector<double>> values;
    for (const auto& member : members) // matrices and arrays stay 0: the block writer sets scalars and vectors
        if (const auto [scalar, count] = scalarAndCount(member.type); count > 0) values[member.name] = seeds.values(scalar, count);
    return values;
}

std::string textureFormat(const std::string& componentType) {
    return componentType == "uint" ? "R32G32B32A32_UINT" : componentType == "int" ? "R32G32B32A32_SINT" : "R32G32B32A32_SFLOAT";
}

size_t mipChainTexels(uint32_t size) {
    size_t texels = 0;
    for (uint32_t s = size; s > 0; s /= 2) texels += size_t(s) * s;
    return texels;
}

// One resource (or element) seeded, or why it cannot be.
std::variant<ResourceSpec, std::string> seededResource(const compiler::ReflectedResource& resource, Seeds& seeds) {
    ResourceSpec spec;
    switch (resource.kind) {
    case ResourceKind::ConstantBuffer:
        spec.kind = "cbuffer";
        spec.members = seededMembers(resource.members, seeds);
        return spec;
    case ResourceKind::StorageBuffer: {
        spec.kind = "buffer";
        const bool floats = std::all_of(resource.members.begin(), resource.members.end(),
                                        [](const auto& m) { return m.type.rfind("float", 0) == 0; });
        spec.elementType = floats ? "float" : "uint";
        spec.count = std::min<size_t>(std::max<size_t>(resource.blockSize / 4, 4) * 4096, size_t(1) << 20);
        spec.initial.values = seeds.values(spec.elementType, spec.count);
        return spec;
    }
    case ResourceKind::Texture: {
        if (resource.dimension != "2d" && resource.dimension != "2d_array" && resource.dimension != "cube")
            return "a texture of dimension " + resource.dimension + ", which the run harness does not make";
        spec.kind = resource.dimension == "cube" ? "cube" : "image";
        spec.dimension = resource.dimension;
        spec.format = textureFormat(resource.componentType);
        spec.width = spec.height = 16;
        spec.layers = resource.dimension == "cube" ? 6 : resource.dimension == "2d_array" ? 2 : 1;
        spec.mips = 0;
        spec.initial.values = seeds.values(resource.componentType, mipChainTexels(16) * spec.layers * 4);
        return spec;
    }
    case ResourceKind::StorageImage:
        if (resource.dimension != "2d" && resource.dimension != "2d_array")
            return "a storage image of dimension " + resource.dimension + ", which the run harness does not make";
        spec.kind = "storage_image";
        spec.dimension = resource.dimension;
        spec.format = resource.vulkanFormat.empty() ? textureFormat(resource.componentType) : resource.vulkanFormat;
        spec.width = spec.height = 64;
        spec.layers = resource.dimension == "2d_array" ? 6 : 1;
        return spec;
    case ResourceKind::Sampler: spec.kind = "sampler"; return spec;
    case ResourceKind::TexelBuffer:
    case ResourceKind::StorageTexelBuffer: return "a texel buffer (Buffer<T>, RWBuffer<T>), which the run harness does not make";
    }
    return "an unknown kind of resource";
}

std::optional<std::string> seedResources(const compiler::ShaderReflection& reflection, Seeds& seeds, RunSpec& run) {
    for (const auto& resource : reflection.resources) {
        if (resource.location.count == 0 || resource.location.count > 64)
            return "'" + resource.name + "' is an array of " + std::to_string(resource.location.count) + " resources";
        for (uint32_t element = 0; element < resource.location.count; ++element) {
            auto seeded = seededResource(resource, seeds);
            if (auto* why = std::get_if<std::string>(&seeded)) return "'" + resource.name + "' is " + *why;
            auto& spec = std::get<ResourceSpec>(seeded);
            spec.binding = resource.name;
            spec.element = element;
            spec.name = resource.location.count > 1 ? fmt::format("{}[{}]", resource.name, element) : resource.name;
            run.resources.push_back(std::move(spec));
        }
    }
    run.pushConstants = seededMembers(reflection.pushConstants, seeds);
    return std::nullopt;
}

std::string typeOf(const Varying& varying) {
    return varying.componentType + (varying.components > 1 ? std::to_string(varying.components) : "");
}

// A value of the varying's type as a float4, uint4 or int4: its components, then zeros.
std::string padded(const Varying& varying, const std::string& value) {
    std::string text = varying.componentType + "4(" + value;
    for (uint32_t c = varying.components; c < 4; ++c) text += ", 0";
    return text + ")";
}

// The built-ins a seeded draw can give or take without a feature of its own.
std::optional<std::string> unsupportedBuiltIn(const std::vector<Varying>& varyings) {
    static const std::set<std::string> plain{"Position",  "VertexIndex", "InstanceIndex", "FragCoord", "FrontFacing",
                                             "FragDepth", "SubgroupSize", "SubgroupLocalInvocationId"};
    for (const auto& varying : varyings)
        if (!varying.builtIn.empty() && !plain.count(varying.builtIn))
            return varying.semantic + " (" + varying.builtIn + "), which a seeded draw does not give; give it a run file";
    return std::nullopt;
}

std::vector<const Varying*> userVaryings(const compiler::ShaderReflection& reflection, bool input) {
    std::vector<const Varying*> found;
    for (const auto& varying : reflection.varyings)
        if (varying.input == input && varying.builtIn.empty()) found.push_back(&varying);
    return found;
}

// The declaration of varying k at its location in a stage the kit writes.
std::string declaration(const Varying& varying, size_t k) {
    const bool flat = varying.componentType != "float";
    return fmt::format("    [[vk::location({})]] {}{} v{}{} : KIT_VARYING{};\n", varying.location, flat ? "nointerpolation " : "",
                       typeOf(varying), k, varying.locations > 1 ? fmt::format("[{}]", varying.locations) : "", k);
}

std::string targetFormat(const std::string& componentType, uint32_t components) {
    const std::string suffix = componentType == "uint" ? "32ui" : componentType == "int" ? "32i" : "32f";
    return (components == 1 ? "r" : components == 2 ? "rg" : "rgba") + suffix;
}

// A pixel shader that passes every output of a vertex shader on to a target of its own.
std::variant<StageSpec, std::string> passOnPixelShader(const compiler::ShaderReflection& vertex, const std::filesystem::path& near,
                                                       GraphicsSpec& graphics) {
    std::string inputs, writes, outputs;
    uint32_t target = 0;
    const auto varyings = userVaryings(vertex, false);
    for (size_t k = 0; k < varyings.size(); ++k) {
        const auto& varying = *varyings[k];
        inputs += declaration(varying, k);
        for (uint32_t element = 0; element < varying.locations && target < 8; ++element, ++target) {
            const std::string value = fmt::format("i.v{}{}", k, varying.locations > 1 ? fmt::format("[{}]", element) : "");
            outputs += fmt::format("    {}4 t{} : SV_Target{};\n", varying.componentType, target, target);
            writes += fmt::format("    o.t{} = {};\n", target, padded(varying, value));
            graphics.targets.push_back({fmt::format("SV_Target{}", target), targetFormat(varying.componentType, 4), 16, 16});
        }
    }
    if (target == 0) { // nothing but the position: the coverage is what the paths compare
        outputs = "    float4 t0 : SV_Target0;\n";
        writes = "    o.t0 = float4(i.position.xy, i.position.z, 1);\n";
        graphics.targets.push_back({"SV_Target0", "rgba32f", 16, 16});
    }
    const std::string text = "struct KitPixelInput\n{\n    float4 position : SV_Position;\n" + inputs + "};\n\nstruct KitPixelOutput\n{\n" +
                             outputs + "};\n\nKitPixelOutput main(KitPixelInput i)\n{\n    KitPixelOutput o;\n" + writes + "    return o;\n}\n";
    return StageSpec{near.parent_path() / ("kit-pixel-shader-for-" + near.filename().string()), "main", text};
}

// A vertex shader that draws a full-screen triangle and gives a pixel shader every input.
StageSpec fullScreenVertexShader(const compiler::ShaderReflection& pixel, const std::filesystem::path& near) {
    std::string outputs, writes;
    const auto varyings = userVaryings(pixel, true);
    for (size_t k = 0; k < varyings.size(); ++k) {
        const auto& varying = *varyings[k];
        outputs += declaration(varying, k);
        const std::string floats = "float4(uv.x, uv.y, uv.x * uv.y + 0.25, 1 - uv.x)";
        const std::string whole = varying.componentType + "4(id, id + 1, id * 2, 3)";
        const std::string source = varying.componentType == "float" ? floats : whole;
        const std::string swizzle = std::string(".xyzw").substr(0, varying.components + 1);
        const std::string value = varying.componentType + (varying.components > 1 ? std::to_string(varying.components) : "") + "(" +
                                  source + swizzle + ")";
        if (varying.locations > 1)
            for (uint32_t element = 0; element < varying.locations; ++element)
                writes += fmt::format("    o.v{}[{}] = {} * {};\n", k, element, value, element + 1);
        else
            writes += fmt::format("    o.v{} = {};\n", k, value);
    }
    const std::string text = "struct KitVertexOutput\n{\n    float4 position : SV_Position;\n" + outputs +
                             "};\n\nKitVertexOutput main(uint id : SV_VertexID)\n{\n    KitVertexOutput o;\n"
                             "    const float2 uv = float2((id << 1) & 2, id & 2);\n"
                             "    o.position = float4(uv * float2(2, -2) + float2(-1, 1), 0.5, 1);\n" +
                             writes + "    return o;\n}\n";
    return {near.parent_path() / ("kit-vertex-shader-for-" + near.filename().string()), "main", text};
}

RunSpec runOf(const compiler::CompileOptions& options) {
    RunSpec run;
    run.compileBase = options;
    run.runFile = options.source.string() + " (seeded run)";
    run.shader = options.source;
    run.entry = options.entryPoint;
    run.includeDirs = options.includeDirs;
    run.defines = options.defines;
    run.imageFormats = options.imageFormats;
    run.enable16BitTypes = options.enable16BitTypes;
    run.hlslVersion = options.hlslVersion;
    run.virtualFiles = options.virtualFiles;
    return run;
}

} // namespace

std::variant<RunSpec, std::string> seededRun(const compiler::CompileOptions& options, const compiler::ShaderReflection& reflection) {
    auto run = runOf(options);
    Seeds seeds;
    if (auto why = seedResources(reflection, seeds, run)) return *why;
    if (reflection.stage == compiler::ShaderStage::Compute) {
        run.groups = std::array<uint32_t, 3>{2, 2, 1};
        return run;
    }
    if (reflection.stage != compiler::ShaderStage::Vertex && reflection.stage != compiler::ShaderStage::Fragment)
        return std::string("a ") + std::string(compiler::stageName(reflection.stage)) + " shader, which the run harness does not run";
    if (auto why = unsupportedBuiltIn(reflection.varyings)) return *why;
    GraphicsSpec graphics;
    const StageSpec own{options.source, options.entryPoint, options.sourceText};
    if (reflection.stage == compiler::ShaderStage::Vertex) {
        graphics.vertex = own;
        const auto slots = inputSlots(reflection);
        for (const auto* input = slots.data(); input != slots.data() + slots.size(); ++input) {
            const std::string kind = input->componentType == "float" ? "32f" : input->componentType == "uint" ? "32ui" : "32i";
            const std::string format = std::string(input->components == 1 ? "r" : input->components == 2 ? "rg" : input->components == 3 ? "rgb" : "rgba") + kind;
            graphics.vertexInput.push_back({input->semantic, format, {{}, seeds.values(input->componentType, 6 * input->components, -0.9, 0.9), {}}});
        }
        auto pixel = passOnPixelShader(reflection, options.source, graphics);
        if (auto* why = std::get_if<std::string>(&pixel)) return *why;
        graphics.pixel = std::get<StageSpec>(pixel);
        graphics.draw.vertices = 6;
    } else {
        graphics.pixel = own;
        graphics.vertex = fullScreenVertexShader(reflection, options.source);
        for (const auto* output : userVaryings(reflection, false))
            graphics.targets.push_back({output->semantic, targetFormat(output->componentType, output->components == 3 ? 4 : output->components), 16, 16});
        if (std::any_of(reflection.varyings.begin(), reflection.varyings.end(), [](const auto& v) { return v.builtIn == "FragDepth"; }))
            graphics.depth = DepthSpec{"SV_Depth", 16, 16, 1.0, "always", true};
        if (graphics.targets.empty() && !graphics.depth) return std::string("a pixel shader that writes nothing to compare");
        graphics.draw.vertices = 3;
    }
    run.shader = graphics.vertex.shader;
    run.entry = graphics.vertex.entry;
    run.graphics = std::move(graphics);
    return run;
}

} // namespace iblkit::run
