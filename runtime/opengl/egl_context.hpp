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
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    const GlFunctions& gl() const { return gl_; }
    std::string renderer() const;
    // Throws GlError naming `what` when OpenGL has recorded an error.
    void check(const char* what) const;

private:
    // Each releases what it holds, so a constructor that throws halfway leaks nothing.
    struct Display {
        EGLDisplay handle = EGL_NO_DISPLAY;
        ~Display() {
            if (handle != EGL_NO_DISPLAY) eglTerminate(handle);
        }
    };
    struct Context {
        EGLDisplay display = EGL_NO_DISPLAY;
        EGLContext handle = EGL_NO_CONTEXT;
        ~Context() {
            if (handle == EGL_NO_CONTEXT) return;
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display, handle);
        }
    };

    Display display_;
    Context context_;
    GlFunctions gl_{};
};

} // namespace iblkit::opengl
