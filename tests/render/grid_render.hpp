#pragma once
// The sphere grid rendered by both images at 9-pixel cells, and what its sphere centres must be,
// shared by the render's GPU tests.
#include "render/baked_maps.hpp"
#include "render/reference_render.hpp"
#include "render/render_settings.hpp"
#include "render/sphere_grid.hpp"
#include "render/split_sum_render.hpp"

#include "kernels/kernel_table.hpp"
#include "reference/path_tracer_bsdf.hpp"

#include <cmath>
#include <numbers>

namespace iblkit::render::grid_test {

// Odd, so that the middle pixel of a cell looks at its sphere head on: N = V = +Z.
constexpr uint32_t kCell = 9;
constexpr double kFloorShare = 0.1;

inline const SphereGrid& grid() { return defaultSphereGrid(); }
inline uint32_t columns() { return grid().columns(); }
// The grid's opaque rows come first, then its glass.
inline uint32_t opaqueRows() {
    uint32_t rows = 0;
    while (rows < grid().rowCount() && !grid().rows[rows].glass()) ++rows;
    return rows;
}

inline bake::EnvironmentInput uniformEnvironment(float radiance) {
    bake::EnvironmentInput input;
    input.kind = bake::InputKind::Cube;
    input.cubeSize = 16;
    input.cubeTexels.assign(6 * 16 * 16 * 4, radiance);
    return input;
}

struct Rendered {
    SphereImage splitSum;
    ReferenceImage reference;
};

inline size_t centreOf(uint32_t row, uint32_t column) {
    return size_t(row * kCell + kCell / 2) * (columns() * kCell) + column * kCell + kCell / 2;
}

// Which pixels the reference traces: every pixel a sphere covers, or only each cell's centre, for
// the tests that read no other (a 57th of the paths).
enum class Traced { EveryPixel, Centres };

inline SphereImage coverageOf(const SphereImage& splitSum, Traced traced) {
    if (traced == Traced::EveryPixel) return splitSum;
    SphereImage centres{splitSum.width, splitSum.height, std::vector<float>(splitSum.rgba.size(), 0.f)};
    for (uint32_t row = 0; row < grid().rowCount(); ++row)
        for (uint32_t column = 0; column < columns(); ++column) centres.rgba[4 * centreOf(row, column) + 3] = 1.f;
    return centres;
}

// 8192 paths per pixel, fewer where every pixel is within `bound` sooner.
inline Rendered renderGrid(const bake::EnvironmentInput& input, const std::vector<RenderLight>& lights, ReferenceBsdf bsdf,
                           double bound, const kernels::ShaderFiles& files = kernels::embeddedShaderFiles(),
                           uint32_t pathsPerDispatch = 0, Traced traced = Traced::EveryPixel) {
    const vulkan::VulkanContext context(vulkan::ContextOptions{});
    bake::BakeProgress progress(true);
    auto maps = bakeMaps(context, input, shading::defaultRecipe(), progress);
    auto splitSumKernel = bake::makeKernel(context, kernels::KernelRole::RenderSplitSum);
    kernels::Kernel referenceKernel(
        context, kernels::compileKernel(kernels::kernelFor(kernels::KernelRole::RenderReference, methodOf(bsdf)), {}, {}, files));
    auto splitSum = renderSplitSum(context, splitSumKernel, grid(), maps, kCell, progress);
    auto reference = renderReference(context, referenceKernel, grid(), maps.source, lights, coverageOf(splitSum, traced),
                                     {kCell, 8192, 7, kFloorShare, bound, pathsPerDispatch}, progress);
    return {std::move(splitSum), std::move(reference)};
}

// renderGrid's reference at the cells' centres alone.
inline Rendered renderCentres(const bake::EnvironmentInput& input, const std::vector<RenderLight>& lights, ReferenceBsdf bsdf,
                              double bound, const kernels::ShaderFiles& files = kernels::embeddedShaderFiles()) {
    return renderGrid(input, lights, bsdf, bound, files, 0, Traced::Centres);
}

inline glm::dvec3 rgbAt(const std::vector<float>& rgba, size_t pixel) {
    return {rgba[4 * pixel], rgba[4 * pixel + 1], rgba[4 * pixel + 2]};
}

inline reference::SurfacePoint<double> opaqueSphere(uint32_t row, uint32_t column) {
    reference::SurfacePoint<double> X;
    X.Albedo = glm::dvec3(grid().rows[row].albedo);
    X.Roughness = grid().roughness[column];
    X.Metalness = grid().rows[row].metalness;
    return X;
}

// The integral of BSDF(L, N) cos over the hemisphere for V = N, in double: symmetric about N, a
// single integral in theta, on a grid dense where the mirror-like lobes are (theta = pi/2 t²).
inline glm::dvec3 directionalAlbedo(const reference::SurfacePoint<double>& X) {
    const glm::dvec3 N(0, 0, 1);
    const int steps = 400000;
    glm::dvec3 sum(0);
    for (int i = 0; i < steps; ++i) {
        const double t = (i + 0.5) / steps, theta = std::numbers::pi / 2 * t * t;
        const double dTheta = std::numbers::pi * t / steps;
        const glm::dvec3 L(std::sin(theta), 0, std::cos(theta));
        sum += reference::BSDF(X, L, N) * std::cos(theta) * std::sin(theta) * dTheta;
    }
    return 2 * std::numbers::pi * sum;
}

} // namespace iblkit::render::grid_test
