#include "gl_bake.hpp"

#include "kernels/kernel_steps.hpp"

#include "compiler.hpp"
#include "gl_support.hpp"
#include "kernels/kernel_parameters.hpp"
#include "suite_inputs.hpp"

namespace iblkit::consistency {
namespace {

// The environment's mip 0 as EnvMap, sampled linearly, bound at its combined slot.
struct BoundEnvironment {
    opengl::GlObject texture;
    opengl::GlObject sampler;
};
BoundEnvironment bindEnvironment(const opengl::EglContext& context, const OpenGlForm& form,
                                 const reference::CubeEnvironment& environment) {
    BoundEnvironment bound{glpath::cubeTexture(context, GL_TEXTURE_CUBE_MAP, environment.size(), 1, environment.texels()),
                           glpath::linearClampSampler(context)};
    const GLuint unit = glpath::slotOf(form, "EnvMap+EnvMapSampler");
    context.gl().BindTextureUnit(unit, bound.texture.name());
    context.gl().BindSampler(unit, bound.sampler.name());
    return bound;
}

// An RG32F or RGBA32F storage image bound at the resource's slot, layered for a cube.
opengl::GlObject bindImage(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
                           uint32_t size, bool cube) {
    auto image = cube ? glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, size, 1)
                      : glpath::texture2D(context, GL_RG32F, GL_RG, size, size);
    const GLenum format = cube ? GL_RGBA32F : GL_RG32F;
    context.gl().BindImageTexture(glpath::slotOf(form, resource), image.name(), 0, cube, 0, GL_READ_WRITE, format);
    context.check("binding an image");
    return image;
}

size_t lutValues(uint32_t size) { return size_t(size) * size * 2; }
} // namespace

OpenGlForm openGlForm(const compiler::CompileOptions& options) {
    const auto shader = compiler::compileShader(options);
    return {options.source.stem().string(), compiler::crossCompileShader(shader, compiler::CrossTarget::Glsl),
            shader.reflection.workgroupSize, shader.reflection};
}

std::vector<float> glBrdfLut(const opengl::EglContext& context, const OpenGlForm& form, uint32_t size) {
    const auto program = glpath::program(context, form);
    const auto lut = bindImage(context, form, "Precomputed", size, false);
    glpath::dispatch(context, program, form, {size, size, 1});
    return glpath::readTexture(context, lut, 0, GL_RG, lutValues(size));
}

std::vector<float> glPrefilter(const opengl::EglContext& context, const OpenGlForm& form,
                               const reference::CubeEnvironment& environment, float roughness, uint32_t size) {
    const auto program = glpath::program(context, form);
    const auto envMap = bindEnvironment(context, form, environment);
    const auto prefiltered = bindImage(context, form, "Prefiltered", size, true);
    const auto parameters = glpath::bindParameters(context, form, kernels::PrefilterParameters{roughness}.members());
    glpath::dispatch(context, program, form, {size, size, 6});
    return glpath::readTexture(context, prefiltered, 0, GL_RGBA, glpath::cubeValueCount(size));
}

std::vector<float> glBrdfLutChunks(const opengl::EglContext& context, const OpenGlForm& form, uint32_t size,
                                   uint32_t samples, uint32_t chunk) {
    const auto program = glpath::program(context, form);
    const auto accumulator = bindImage(context, form, "Accumulated", size, false);
    const auto lut = bindImage(context, form, "Precomputed", size, false);
    kernels::forEachChunk(samples, chunk, [&](uint32_t first, uint32_t count, bool last) {
        const auto parameters = glpath::bindParameters(context, form, kernels::BrdfChunkParameters{first, count, last}.members());
        glpath::dispatch(context, program, form, {size, size, 1});
    });
    return glpath::readTexture(context, lut, 0, GL_RG, lutValues(size));
}

std::vector<float> glPrefilterChunks(const opengl::EglContext& context, const OpenGlForm& form,
                                     const reference::CubeEnvironment& environment, float roughness, uint32_t size,
                                     uint32_t samples, uint32_t chunk) {
    const auto program = glpath::program(context, form);
    const auto envMap = bindEnvironment(context, form, environment);
    const auto accumulator = bindImage(context, form, "Accumulated", size, true);
    const auto prefiltered = bindImage(context, form, "Prefiltered", size, true);
    kernels::forEachChunk(samples, chunk, [&](uint32_t first, uint32_t count, bool last) {
        const kernels::PrefilterChunkParameters chunkParameters{roughness, first, count, last};
        const auto parameters = glpath::bindParameters(context, form, chunkParameters.members());
        glpath::dispatch(context, program, form, {size, size, 6});
    });
    return glpath::readTexture(context, prefiltered, 0, GL_RGBA, glpath::cubeValueCount(size));
}

} // namespace iblkit::consistency
