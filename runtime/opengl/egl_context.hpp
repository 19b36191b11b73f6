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
    // Terminated only by the context that initialized it: Mesa's surfaceless display is one
    // for the whole process, and an inner context must not end an outer one's.
    struct Display {
        EGLDisplay handle = EGL_NO_DISPLAY;
        bool initializedHere = false;
        ~Display() {
            if (handle != EGL_NO_DISPLAY && initializedHere) eglTerminate(handle);
        }
    };
    // The context current before this one is current again when it goes: a run's context inside
    // a suite's leaves the suite's usable.
    struct Context {
        EGLDisplay display = EGL_NO_DISPLAY;
        EGLContext handle = EGL_NO_CONTEXT;
        EGLDisplay previousDisplay = eglGetCurrentDisplay();
        EGLContext previous = eglGetCurrentContext();
        EGLSurface previousDraw = eglGetCurrentSurface(EGL_DRAW), previousRead = eglGetCurrentSurface(EGL_READ);
        ~Context() {
            if (handle == EGL_NO_CONTEXT) return;
            if (previous != EGL_NO_CONTEXT) eglMakeCurrent(previousDisplay, previousDraw, previousRead, previous);
            else eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display, handle);
        }
    };

    Display display_;
    Context context_;
    GlFunctions gl_{};
};

} // namespace iblkit::opengl
