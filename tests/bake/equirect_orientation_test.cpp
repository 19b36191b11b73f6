// EquirectToCubeCS puts every direction of a panorama where the cube's convention says: a
// panorama whose colour is its own direction (0.5 + 0.5 d) comes back as the direction of each
// cube texel. The field is smooth, so only bilinear interpolation error remains.
#include "kernels/kernel_steps.hpp"
#include "reference_irradiance.hpp"
#include "cube_environment.hpp"
#include "vulkan_test_support.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace iblkit::bake {
namespace {

glm::dvec3 panoramaDirection(double u, double v) {
    const double longitude = (u - 0.5) * 2 * std::numbers::pi, latitude = v * std::numbers::pi;
    return {std::sin(latitude) * std::sin(longitude), std::cos(latitude), -std::sin(latitude) * std::cos(longitude)};
}

class EquirectOrientation : public iblkit::testing::VulkanTest {};

TEST_F(EquirectOrientation, EveryCubeTexelSeesItsOwnDirection) {
    const uint32_t width = 256, height = 128, size = 32;
    std::vector<float> panorama;
    for (uint32_t row = 0; row < height; ++row)
        for (uint32_t column = 0; column < width; ++column) {
            const auto d = panoramaDirection((column + 0.5) / width, (row + 0.5) / height);
            panorama.insert(panorama.end(), {float(0.5 + 0.5 * d.x), float(0.5 + 0.5 * d.y), float(0.5 + 0.5 * d.z), 1.f});
        }
    const auto& rgba32 = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");
    vulkan::Image equirect(context(), {"Equirect", &rgba32, width, height, 1, 1, false, false});
    equirect.upload(context(), panorama);
    vulkan::Image cube(context(), {"Cube", &rgba32, size, size, 6, 1, true, true});
    using namespace kernels;
    Kernel kernel(context(), compileKernel(kernelFor(KernelRole::EquirectToCube)));
    runEquirectToCube(kernel, equirect, cube, {2});
    const auto texels = cube.download(context());

    double worst = 0;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t row = 0; row < size; ++row)
            for (uint32_t column = 0; column < size; ++column) {
                const auto d = glm::normalize(reference::cubeTexelDirection(face, column, row, size));
                const float* t = &texels[((size_t(face) * size + row) * size + column) * 4];
                const glm::dvec3 seen(2.0 * t[0] - 1, 2.0 * t[1] - 1, 2.0 * t[2] - 1);
                worst = std::max(worst, glm::length(seen - d));
            }
    RecordProperty("max_direction_error", std::to_string(worst));
    // Measured 3.6e-4: interpolating a sphere's directions linearly across 1.4° panorama
    // texels; bound 1e-3. A wrong face, flip or longitude origin is off by 0.5 or more.
    EXPECT_LT(worst, 1e-3);
}

} // namespace
} // namespace iblkit::bake
