#include "gl_object.hpp"

#include "gl_error.hpp"

#include <string>
#include <vector>

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

GlObject createVertexArray(const EglContext& context) {
    GLuint name = 0;
    context.gl().CreateVertexArrays(1, &name);
    return GlObject(context, name, [](const GlFunctions& gl, GLuint n) { gl.DeleteVertexArrays(1, &n); });
}

GlObject createFramebuffer(const EglContext& context) {
    GLuint name = 0;
    context.gl().CreateFramebuffers(1, &name);
    return GlObject(context, name, [](const GlFunctions& gl, GLuint n) { gl.DeleteFramebuffers(1, &n); });
}

namespace {

// A driver's log on one line: its lines joined with "; ".
std::string oneLine(const char* log) {
    std::string line;
    for (const char* c = log; *c; ++c) {
        if (*c != '\n') line += *c;
        else if (c[1] != '\0') line += "; ";
    }
    return line;
}

GlObject compiledShader(const EglContext& context, GLenum stage, const std::string& source, const std::string& name) {
    const auto& gl = context.gl();
    GlObject shader(context, gl.CreateShader(stage), [](const GlFunctions& g, GLuint n) { g.DeleteShader(n); });
    const char* text = source.c_str();
    gl.ShaderSource(shader.name(), 1, &text, nullptr);
    gl.CompileShader(shader.name());
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader.name(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::string log(4096, '\0');
        gl.GetShaderInfoLog(shader.name(), GLsizei(log.size()), nullptr, log.data());
        throw GlError(name + ": error: OpenGL rejected the shader: " + oneLine(log.c_str()));
    }
    return shader;
}

GlObject linkedProgram(const EglContext& context, const std::vector<const GlObject*>& shaders, const std::string& name) {
    const auto& gl = context.gl();
    GlObject program(context, gl.CreateProgram(), [](const GlFunctions& g, GLuint n) { g.DeleteProgram(n); });
    for (const auto* shader : shaders) gl.AttachShader(program.name(), shader->name());
    gl.LinkProgram(program.name());
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program.name(), GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log(4096, '\0');
        gl.GetProgramInfoLog(program.name(), GLsizei(log.size()), nullptr, log.data());
        throw GlError(name + ": error: OpenGL did not link the shader: " + oneLine(log.c_str()));
    }
    return program;
}

} // namespace

GlObject createGraphicsProgram(const EglContext& context, const std::string& vertexSource, const std::string& fragmentSource,
                               const std::string& name) {
    const auto vertex = compiledShader(context, GL_VERTEX_SHADER, vertexSource, name + " (vertex)");
    const auto fragment = compiledShader(context, GL_FRAGMENT_SHADER, fragmentSource, name + " (pixel)");
    return linkedProgram(context, {&vertex, &fragment}, name);
}

GlObject createComputeProgram(const EglContext& context, const std::string& source, const std::string& name) {
    const auto shader = compiledShader(context, GL_COMPUTE_SHADER, source, name);
    return linkedProgram(context, {&shader}, name);
}

} // namespace iblkit::opengl
