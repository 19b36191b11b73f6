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
    IBLKIT_LOAD(Disable); IBLKIT_LOAD(Enablei); IBLKIT_LOAD(Disablei); IBLKIT_LOAD(PixelStorei);
    IBLKIT_LOAD(ClipControl); IBLKIT_LOAD(ViewportIndexedf); IBLKIT_LOAD(DepthRangef); IBLKIT_LOAD(DepthFunc);
    IBLKIT_LOAD(DepthMask); IBLKIT_LOAD(CullFace); IBLKIT_LOAD(FrontFace); IBLKIT_LOAD(BlendFunci);
    IBLKIT_LOAD(BlendEquationi); IBLKIT_LOAD(CreateVertexArrays); IBLKIT_LOAD(DeleteVertexArrays); IBLKIT_LOAD(BindVertexArray);
    IBLKIT_LOAD(VertexArrayVertexBuffer); IBLKIT_LOAD(VertexArrayAttribFormat); IBLKIT_LOAD(VertexArrayAttribIFormat); IBLKIT_LOAD(VertexArrayAttribBinding);
    IBLKIT_LOAD(EnableVertexArrayAttrib); IBLKIT_LOAD(VertexArrayElementBuffer); IBLKIT_LOAD(CreateFramebuffers); IBLKIT_LOAD(DeleteFramebuffers);
    IBLKIT_LOAD(BindFramebuffer); IBLKIT_LOAD(NamedFramebufferTexture); IBLKIT_LOAD(NamedFramebufferTextureLayer); IBLKIT_LOAD(NamedFramebufferDrawBuffers);
    IBLKIT_LOAD(CheckNamedFramebufferStatus); IBLKIT_LOAD(ClearNamedFramebufferfv); IBLKIT_LOAD(ClearNamedFramebufferuiv); IBLKIT_LOAD(ClearNamedFramebufferiv);
    IBLKIT_LOAD(DrawArraysInstancedBaseInstance); IBLKIT_LOAD(DrawElementsInstancedBaseVertexBaseInstance); IBLKIT_LOAD(ProgramUniform1fv); IBLKIT_LOAD(ProgramUniform2fv);
    IBLKIT_LOAD(ProgramUniform3fv); IBLKIT_LOAD(ProgramUniform4fv); IBLKIT_LOAD(ProgramUniform1iv); IBLKIT_LOAD(ProgramUniform2iv);
    IBLKIT_LOAD(ProgramUniform3iv); IBLKIT_LOAD(ProgramUniform4iv); IBLKIT_LOAD(ProgramUniform1uiv); IBLKIT_LOAD(ProgramUniform2uiv);
    IBLKIT_LOAD(ProgramUniform3uiv); IBLKIT_LOAD(ProgramUniform4uiv); IBLKIT_LOAD(GetUniformLocation); IBLKIT_LOAD(SamplerParameterf); IBLKIT_LOAD(TextureParameteri); IBLKIT_LOAD(ProvokingVertex);
#undef IBLKIT_LOAD
    return gl;
}

} // namespace iblkit::opengl
