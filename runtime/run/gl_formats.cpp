#include "gl_formats.hpp"

#include "gl_error.hpp"

#include <string>

namespace iblkit::run {

GlTexelFormat glTexelFormatOf(const vulkan::TexelFormat& format) {
    using vulkan::ComponentKind;
    if (format.depth()) return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT};
    static const GLenum floats32[] = {GL_R32F, GL_RG32F, 0, GL_RGBA32F};
    static const GLenum floats16[] = {GL_R16F, GL_RG16F, 0, GL_RGBA16F};
    static const GLenum uints[] = {GL_R32UI, GL_RG32UI, 0, GL_RGBA32UI};
    static const GLenum sints[] = {GL_R32I, GL_RG32I, 0, GL_RGBA32I};
    static const GLenum layouts[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    static const GLenum integerLayouts[] = {GL_RED_INTEGER, GL_RG_INTEGER, GL_RGB_INTEGER, GL_RGBA_INTEGER};
    const uint32_t i = format.channels - 1;
    GlTexelFormat gl{0, 0, 0};
    switch (format.kind) {
    case ComponentKind::Float:
        gl = format.bytesPerChannel == 2 ? GlTexelFormat{floats16[i], layouts[i], GL_HALF_FLOAT} : GlTexelFormat{floats32[i], layouts[i], GL_FLOAT};
        break;
    case ComponentKind::UNorm: gl = {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE}; break;
    case ComponentKind::UInt: gl = {uints[i], integerLayouts[i], GL_UNSIGNED_INT}; break;
    case ComponentKind::SInt: gl = {sints[i], integerLayouts[i], GL_INT}; break;
    }
    if (!gl.internalFormat) throw opengl::GlError("the OpenGL runner has no texture format for " + std::string(format.name));
    return gl;
}

} // namespace iblkit::run
