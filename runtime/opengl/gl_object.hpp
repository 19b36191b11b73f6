#pragma once

#include "egl_context.hpp"

#include <utility>

namespace iblkit::opengl {

// One OpenGL object name, deleted when it goes: the RAII of the OpenGL runner.
class GlObject {
public:
    using Deleter = void (*)(const GlFunctions&, GLuint);

    GlObject(const EglContext& context, GLuint name, Deleter deleter) : gl_(&context.gl()), name_(name), deleter_(deleter) {}
    ~GlObject() {
        if (name_) deleter_(*gl_, name_);
    }
    GlObject(GlObject&& other) noexcept
        : gl_(other.gl_), name_(std::exchange(other.name_, 0)), deleter_(other.deleter_) {}
    GlObject& operator=(GlObject&&) = delete;
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;

    GLuint name() const { return name_; }

private:
    const GlFunctions* gl_;
    GLuint name_;
    Deleter deleter_;
};

GlObject createTexture(const EglContext& context, GLenum target);
GlObject createBuffer(const EglContext& context);
GlObject createSampler(const EglContext& context);

GlObject createVertexArray(const EglContext& context);
GlObject createFramebuffer(const EglContext& context);

// A program of a vertex and a fragment shader from GLSL source; throws GlError with the
// compiler's or linker's log.
GlObject createGraphicsProgram(const EglContext& context, const std::string& vertexSource, const std::string& fragmentSource,
                               const std::string& name);

// A compute program from GLSL source; throws GlError with the compiler's or linker's log.
GlObject createComputeProgram(const EglContext& context, const std::string& source, const std::string& name);

} // namespace iblkit::opengl
