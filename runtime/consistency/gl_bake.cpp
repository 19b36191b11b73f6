#include "gl_bake.hpp"

#include "compiler.hpp"
#include "gl_error.hpp"
#include "gl_object.hpp"

#include <algorithm>

namespace iblkit::consistency {
namespace {

GLuint slotOf(const OpenGlForm& form, const std::string& resource) {
    for (const auto& binding : form.glsl.bindings)
        if (binding.resource == resource) return binding.slot;
    throw opengl::GlError("the GLSL form records no binding for '" + resource + "'");
}

void dispatch(const opengl::EglContext& context, const opengl::GlObject& program, const OpenGlForm& form,
              std::array<uint32_t, 3> threads) {
    const auto& gl = context.gl();
    gl.UseProgram(program.name());
    std::array<GLuint, 3> groups{};
    for (int axis = 0; axis < 3; ++axis) {
        const uint32_t size = std::max(1u, form.workgroupSize[axis]);
        groups[axis] = (threads[axis] + size - 1) / size;
    }
    gl.DispatchCompute(groups[0], groups[1], groups[2]);
    gl.MemoryBarrier(GL_ALL_BARRIER_BITS);
    gl.Finish();
    context.check("the dispatch");
}

std::vector<float> readBack(const opengl::EglContext& context, const opengl::GlObject& texture, GLenum format, size_t count) {
    std::vector<float> values(count);
    context.gl().GetTextureImage(texture.name(), 0, format, GL_FLOAT, GLsizei(count * sizeof(float)), values.data());
    context.check("the readback");
    return values;
}

} // namespace

OpenGlForm openGlForm(const compiler::CompileOptions& options) {
    const auto shader = compiler::compileShader(options);
    return {compiler::crossCompileShader(shader, compiler::CrossTarget::Glsl), shader.reflection.workgroupSize};
}

std::vector<float> glBrdfLut(const opengl::EglContext& context, const OpenGlForm& form, uint32_t size) {
    const auto& gl = context.gl();
    const auto program = opengl::createComputeProgram(context, form.glsl.source, "PrecomputedBrdfCS (GLSL)");
    const auto lut = opengl::createTexture(context, GL_TEXTURE_2D);
    gl.TextureStorage2D(lut.name(), 1, GL_RG32F, GLsizei(size), GLsizei(size));
    gl.BindImageTexture(slotOf(form, "Precomputed"), lut.name(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    context.check("binding the LUT");
    dispatch(context, program, form, {size, size, 1});
    return readBack(context, lut, GL_RG, size_t(size) * size * 2);
}

std::vector<float> glPrefilter(const opengl::EglContext& context, const OpenGlForm& form,
                               const reference::CubeEnvironment& environment, float roughness, uint32_t size) {
    const auto& gl = context.gl();
    const auto program = opengl::createComputeProgram(context, form.glsl.source, "PrefilterSpecularCS (GLSL)");
    const auto envMap = opengl::createTexture(context, GL_TEXTURE_CUBE_MAP);
    const auto n = GLsizei(environment.size());
    gl.TextureStorage2D(envMap.name(), 1, GL_RGBA32F, n, n);
    gl.TextureSubImage3D(envMap.name(), 0, 0, 0, 0, n, n, 6, GL_RGBA, GL_FLOAT, environment.texels().data());
    const auto sampler = opengl::createSampler(context);
    gl.SamplerParameteri(sampler.name(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl.SamplerParameteri(sampler.name(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        gl.SamplerParameteri(sampler.name(), wrap, GL_CLAMP_TO_EDGE);
    const GLuint unit = slotOf(form, "EnvMap+EnvMapSampler");
    gl.BindTextureUnit(unit, envMap.name());
    gl.BindSampler(unit, sampler.name());

    const auto prefiltered = opengl::createTexture(context, GL_TEXTURE_2D_ARRAY);
    gl.TextureStorage3D(prefiltered.name(), 1, GL_RGBA32F, GLsizei(size), GLsizei(size), 6);
    gl.BindImageTexture(slotOf(form, "Prefiltered"), prefiltered.name(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);

    const auto parameters = opengl::createBuffer(context);
    const float block[4] = {roughness, 0, 0, 0};
    gl.NamedBufferData(parameters.name(), sizeof block, block, GL_STATIC_DRAW);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, slotOf(form, "PrefilterSpecularParameter"), parameters.name());
    context.check("binding the prefilter's resources");
    dispatch(context, program, form, {size, size, 6});
    return readBack(context, prefiltered, GL_RGBA, size_t(size) * size * 6 * 4);
}

} // namespace iblkit::consistency
