#pragma once

#include <GL/glcorearb.h>

namespace iblkit::opengl {

// The OpenGL 4.5 entry points the compute runner uses, loaded through eglGetProcAddress so
// that only libEGL is linked.
struct GlFunctions {
    PFNGLGETERRORPROC GetError;
    PFNGLGETSTRINGPROC GetString;
    PFNGLENABLEPROC Enable;
    PFNGLCREATESHADERPROC CreateShader;
    PFNGLSHADERSOURCEPROC ShaderSource;
    PFNGLCOMPILESHADERPROC CompileShader;
    PFNGLGETSHADERIVPROC GetShaderiv;
    PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog;
    PFNGLDELETESHADERPROC DeleteShader;
    PFNGLCREATEPROGRAMPROC CreateProgram;
    PFNGLATTACHSHADERPROC AttachShader;
    PFNGLLINKPROGRAMPROC LinkProgram;
    PFNGLGETPROGRAMIVPROC GetProgramiv;
    PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog;
    PFNGLDELETEPROGRAMPROC DeleteProgram;
    PFNGLUSEPROGRAMPROC UseProgram;
    PFNGLCREATETEXTURESPROC CreateTextures;
    PFNGLTEXTURESTORAGE2DPROC TextureStorage2D;
    PFNGLTEXTURESTORAGE3DPROC TextureStorage3D;
    PFNGLTEXTURESUBIMAGE2DPROC TextureSubImage2D;
    PFNGLTEXTURESUBIMAGE3DPROC TextureSubImage3D;
    PFNGLGETTEXTUREIMAGEPROC GetTextureImage;
    PFNGLDELETETEXTURESPROC DeleteTextures;
    PFNGLBINDTEXTUREUNITPROC BindTextureUnit;
    PFNGLBINDIMAGETEXTUREPROC BindImageTexture;
    PFNGLCREATESAMPLERSPROC CreateSamplers;
    PFNGLSAMPLERPARAMETERIPROC SamplerParameteri;
    PFNGLBINDSAMPLERPROC BindSampler;
    PFNGLDELETESAMPLERSPROC DeleteSamplers;
    PFNGLCREATEBUFFERSPROC CreateBuffers;
    PFNGLNAMEDBUFFERDATAPROC NamedBufferData;
    PFNGLGETNAMEDBUFFERSUBDATAPROC GetNamedBufferSubData;
    PFNGLBINDBUFFERBASEPROC BindBufferBase;
    PFNGLDELETEBUFFERSPROC DeleteBuffers;
    PFNGLDISPATCHCOMPUTEPROC DispatchCompute;
    PFNGLMEMORYBARRIERPROC MemoryBarrier;
    PFNGLFINISHPROC Finish;
};

// Throws GlError naming the first entry point that cannot be found.
GlFunctions loadGlFunctions();

} // namespace iblkit::opengl
