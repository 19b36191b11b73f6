#include "gl_cube_bake.hpp"

#include "shading/lobe_table.hpp"

#include "gl_support.hpp"

namespace iblkit::consistency {
namespace {

// EnvMap: `cube` with its whole chain, read through a trilinear sampler. A shader that also
// asks EnvMap its size reads it through a second unit, the texture alone ("EnvMap").
struct BoundMippedEnvironment {
    opengl::GlObject texture, sampler;
};
BoundMippedEnvironment bindMippedEnvironment(const opengl::EglContext& context, const OpenGlForm& form,
                                             const MippedCube& cube) {
    BoundMippedEnvironment bound{glpath::cubeTexture(context, GL_TEXTURE_CUBE_MAP, cube.size, cube.mips, cube.texels),
                                 glpath::linearClampSampler(context)};
    glpath::bindTexture(context, form, "EnvMap+EnvMapSampler", bound.texture);
    context.gl().BindSampler(glpath::slotOf(form, "EnvMap+EnvMapSampler"), bound.sampler.name());
    for (const auto& binding : form.glsl.bindings)
        if (binding.resource == "EnvMap") glpath::bindTexture(context, form, "EnvMap", bound.texture);
    return bound;
}

} // namespace

std::vector<float> glSkyCube(const opengl::EglContext& context, const OpenGlForm& form, uint32_t size, uint32_t supersample) {
    const auto program = glpath::program(context, form);
    const auto cube = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, size, 1);
    glpath::bindLayeredImage(context, form, "Cube", cube, 0);
    const auto parameters = glpath::bindParameters(context, form, kernels::SupersampleParameters{supersample}.members());
    glpath::dispatch(context, program, form, {size, size, 6});
    return glpath::readTexture(context, cube, 0, GL_RGBA, glpath::cubeValueCount(size));
}

std::vector<float> glEquirectToCube(const opengl::EglContext& context, const OpenGlForm& form, const Panorama& panorama,
                                    uint32_t size, uint32_t supersample) {
    const auto program = glpath::program(context, form);
    const auto equirect = glpath::texture2D(context, GL_RGBA32F, GL_RGBA, panorama.width, panorama.height, panorama.texels);
    glpath::bindTexture(context, form, "Equirect", equirect);
    const auto cube = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, size, 1);
    glpath::bindLayeredImage(context, form, "Cube", cube, 0);
    const auto parameters = glpath::bindParameters(context, form, kernels::SupersampleParameters{supersample}.members());
    glpath::dispatch(context, program, form, {size, size, 6});
    return glpath::readTexture(context, cube, 0, GL_RGBA, glpath::cubeValueCount(size));
}

// Each mip reads the one above from the texture unit and writes its own level as an image.
std::vector<float> glDownsampleChain(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube) {
    const auto program = glpath::program(context, form);
    const auto texture = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, cube.size, cube.mips);
    const auto mip0 = cube.mip(0);
    context.gl().TextureSubImage3D(texture.name(), 0, 0, 0, 0, GLsizei(cube.size), GLsizei(cube.size), 6, GL_RGBA, GL_FLOAT,
                                   mip0.data());
    glpath::bindTexture(context, form, "Source", texture);
    std::vector<float> chain;
    for (uint32_t mip = 1; mip < cube.mips; ++mip) {
        glpath::bindLayeredImage(context, form, "Destination", texture, mip);
        const auto parameters = glpath::bindParameters(context, form, kernels::SourceMipParameters{mip - 1}.members());
        glpath::dispatch(context, program, form, {cube.mipSize(mip), cube.mipSize(mip), 6});
        const auto level = glpath::readTexture(context, texture, mip, GL_RGBA, glpath::cubeValueCount(cube.mipSize(mip)));
        chain.insert(chain.end(), level.begin(), level.end());
    }
    return chain;
}

// The partial sums of every 8x8 group added in double by kernels::sumShPartials, as on Vulkan.
kernels::ShProjection glShProject(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube,
                                  uint32_t mip) {
    const auto program = glpath::program(context, form);
    const auto source = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, cube.size, cube.mips, cube.texels);
    glpath::bindTexture(context, form, "Source", source);
    const uint32_t groupsPerSide = (cube.mipSize(mip) + 7) / 8, groups = groupsPerSide * groupsPerSide * 6;
    const auto partials = glpath::bindStorageBuffer(context, form, "Partials", size_t(groups) * 9 * 16);
    const auto parameters = glpath::bindParameters(context, form, kernels::SourceMipParameters{mip}.members());
    glpath::dispatch(context, program, form, {groupsPerSide * 8, groupsPerSide * 8, 6});
    return kernels::sumShPartials(glpath::readBuffer(context, partials, size_t(groups) * 9 * 4), groups);
}

