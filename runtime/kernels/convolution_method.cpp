#include "kernels/convolution_method.hpp"

#include "kernels/kernel_steps.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

#include <fmt/core.h>

namespace iblkit::kernels {
namespace {

constexpr uint32_t kMaxTreeDepth = 7; // levels from the top level down to the fine level

uint32_t levelOf(uint32_t sourceSize, uint32_t size) { return uint32_t(std::bit_width(sourceSize / size)) - 1; }

void requireBudget(uint32_t budget) {
    if (budget == 0 || budget > kMaxConvolutionBudget)
        throw std::invalid_argument(fmt::format("the convolution method takes a budget of 1 to {} terms per texel, not {}",
                                                kMaxConvolutionBudget, budget));
}

} // namespace

ConvolutionPlan planConvolution(uint32_t sourceSize, float roughness, uint32_t budget) {
    if (!(roughness > 0 && roughness <= 1))
        throw std::invalid_argument("the convolution method takes a roughness in (0, 1], not " + std::to_string(roughness));
    requireBudget(budget);
    if (!std::has_single_bit(sourceSize))
        throw std::invalid_argument(fmt::format("the convolution method takes a source a power of two wide, not {}", sourceSize));
    const double alpha = double(roughness) * roughness;
    const double lobeWidth = std::min(2.58 * alpha, std::numbers::pi / 2);
    // A face of w texels is 2 / w radians wide at its centre.
    const double wanted = 2 * kFineTexelsPerLobe / lobeWidth;
    const uint32_t fineSize = std::bit_ceil(uint32_t(std::ceil(std::min(wanted, double(sourceSize)))));
    const uint32_t fineLevel = levelOf(sourceSize, fineSize);
    const uint32_t lastLevel = levelOf(sourceSize, 1);
    // The top level has at most 2 x 2 blocks per face: above 256², every texel would otherwise sum
    // 6 top² terms whatever its budget (384 at 1024², three times the default budget).
    const uint32_t topLevel = std::min(lastLevel, std::max(fineLevel + kMaxTreeDepth, lastLevel - 1));
    const double topBlocks = 6.0 * std::pow(double(sourceSize >> topLevel), 2);
    const double depth = topLevel - fineLevel;
    const double refine = std::sqrt(std::max(double(budget) - topBlocks, 0.0) / (std::numbers::pi * (3 * depth + 4)));
    // The lobe's weight at N's horizon against its peak, D(sqrt(1/2)) / D(1).
    const double horizonWeight = 4 * std::pow(alpha, 4) / std::pow(1 + alpha * alpha, 2);
    const double horizonTexels = kHorizonTexels * std::cbrt(horizonWeight);
    const uint32_t horizonSize = std::min(fineSize, std::bit_ceil(uint32_t(std::ceil(horizonTexels))));
    const uint32_t horizonLevel = std::clamp(levelOf(sourceSize, horizonSize), fineLevel, topLevel);
    return {topLevel, fineLevel, float(std::clamp(refine, 1.0, 1e4)), horizonLevel};
}

bool pyramidHoldsSourceTexels(uint32_t sourceSize, uint32_t maxSourceTexelsInPyramid) {
    return sourceSize >= 2 && sourceSize <= maxSourceTexelsInPyramid;
}

uint32_t convolutionPyramidSize(uint32_t sourceSize, uint32_t maxSourceTexelsInPyramid) {
    return pyramidHoldsSourceTexels(sourceSize, maxSourceTexelsInPyramid) ? sourceSize : pyramidSize(sourceSize);
}

KernelProgram compileConvolutionWalk(const std::string& method, bool sourceTexelsInPyramid, const ShaderFiles& files) {
    const std::map<std::string, std::string> defines{{kSourceTexelsInPyramidDefine, sourceTexelsInPyramid ? "1" : "0"}};
    return compileKernel(kernelFor(KernelRole::PrefilterConvolution, method), defines, {}, files);
}

ConvolutionPrefilter::ConvolutionPrefilter(const vulkan::VulkanContext& context, const std::string& method,
                                           uint32_t budget, const ShaderFiles& files, uint32_t expectedSourceSize,
                                           uint32_t maxSourceTexelsInPyramid)
    : context_(context), method_(method), files_(files), budget_(budget), maxSourceTexelsInPyramid_(maxSourceTexelsInPyramid),
      cluster_(context, compileKernel(kernelFor(KernelRole::ClusterCube), {}, {}, files)) {
    requireBudget(budget);
    walkFor(expectedSourceSize == 0 || pyramidHoldsSourceTexels(expectedSourceSize, maxSourceTexelsInPyramid));
}

Kernel& ConvolutionPrefilter::walkFor(bool holdsSourceTexels) {
    auto& walk = holdsSourceTexels ? walkInPyramid_ : walkMakingTexels_;
    if (!walk) walk.emplace(context_, compileConvolutionWalk(method_, holdsSourceTexels, files_));
    return *walk;
}

void ConvolutionPrefilter::buildPyramid(vulkan::Image& source) {
    holdsSourceTexels_ = pyramidHoldsSourceTexels(source.desc().width, maxSourceTexelsInPyramid_);
    const uint32_t size = convolutionPyramidSize(source.desc().width, maxSourceTexelsInPyramid_);
    const auto& rgba32 = vulkan::texelFormatNamed("R32G32B32A32_SFLOAT");
    const uint32_t mips = vulkan::fullMipCount(size, size);
    energy_.emplace(context_, vulkan::ImageDesc{"Energy", &rgba32, size, size, 6, mips, true, true});
    centroid_.emplace(context_, vulkan::ImageDesc{"Centroid", &rgba32, size, size, 6, mips, true, true});
    geometry_.emplace(context_, vulkan::ImageDesc{"Geometry", &rgba32, size, size, 6, mips, true, true});
    // Only a walk that makes single texels reads their solid angles; ClusterCube binds a texel of it regardless.
    const uint32_t tableSize = holdsSourceTexels_ ? 1 : source.desc().width;
    texelSolidAngle_.emplace(context_, vulkan::ImageDesc{"TexelSolidAngle", &vulkan::texelFormatNamed("R32_SFLOAT"), tableSize,
                                                         tableSize, 1, 1, false, true});
    runClusterPyramid(cluster_, source, pyramid());
    pyramidSource_ = &source;
}

void ConvolutionPrefilter::run(vulkan::Image& source, vulkan::Image& target, uint32_t mip, float roughness) {
    const auto plan = planConvolution(source.desc().width, roughness, budget_);
    if (pyramidSource_ != &source) buildPyramid(source);
    runPrefilterConvolution(walkFor(holdsSourceTexels_), source, pyramid(), target, mip,
                            {roughness, plan.topLevel, plan.fineLevel, plan.refine, plan.horizonLevel, uint32_t(weighting_)});
}

EnergyPyramid ConvolutionPrefilter::pyramid() {
    return {*energy_, *centroid_, *geometry_, *texelSolidAngle_, holdsSourceTexels_};
}

void ConvolutionPrefilter::releasePyramids() {
    energy_.reset();
    centroid_.reset();
    geometry_.reset();
    texelSolidAngle_.reset();
    pyramidSource_ = nullptr;
}

DispatchTotals ConvolutionPrefilter::takeTotals() {
    auto totals = cluster_.takeTotals();
    for (auto* walk : {&walkInPyramid_, &walkMakingTexels_})
        if (*walk) totals += (*walk)->takeTotals();
    return totals;
}

} // namespace iblkit::kernels
