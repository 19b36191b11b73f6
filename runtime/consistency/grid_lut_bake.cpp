#include "grid_lut_bake.hpp"

#include "gl_support.hpp"
#include "kernels/kernel_steps.hpp"

namespace iblkit::consistency {
namespace {

size_t gridValues(uint32_t gridSize) { return size_t(gridSize) * gridSize * 2; }

vulkan::Buffer gridBuffer(const vulkan::VulkanContext& context, uint32_t gridSize) {
    return vulkan::Buffer(context, gridValues(gridSize) * sizeof(float), vk::BufferUsageFlagBits::eStorageBuffer, "Grid");
}

opengl::GlObject bindGrid(const opengl::EglContext& context, const OpenGlForm& form, uint32_t gridSize,
                          std::span<const float> values = {}) {
    return glpath::bindStorageBuffer(context, form, "Grid", gridValues(gridSize) * sizeof(float), std::as_bytes(values));
}

} // namespace

std::vector<float> gpuBrdfLutGrid(const vulkan::VulkanContext& context, const PathProgram& program, uint32_t gridSize) {
    kernels::Kernel kernel(context, program);
    const auto grid = gridBuffer(context, gridSize);
    kernels::runBrdfLutGrid(kernel, grid, gridSize);
    const auto bytes = grid.read();
    const auto* values = reinterpret_cast<const float*>(bytes.data());
    return {values, values + gridValues(gridSize)};
}

std::vector<float> gpuBrdfLutResample(const vulkan::VulkanContext& context, const PathProgram& program,
                                      std::span<const float> grid, uint32_t gridSize, uint32_t size) {
    kernels::Kernel kernel(context, program);
    auto nodes = gridBuffer(context, gridSize);
    nodes.write(std::as_bytes(grid));
    vulkan::Image lut(context, {"Precomputed", &vulkan::texelFormatNamed("R32G32_SFLOAT"), size, size, 1, 1, false, true});
    kernels::runBrdfLutResample(kernel, nodes, gridSize, lut);
    return lut.download(context);
}

std::vector<float> glBrdfLutGrid(const opengl::EglContext& context, const OpenGlForm& form, uint32_t gridSize) {
    const auto program = glpath::program(context, form);
    const auto grid = bindGrid(context, form, gridSize);
    const auto parameters = glpath::bindParameters(context, form, kernels::LutGridParameters{gridSize}.members());
    glpath::dispatch(context, program, form, {gridSize, gridSize, 1});
    return glpath::readBuffer(context, grid, gridValues(gridSize));
}

std::vector<float> glBrdfLutResample(const opengl::EglContext& context, const OpenGlForm& form,
                                     std::span<const float> grid, uint32_t gridSize, uint32_t size) {
    const auto program = glpath::program(context, form);
    const auto nodes = bindGrid(context, form, gridSize, grid);
    const auto lut = glpath::texture2D(context, GL_RG32F, GL_RG, size, size);
    context.gl().BindImageTexture(glpath::slotOf(form, "Precomputed"), lut.name(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32F);
    const auto parameters = glpath::bindParameters(context, form, kernels::LutGridParameters{gridSize}.members());
    glpath::dispatch(context, program, form, {size, size, 1});
    return glpath::readTexture(context, lut, 0, GL_RG, size_t(size) * size * 2);
}

} // namespace iblkit::consistency
