#pragma once

#include "gl_functions.hpp"

#include <EGL/egl.h>

#include <string>

namespace iblkit::opengl {

// A headless OpenGL 4.5 core context: EGL's surfaceless platform (Mesa), no window, no config,
// current on the calling thread for as long as it lives.
class EglContext {
public:
    EglContext();
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    const GlFunctions& gl() const { return gl_; }
    std::string renderer() const;
    // Throws GlError naming `what` when OpenGL has recorded an error.
    void check(const char* what) const;

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    GlFunctions gl_{};
};

} // namespace iblkit::opengl
