#include "convolution_bake.hpp"

#include "gl_support.hpp"

#include <bit>

namespace iblkit::consistency {
namespace {

void appendLevels(const opengl::EglContext& context, const opengl::GlObject& texture, uint32_t size,
                  std::vector<float>& values) {
    for (uint32_t level = 0; (size >> level) > 0; ++level) {
        const auto texels = glpath::readTexture(context, texture, level, GL_RGBA, glpath::cubeValueCount(size >> level));
        values.insert(values.end(), texels.begin(), texels.end());
    }
}

} // namespace

// Each level reads the one below from the texture units and writes its own as images.
std::vector<float> glClusterPyramid(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube) {
    if (cube.size < 2) return {}; // a single texel is no block of the pyramid
    const auto program = glpath::program(context, form);
    const auto source = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, cube.size, cube.mips, cube.texels);
    glpath::bindTexture(context, form, "Source", source);
    const uint32_t size = kernels::pyramidSize(cube.size), levels = uint32_t(std::bit_width(size));
    const auto energy = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, size, levels);
    const auto centroid = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, size, levels);
    const auto geometry = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, size, levels);
    glpath::bindTexture(context, form, "EnergyIn", energy);
    glpath::bindTexture(context, form, "CentroidIn", centroid);
    glpath::bindTexture(context, form, "GeometryIn", geometry);
    const auto solidAngle = glpath::texture2D(context, GL_R32F, GL_RED, cube.size, cube.size);
    glpath::bindImage(context, form, "TexelSolidAngle", solidAngle, GL_R32F);
    for (uint32_t level = 0; level < levels; ++level) {
        glpath::bindLayeredImage(context, form, "Energy", energy, level);
        glpath::bindLayeredImage(context, form, "Centroid", centroid, level);
        glpath::bindLayeredImage(context, form, "Geometry", geometry, level);
        const auto parameters = glpath::bindParameters(context, form, kernels::ClusterParameters{level}.members());
        glpath::dispatch(context, program, form, {size >> level, size >> level, 6});
    }
    std::vector<float> values;
    for (const auto* texture : {&energy, &centroid, &geometry}) appendLevels(context, *texture, size, values);
    return values;
}

std::vector<float> glPrefilterConvolution(const opengl::EglContext& context, const OpenGlForm& form,
                                          const PyramidTexels& pyramid, uint32_t outSize,
                                          const kernels::PrefilterConvolutionParameters& parameters) {
    const auto program = glpath::program(context, form);
    const auto upload = [&](const MippedCube& cube) {
        return glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, cube.size, cube.mips, cube.texels);
    };
    const auto source = upload(pyramid.source);
    const auto energy = upload(pyramid.energy), centroid = upload(pyramid.centroid), geometry = upload(pyramid.geometry);
    const auto solidAngle =
        glpath::texture2D(context, GL_R32F, GL_RED, pyramid.source.size, pyramid.source.size, pyramid.texelSolidAngle);
    if (!pyramid.holdsSourceTexels) { // the walk makes the texels it reaches
        glpath::bindTexture(context, form, "Source", source);
        glpath::bindTexture(context, form, "TexelSolidAngle", solidAngle);
    }
    glpath::bindTexture(context, form, "Energy", energy);
    glpath::bindTexture(context, form, "Centroid", centroid);
    glpath::bindTexture(context, form, "Geometry", geometry);
    const auto target = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, outSize, 1);
    glpath::bindLayeredImage(context, form, "Prefiltered", target, 0);
    const auto bound = glpath::bindParameters(context, form, parameters.members());
    glpath::dispatch(context, program, form, {outSize, outSize, 6});
    return glpath::readTexture(context, target, 0, GL_RGBA, glpath::cubeValueCount(outSize));
}

} // namespace iblkit::consistency
