// ForwardSpheres — the preview's spheres drawn as an engine draws meshes — on every path of the run
// harness (Vulkan from the SPIR-V, Vulkan from the HLSL form, OpenGL from the GLSL form), each
// judged against SplitSumSpheresCS's image on path a: the kit's shading as an engine uses it must
// give the kit's own picture.
#include "consistency_suite.hpp"
#include "render_outputs.hpp"
#include "suite_run.hpp"

#include "kernels/kernel_steps.hpp"
#include "render/sphere_grid.hpp"
#include "run_executor.hpp"
#include "shading/lobe_table.hpp"
#include "shading/shading_recipe.hpp"
#include "shading/sphere_transmission.hpp"
#include "shading/transmission_table.hpp"
#include "shading_maps.hpp"

#include <fmt/core.h>

#include <cmath>
#include <numbers>
#include <sstream>

namespace iblkit::consistency {
namespace {

constexpr uint32_t kCellSize = 8;
// The unit sphere's mesh: 96 segments around, 48 rings from pole to pole.
constexpr uint32_t kSegments = 96, kRings = 48;

struct SphereMesh {
    std::vector<double> positions; // x, y, z per vertex, on the unit sphere
    std::vector<uint32_t> indices;
};

SphereMesh unitSphere() {
    SphereMesh mesh;
    for (uint32_t ring = 0; ring <= kRings; ++ring) {
        const double theta = std::numbers::pi * ring / kRings;
        for (uint32_t segment = 0; segment <= kSegments; ++segment) {
            const double phi = 2.0 * std::numbers::pi * segment / kSegments;
            mesh.positions.insert(mesh.positions.end(), {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
        }
    }
    for (uint32_t ring = 0; ring < kRings; ++ring)
        for (uint32_t segment = 0; segment < kSegments; ++segment) {
            const uint32_t a = ring * (kSegments + 1) + segment, b = a + kSegments + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    return mesh;
}

const render::SphereGrid& grid() { return render::defaultSphereGrid(); }

std::vector<double> asDoubles(std::span<const float> values) { return {values.begin(), values.end()}; }

run::ResourceSpec imageResource(const std::string& name, const std::string& kind, const std::string& format, uint32_t width,
                                uint32_t height, uint32_t mips, std::span<const float> values) {
    run::ResourceSpec spec;
    spec.name = spec.binding = name;
    spec.kind = kind;
    spec.format = format;
    spec.dimension = kind == "cube" ? "cube" : "2d";
    spec.width = width;
    spec.height = height;
    spec.layers = kind == "cube" ? 6 : 1;
    spec.mips = mips;
    spec.initial.values = asDoubles(values);
    return spec;
}

run::ResourceSpec bufferResource(const std::string& name, std::span<const float> values) {
    run::ResourceSpec spec;
    spec.name = spec.binding = name;
    spec.kind = "buffer";
    spec.initial.values = asDoubles(values);
    return spec;
}

// The draw: every sphere an instance of one mesh, depth-tested, over the grid SplitSumSpheresCS
// writes, with the maps it reads.
run::RunSpec forwardRun(const compiler::CompileOptions& shader, const PreviewInputs& maps) {
    run::RunSpec spec;
    spec.runFile = shader.source.string() + " (the suite's forward pass)";
    spec.includeDirs = shader.includeDirs;
    spec.defines = shader.defines;
    spec.virtualFiles = shader.virtualFiles;
    run::GraphicsSpec graphics;
    graphics.vertex = {shader.source, "VSMain", shader.sourceText};
    graphics.pixel = {shader.source, "PSMain", shader.sourceText};
    const auto mesh = unitSphere();
    graphics.vertexInput.push_back({"POSITION", "rgb32f", {{}, mesh.positions, {}}});
    graphics.indices = mesh.indices;
    graphics.draw.instances = uint32_t(grid().columns() * grid().rowCount());
    const uint32_t width = grid().columns() * kCellSize, height = grid().rowCount() * kCellSize;
    graphics.targets.push_back({"SV_Target0", "R32G32B32A32_SFLOAT", width, height});
    graphics.depth = run::DepthSpec{"SV_Depth", 0, 0, 1.0, "less", true};
    graphics.cull = "back";
    spec.shader = graphics.vertex.shader;
    spec.entry = graphics.vertex.entry;
    spec.graphics = std::move(graphics);

    run::ResourceSpec parameters;
    parameters.name = parameters.binding = "SplitSumParameter";
    parameters.kind = "cbuffer";
    parameters.members = splitSumParameters(maps).members();
    spec.resources.push_back(std::move(parameters));
    spec.resources.push_back(imageResource("Specular", "cube", "R32G32B32A32_SFLOAT", maps.specular.size, maps.specular.size,
                                           maps.specular.mips, maps.specular.texels));
    spec.resources.push_back(imageResource("IrradianceMap", "cube", "R32G32B32A32_SFLOAT", maps.irradiance.size, maps.irradiance.size,
                                           maps.irradiance.mips, maps.irradiance.texels));
    spec.resources.push_back(imageResource("BrdfLut", "image", "R32G32_SFLOAT", maps.lutSize, maps.lutSize, 1, maps.lut));
    spec.resources.push_back(imageResource("LobeTable", "image", "R32G32B32A32_SFLOAT", shading::kLobeTableSize,
                                           shading::kLobeTableSize, 1, maps.lobeTable));
    const auto transmission = shading::defaultRecipe().glass.transmission;
    const auto layers = uint32_t(shading::kTransmissionEtas.size());
    const uint32_t interfaceSize = bake::transmissionTableSize(transmission), sphereSize = bake::sphereTransmissionTableSize(transmission);
    spec.resources.push_back(imageResource("TransmissionTable", "image", "R32G32_SFLOAT", interfaceSize, interfaceSize * layers, 1,
                                           bake::transmissionTableOf(interfaceSize)));
    spec.resources.push_back(imageResource("SphereTransmissionTable", "image", "R32G32B32A32_SFLOAT", sphereSize, sphereSize * layers, 1,
                                           bake::sphereTransmissionTableOf(sphereSize)));
    spec.resources.push_back(bufferResource("Lights", maps.lights));
    spec.resources.push_back(bufferResource("Spheres", sphereMaterials()));
    run::ResourceSpec sampler;
    sampler.name = sampler.binding = "LinearClamp";
    sampler.kind = "sampler";
    spec.resources.push_back(std::move(sampler));
    return spec;
}

// Both images where both cover the pixel, and 0 elsewhere: what a mesh's polygon leaves out of
// the sphere's silhouette is no error of the shading.
struct CoveredByBoth {
    std::vector<float> drawn;
    std::vector<double> computed;
};

CoveredByBoth whereBothCover(std::span<const double> drawn, std::span<const float> computed) {
    CoveredByBoth both{std::vector<float>(drawn.size(), 0.f), std::vector<double>(drawn.size(), 0.0)};
    for (size_t pixel = 0; pixel + 3 < drawn.size() && pixel + 3 < computed.size(); pixel += 4)
        if (drawn[pixel + 3] > 0 && computed[pixel + 3] > 0)
            for (size_t c = 0; c < 4; ++c) {
                both.drawn[pixel + c] = float(drawn[pixel + c]);
                both.computed[pixel + c] = computed[pixel + c];
            }
    return both;
}

} // namespace

void addForwardPassOutput(SuiteRun& run) {
    if (!run.runs(kForwardPassShader)) return;
    const auto maps = splitSumMaps(run.options);
    const auto computed = gpuSplitSum(run.vulkan, run.program("SplitSumSpheresCS", ShaderPath::Glslang), maps);
    std::ostringstream log;
    run::RunOptions options;
    options.api = run::RunApi::All;
    const auto summary = run::executeRunOnPaths(forwardRun(run.options.shaders.at(kForwardPassShader), maps), options, log);
    const OutputSpec spec{kForwardPassShader,
                          fmt::format("{}×{} spheres drawn as {}×{} meshes, against SplitSumSpheresCS on path a where both cover",
                                      grid().columns() * kCellSize, grid().rowCount() * kCellSize, kSegments, kRings),
                          forwardPassBounds()};
    for (const auto& path : summary.paths) {
        const std::string name = "drawn: " + path.path;
        if (!path.ran) throw std::runtime_error(std::string(kForwardPassShader) + " did not run on the " + path.path + " path: " + path.notRun);
        const auto both = whereBothCover(summary.written.at(path.path).at("SV_Target0"), computed);
        const References references{std::vector<float>(both.computed.begin(), both.computed.end()), both.computed};
        addJudgedRow(run, spec, name, both.drawn, references);
    }
}

} // namespace iblkit::consistency
