#include "gl_support.hpp"

#include "block_writer.hpp"
#include "gl_error.hpp"

#include <algorithm>
#include <stdexcept>

namespace iblkit::consistency::glpath {
namespace {

const compiler::ReflectedResource& constantBuffer(const OpenGlForm& form) {
    for (const auto& resource : form.reflection.resources)
        if (resource.kind == compiler::ResourceKind::ConstantBuffer) return resource;
    throw opengl::GlError(form.name + " has no cbuffer to take parameters");
}

} // namespace

GLuint slotOf(const OpenGlForm& form, const std::string& resource) {
    for (const auto& binding : form.glsl.bindings)
        if (binding.resource == resource) return binding.slot;
    throw opengl::GlError("the GLSL form of " + form.name + " records no binding for '" + resource + "'");
}

void bindTexture(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
                 const opengl::GlObject& texture) {
    context.gl().BindTextureUnit(slotOf(form, resource), texture.name());
    context.check("binding a texture");
}

void bindLayeredImage(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
                      const opengl::GlObject& texture, uint32_t level) {
    context.gl().BindImageTexture(slotOf(form, resource), texture.name(), GLint(level), GL_TRUE, 0, GL_WRITE_ONLY,
                                  GL_RGBA32F);
    context.check("binding an image");
}

void bindImage(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
               const opengl::GlObject& texture, GLenum internalFormat) {
    context.gl().BindImageTexture(slotOf(form, resource), texture.name(), 0, GL_FALSE, 0, GL_WRITE_ONLY, internalFormat);
    context.check("binding an image");
}

opengl::GlObject program(const opengl::EglContext& context, const OpenGlForm& form) {
    return opengl::createComputeProgram(context, form.glsl.source, form.name + " (GLSL)");
}

opengl::GlObject bindParameters(const opengl::EglContext& context, const OpenGlForm& form, const kernels::NamedValues& values) {
    const auto& block = constantBuffer(form);
    const auto bytes = vulkan::packBlock(block.name, block.members, block.blockSize, values);
    auto buffer = opengl::createBuffer(context);
    context.gl().NamedBufferData(buffer.name(), GLsizeiptr(bytes.size()), bytes.data(), GL_STATIC_DRAW);
    context.gl().BindBufferBase(GL_UNIFORM_BUFFER, slotOf(form, block.name), buffer.name());
    context.check("binding the parameters");
    return buffer;
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

opengl::GlObject cubeTexture(const opengl::EglContext& context, GLenum target, uint32_t size, uint32_t mips,
                             std::span<const float> texels) {
    const auto& gl = context.gl();
    auto texture = opengl::createTexture(context, target);
    const auto n = GLsizei(size);
    if (target == GL_TEXTURE_CUBE_MAP) gl.TextureStorage2D(texture.name(), GLsizei(mips), GL_RGBA32F, n, n);
    else gl.TextureStorage3D(texture.name(), GLsizei(mips), GL_RGBA32F, n, n, 6);
    size_t offset = 0;
    for (uint32_t mip = 0; mip < mips && !texels.empty(); ++mip) {
        const auto mipSize = GLsizei(std::max(1u, size >> mip));
        gl.TextureSubImage3D(texture.name(), GLint(mip), 0, 0, 0, mipSize, mipSize, 6, GL_RGBA, GL_FLOAT, texels.data() + offset);
        offset += size_t(6) * mipSize * mipSize * 4;
    }
    context.check("making a cube texture");
    return texture;
}

opengl::GlObject texture2D(const opengl::EglContext& context, GLenum internalFormat, GLenum format, uint32_t width,
                           uint32_t height, std::span<const float> texels) {
    auto texture = opengl::createTexture(context, GL_TEXTURE_2D);
    context.gl().TextureStorage2D(texture.name(), 1, internalFormat, GLsizei(width), GLsizei(height));
    if (!texels.empty())
        context.gl().TextureSubImage2D(texture.name(), 0, 0, 0, GLsizei(width), GLsizei(height), format, GL_FLOAT, texels.data());
    context.check("making a 2D texture");
    return texture;
}

opengl::GlObject linearClampSampler(const opengl::EglContext& context) {
    const auto& gl = context.gl();
    auto sampler = opengl::createSampler(context);
    gl.SamplerParameteri(sampler.name(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl.SamplerParameteri(sampler.name(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        gl.SamplerParameteri(sampler.name(), wrap, GL_CLAMP_TO_EDGE);
    return sampler;
}

opengl::GlObject bindStorageBuffer(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
                                   size_t bytes, std::span<const std::byte> contents) {
    if (!contents.empty() && contents.size() != bytes)
        throw std::invalid_argument("storage buffer " + resource + ": contents of " + std::to_string(contents.size()) +
                                    " bytes for a buffer of " + std::to_string(bytes));
    auto buffer = opengl::createBuffer(context);
    context.gl().NamedBufferData(buffer.name(), GLsizeiptr(bytes), contents.empty() ? nullptr : contents.data(),
                                 GL_DYNAMIC_READ);
    context.gl().BindBufferBase(GL_SHADER_STORAGE_BUFFER, slotOf(form, resource), buffer.name());
    context.check("binding a storage buffer");
    return buffer;
}

std::vector<float> readTexture(const opengl::EglContext& context, const opengl::GlObject& texture, uint32_t level,
                               GLenum format, size_t count) {
    std::vector<float> values(count);
    context.gl().GetTextureImage(texture.name(), GLint(level), format, GL_FLOAT, GLsizei(count * sizeof(float)), values.data());
    context.check("the readback");
    return values;
}

std::vector<float> readBuffer(const opengl::EglContext& context, const opengl::GlObject& buffer, size_t count) {
    std::vector<float> values(count);
    context.gl().GetNamedBufferSubData(buffer.name(), 0, GLsizeiptr(count * sizeof(float)), values.data());
    context.check("the buffer readback");
    return values;
}

} // namespace iblkit::consistency::glpath