std::vector<float> glIrradianceCube(const opengl::EglContext& context, const OpenGlForm& form,
                                    const std::vector<float>& moments, uint32_t momentSize, uint32_t outSize) {
    const auto program = glpath::program(context, form);
    const auto bytes = std::as_bytes(std::span(moments));
    const auto buffer = glpath::bindStorageBuffer(context, form, "Moments", bytes.size(), bytes);
    const auto irradiance = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, outSize, 1);
    glpath::bindLayeredImage(context, form, "Irradiance", irradiance, 0);
    const auto parameters = glpath::bindParameters(context, form, kernels::IrradianceParameters{momentSize}.members());
    glpath::dispatch(context, program, form, {outSize, outSize, 6});
    return glpath::readTexture(context, irradiance, 0, GL_RGBA, glpath::cubeValueCount(outSize));
}

std::vector<float> glMippedPrefilter(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube,
                                     const kernels::NamedValues& values, uint32_t size) {
    const auto program = glpath::program(context, form);
    const auto envMap = bindMippedEnvironment(context, form, cube);
    const auto prefiltered = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, size, 1);
    glpath::bindLayeredImage(context, form, "Prefiltered", prefiltered, 0);
    const auto parameters = glpath::bindParameters(context, form, values);
    glpath::dispatch(context, program, form, {size, size, 6});
    return glpath::readTexture(context, prefiltered, 0, GL_RGBA, glpath::cubeValueCount(size));
}

std::vector<float> glTablePrefilter(const opengl::EglContext& context, const OpenGlForm& form, const MippedCube& cube,
                                    std::span<const glm::vec4> table, uint32_t size) {
    const auto program = glpath::program(context, form);
    const auto envMap = bindMippedEnvironment(context, form, cube);
    const auto bytes = std::as_bytes(table);
    const auto samples = glpath::bindStorageBuffer(context, form, "SampleTable", bytes.size(), bytes);
    const auto prefiltered = glpath::cubeTexture(context, GL_TEXTURE_2D_ARRAY, size, 1);
    glpath::bindLayeredImage(context, form, "Prefiltered", prefiltered, 0);
    const auto parameters =
        glpath::bindParameters(context, form, kernels::PrefilterTableParameters{uint32_t(table.size())}.members());
    glpath::dispatch(context, program, form, {size, size, 6});
    return glpath::readTexture(context, prefiltered, 0, GL_RGBA, glpath::cubeValueCount(size));
}

GlShadingMaps bindShadingMaps(const opengl::EglContext& context, const OpenGlForm& form, const PreviewInputs& inputs) {
    const auto cubeMap = [&](const MippedCube& cube) {
        return glpath::cubeTexture(context, GL_TEXTURE_CUBE_MAP, cube.size, cube.mips, cube.texels);
    };
    const uint32_t tableSize = shading::kLobeTableSize;
    const auto lightBytes = std::as_bytes(std::span(inputs.lights));
    GlShadingMaps maps{cubeMap(inputs.specular), cubeMap(inputs.irradiance),
                       glpath::texture2D(context, GL_RG32F, GL_RG, inputs.lutSize, inputs.lutSize, inputs.lut),
                       glpath::texture2D(context, GL_RGBA32F, GL_RGBA, tableSize, tableSize, inputs.lobeTable),
                       glpath::linearClampSampler(context),
                       glpath::bindStorageBuffer(context, form, "Lights", lightBytes.size(), lightBytes)};
    for (const auto& [resource, texture] : {std::pair{"Specular+LinearClamp", &maps.specular},
                                            std::pair{"IrradianceMap+LinearClamp", &maps.irradiance},
                                            std::pair{"BrdfLut+LinearClamp", &maps.lut},
                                            std::pair{"LobeTable+LinearClamp", &maps.lobeTable}}) {
        glpath::bindTexture(context, form, resource, *texture);
        context.gl().BindSampler(glpath::slotOf(form, resource), maps.sampler.name());
    }
    return maps;
}

std::vector<float> glPreview(const opengl::EglContext& context, const OpenGlForm& form, const PreviewInputs& inputs) {
    const auto program = glpath::program(context, form);
    const auto maps = bindShadingMaps(context, form, inputs);
    const auto image = glpath::texture2D(context, GL_RGBA32F, GL_RGBA, inputs.width, inputs.height);
    context.gl().BindImageTexture(glpath::slotOf(form, "Preview"), image.name(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const auto parameters = glpath::bindParameters(context, form, inputs.parameters.members());
    glpath::dispatch(context, program, form, {inputs.width, inputs.height, 1});
    return glpath::readTexture(context, image, 0, GL_RGBA, size_t(inputs.width) * inputs.height * 4);
}

} // namespace iblkit::consistency
