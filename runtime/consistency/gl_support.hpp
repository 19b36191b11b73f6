#pragma once

#include "gl_bake.hpp"
#include "gl_object.hpp"
#include "kernels/kernel_parameters.hpp"

#include <array>
#include <span>
#include <string>
#include <vector>

// What every OpenGL run of path d does: bind by the form's binding table, set its cbuffer,
// dispatch, read back. Textures are RGBA32F unless a format is named.
namespace iblkit::consistency::glpath {

// The floats of one level of an RGBA cube of `size`² faces.
inline size_t cubeValueCount(uint32_t size) { return size_t(size) * size * 6 * 4; }

// The slot the GLSL form gives an HLSL resource ("EnvMap+EnvMapSampler" for a combined one).
GLuint slotOf(const OpenGlForm& form, const std::string& resource);

opengl::GlObject program(const opengl::EglContext& context, const OpenGlForm& form);

// The form's one cbuffer from named values, in a uniform buffer bound at its slot; the buffer
// must outlive the dispatch.
opengl::GlObject bindParameters(const opengl::EglContext& context, const OpenGlForm& form, const kernels::NamedValues& values);

// Dispatches enough workgroups to cover `threads` and waits for them.
void dispatch(const opengl::EglContext& context, const opengl::GlObject& program, const OpenGlForm& form,
              std::array<uint32_t, 3> threads);

// Binds `texture` to the texture unit of `resource`.
void bindTexture(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
                 const opengl::GlObject& texture);
// Binds all six layers of `level` of an RGBA32F 2D array to the image unit of `resource`, for writing.
void bindLayeredImage(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
                      const opengl::GlObject& texture, uint32_t level);

// Binds level 0 of a 2D texture of `internalFormat` to the image unit of `resource`, for writing.
void bindImage(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
               const opengl::GlObject& texture, GLenum internalFormat);

// A GL_TEXTURE_CUBE_MAP or GL_TEXTURE_2D_ARRAY of 6 layers with `mips` levels, filled with
// `texels` (every level: face, row, column, RGBA) or left empty when there are none.
opengl::GlObject cubeTexture(const opengl::EglContext& context, GLenum target, uint32_t size, uint32_t mips,
                             std::span<const float> texels = {});
// A GL_TEXTURE_2D, filled with `texels` in `format` unless there are none.
opengl::GlObject texture2D(const opengl::EglContext& context, GLenum internalFormat, GLenum format, uint32_t width,
                           uint32_t height, std::span<const float> texels = {});
// Linear in and between mips, clamped to the edge: vulkan::Sampler's defaults.
opengl::GlObject linearClampSampler(const opengl::EglContext& context);
// A storage buffer of `bytes`, holding `contents` (exactly `bytes` of them; throws
// std::invalid_argument otherwise) or left undefined when there are none, bound at the slot of
// `resource`.
opengl::GlObject bindStorageBuffer(const opengl::EglContext& context, const OpenGlForm& form, const std::string& resource,
                                   size_t bytes, std::span<const std::byte> contents = {});

std::vector<float> readTexture(const opengl::EglContext& context, const opengl::GlObject& texture, uint32_t level,
                               GLenum format, size_t count);
std::vector<float> readBuffer(const opengl::EglContext& context, const opengl::GlObject& buffer, size_t count);

} // namespace iblkit::consistency::glpath
