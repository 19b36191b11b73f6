#include "egl_context.hpp"

#include "gl_error.hpp"

#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>

namespace iblkit::opengl {
namespace {

bool hasExtension(const char* extensions, const char* name) {
    return extensions && std::strstr(extensions, name) != nullptr;
}

} // namespace

EglContext::EglContext() {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
        throw GlError("EGL has no surfaceless platform: install Mesa's EGL (Debian packages libegl1 and libgl1-mesa-dri)");
    const auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) throw GlError("EGL lacks eglGetPlatformDisplayEXT");
    const EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    const bool initializedBefore = display != EGL_NO_DISPLAY && eglQueryString(display, EGL_VENDOR) != nullptr;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr))
        throw GlError("cannot open EGL's surfaceless display (Debian package libgl1-mesa-dri)");
    display_.handle = display;
    display_.initializedHere = !initializedBefore;
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context") || !hasExtension(extensions, "EGL_KHR_no_config_context"))
        throw GlError("the EGL display cannot make a context without a surface");
    if (!eglBindAPI(EGL_OPENGL_API)) throw GlError("EGL offers no desktop OpenGL");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_.display = display;
    context_.handle = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_.handle == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_.handle))
        throw GlError("the driver offers no OpenGL 4.5 core context");
    gl_ = loadGlFunctions();
    // Vulkan always filters cubes across faces; OpenGL only when asked.
    gl_.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

std::string EglContext::renderer() const {
    return reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER)) + std::string(", OpenGL ") +
           reinterpret_cast<const char*>(gl_.GetString(GL_VERSION));
}

void EglContext::check(const char* what) const {
    if (const GLenum error = gl_.GetError(); error != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", error);
        throw GlError(std::string("OpenGL error ") + code + " in " + what);
    }
}

} // namespace iblkit::opengl
