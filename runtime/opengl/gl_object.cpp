#include "gl_object.hpp"

#include "gl_error.hpp"

#include <string>

namespace iblkit::opengl {

GlObject createTexture(const EglContext& context, GLenum target) {
    GLuint name = 0;
    context.gl().CreateTextures(target, 1, &name);
    return GlObject(context, name, [](const GlFunctions& gl, GLuint n) { gl.DeleteTextures(1, &n); });
}

GlObject createBuffer(const EglContext& context) {
    GLuint name = 0;
    context.gl().CreateBuffers(1, &name);
    return GlObject(context, name, [](const GlFunctions& gl, GLuint n) { gl.DeleteBuffers(1, &n); });
}

GlObject createSampler(const EglContext& context) {
    GLuint name = 0;
    context.gl().CreateSamplers(1, &name);
    return GlObject(context, name, [](const GlFunctions& gl, GLuint n) { gl.DeleteSamplers(1, &n); });
}

GlObject createComputeProgram(const EglContext& context, const std::string& source, const std::string& name) {
    const auto& gl = context.gl();
    const GlObject shader(context, gl.CreateShader(GL_COMPUTE_SHADER), [](const GlFunctions& g, GLuint n) { g.DeleteShader(n); });
    const char* text = source.c_str();
    gl.ShaderSource(shader.name(), 1, &text, nullptr);
    gl.CompileShader(shader.name());
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader.name(), GL_COMPILE_STATUS, &ok);
    std::string log(4096, '\0');
    if (!ok) {
        gl.GetShaderInfoLog(shader.name(), GLsizei(log.size()), nullptr, log.data());
        throw GlError(name + ": error: OpenGL rejected the shader: " + log.c_str());
    }
    GlObject program(context, gl.CreateProgram(), [](const GlFunctions& g, GLuint n) { g.DeleteProgram(n); });
    gl.AttachShader(program.name(), shader.name());
    gl.LinkProgram(program.name());
    gl.GetProgramiv(program.name(), GL_LINK_STATUS, &ok);
    if (!ok) {
        gl.GetProgramInfoLog(program.name(), GLsizei(log.size()), nullptr, log.data());
        throw GlError(name + ": error: OpenGL did not link the shader: " + log.c_str());
    }
    return program;
}

} // namespace iblkit::opengl
