#include "gl_functions.hpp"

#include "gl_error.hpp"

#include <EGL/egl.h>

#include <string>

namespace iblkit::opengl {
namespace {

template <typename Function>
void load(Function& function, const char* name) {
    function = reinterpret_cast<Function>(eglGetProcAddress(name));
    if (!function) throw GlError(std::string("the OpenGL driver lacks ") + name);
}

} // namespace

GlFunctions loadGlFunctions() {
    GlFunctions gl{};
#define IBLKIT_LOAD(name) load(gl.name, "gl" #name)
    IBLKIT_LOAD(GetError); IBLKIT_LOAD(GetString); IBLKIT_LOAD(Enable);
    IBLKIT_LOAD(CreateShader); IBLKIT_LOAD(ShaderSource); IBLKIT_LOAD(CompileShader); IBLKIT_LOAD(GetShaderiv);
    IBLKIT_LOAD(GetShaderInfoLog); IBLKIT_LOAD(DeleteShader); IBLKIT_LOAD(CreateProgram); IBLKIT_LOAD(AttachShader);
    IBLKIT_LOAD(LinkProgram); IBLKIT_LOAD(GetProgramiv); IBLKIT_LOAD(GetProgramInfoLog); IBLKIT_LOAD(DeleteProgram);
    IBLKIT_LOAD(UseProgram); IBLKIT_LOAD(CreateTextures); IBLKIT_LOAD(TextureStorage2D); IBLKIT_LOAD(TextureStorage3D);
    IBLKIT_LOAD(TextureSubImage2D); IBLKIT_LOAD(TextureSubImage3D); IBLKIT_LOAD(GetTextureImage); IBLKIT_LOAD(DeleteTextures);
    IBLKIT_LOAD(BindTextureUnit); IBLKIT_LOAD(BindImageTexture); IBLKIT_LOAD(CreateSamplers);
    IBLKIT_LOAD(SamplerParameteri); IBLKIT_LOAD(BindSampler); IBLKIT_LOAD(DeleteSamplers); IBLKIT_LOAD(CreateBuffers);
    IBLKIT_LOAD(NamedBufferData); IBLKIT_LOAD(GetNamedBufferSubData); IBLKIT_LOAD(BindBufferBase); IBLKIT_LOAD(DeleteBuffers);
    IBLKIT_LOAD(DispatchCompute); IBLKIT_LOAD(MemoryBarrier); IBLKIT_LOAD(Finish);
#undef IBLKIT_LOAD
    return gl;
}

} // namespace iblkit::opengl
