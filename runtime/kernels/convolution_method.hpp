#pragma once

#include "kernels/kernel.hpp"
#include "kernels/kernel_steps.hpp"

#include "image.hpp"
#include "shading/lobe_table.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace iblkit::kernels {

// The tree one PrefilterConvolutionCS dispatch walks (see the shader): pyramid levels counted
// from the source's mip 0.
struct ConvolutionPlan {
    uint32_t topLevel = 0, fineLevel = 0;
    float refine = 0;
    uint32_t horizonLevel = 0;
};

// The fine level resolves the lobe (its half-maximum width, about 2.58 α for GGX at N = V) with
// at least kFineTexelsPerLobe texels; the top level is 7 levels above it, or higher where that level
// would have more than 2 x 2 blocks per face (sources above 256²); `refine`
// spends about `budget` block terms per output texel: about 6 top² + π refine² (3 levels + 4),
// and more where bright blocks open from farther away (the shader's Opens);
// blocks across N's horizon open down to kHorizonTexels per face, scaled by the cube root of the
// lobe's weight there. Throws std::invalid_argument for a roughness <= 0 or > 1, a budget of
// 0 or above kMaxConvolutionBudget, or a source whose width is not a power of two (the pyramid
// halves it exactly, and the walk steps through its top level by shifts).
inline constexpr double kFineTexelsPerLobe = 12;
inline constexpr double kHorizonTexels = 16;
// llvmpipe ends every loop of an invocation once all of them together have run 65535 iterations,
// counted for the SIMD vector of texels it runs at once: each term of the walk costs the vector up
// to 3 + 2 × the tree's depth of them (17 at a depth of 7; 25 at 11, a 4096² source's), so a walk of
// more than about 3850 (2600) terms loses the rest of its sum without a word (at 32768, mip 1 of a 64² source was 14 times off). Measured on a
// 256² source, a texel at a face corner sums up to 1.02 terms per unit of budget, and bright
// blocks add about 15 %: budgets above 2048 are refused, and the shader stops opening blocks
// within the device's budget whatever the light.
inline constexpr uint32_t kMaxConvolutionBudget = 2048;
ConvolutionPlan planConvolution(uint32_t sourceSize, float roughness, uint32_t budget);

// Sources up to this wide keep their own texels as the pyramid's level 0: three more RGBA32F
// cubes of the source's size (72 MiB at 512², 288 MiB at 1024²), and a walk that reads every
// block alike, 0.83 of the time of one that makes single texels where it reaches them (mip 1 of
// the default bake).
inline constexpr uint32_t kMaxSourceTexelsInPyramid = 512;

// Whether a source of `sourceSize` keeps its texels in the pyramid: from 2² (a single texel is a
// whole face, made by the walk) to `maxSourceTexelsInPyramid`.
bool pyramidHoldsSourceTexels(uint32_t sourceSize, uint32_t maxSourceTexelsInPyramid = kMaxSourceTexelsInPyramid);
// The pyramids' face size for such a source: its own where it keeps its texels, else pyramidSize's.
uint32_t convolutionPyramidSize(uint32_t sourceSize, uint32_t maxSourceTexelsInPyramid = kMaxSourceTexelsInPyramid);

// The define that compiles PrefilterConvolution for a pyramid holding the source's texels ("1").
inline constexpr const char* kSourceTexelsInPyramidDefine = "SOURCE_TEXELS_IN_PYRAMID";

// PrefilterConvolution for a pyramid that holds the source's texels, or for one half its width.
KernelProgram compileConvolutionWalk(const std::string& method, bool sourceTexelsInPyramid,
                                     const ShaderFiles& files = embeddedShaderFiles());

// The convolution method: the energy pyramid of a source (built once per source image, on its
// first run), then one tree walk per mip. The walk for the pyramid of an `expectedSourceSize`
// source (0: one that holds its texels) is compiled at once; the other when a source first needs it.
class ConvolutionPrefilter {
public:
    // Sources up to `maxSourceTexelsInPyramid` wide keep their texels in the pyramid.
    ConvolutionPrefilter(const vulkan::VulkanContext& context, const std::string& method, uint32_t budget,
                         const ShaderFiles& files = embeddedShaderFiles(), uint32_t expectedSourceSize = 0,
                         uint32_t maxSourceTexelsInPyramid = kMaxSourceTexelsInPyramid);
    // Writes mip `mip` of `target` (RGBA32F, storage) from mip 0 of `source` at `roughness`.
    // `source` must keep its texels while this object runs on it.
    void run(vulkan::Image& source, vulkan::Image& target, uint32_t mip, float roughness);
    void setWeighting(shading::LobeWeighting weighting) { weighting_ = weighting; }
    DispatchTotals takeTotals();
    void releasePyramids(); // built again by the next run

private:
    void buildPyramid(vulkan::Image& source);
    EnergyPyramid pyramid();
    Kernel& walkFor(bool holdsSourceTexels);

    const vulkan::VulkanContext& context_;
    std::string method_;
    ShaderFiles files_;
    uint32_t budget_, maxSourceTexelsInPyramid_;
    shading::LobeWeighting weighting_ = shading::LobeWeighting::NdotL;
    Kernel cluster_;
    std::optional<Kernel> walkInPyramid_, walkMakingTexels_;
    const vulkan::Image* pyramidSource_ = nullptr;
    bool holdsSourceTexels_ = false;
    std::optional<vulkan::Image> energy_, centroid_, geometry_, texelSolidAngle_;
};

} // namespace iblkit::kernels
