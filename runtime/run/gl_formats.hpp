#pragma once

#include "texel_format.hpp"

#include <GL/glcorearb.h>

namespace iblkit::run {

// How OpenGL names a texel format: the texture's internal format, and the format and type of
// its texels in memory for uploads and readbacks.
struct GlTexelFormat {
    GLenum internalFormat, format, type;
};

// Throws opengl::GlError for a format the OpenGL runner has no mapping for.
GlTexelFormat glTexelFormatOf(const vulkan::TexelFormat& format);

} // namespace iblkit::run
