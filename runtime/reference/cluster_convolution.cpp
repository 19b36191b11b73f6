#include "cluster_convolution.hpp"

#include "cube_geometry.hpp"
#include "parallel_rows.hpp"

#include <algorithm>

namespace iblkit::reference {
namespace {

template <typename T> using vec4 = glm::vec<4, T>;

constexpr float kHorizonOpen = 2;
// The shader's LOOP_BUDGET: llvmpipe's iterations of all of an invocation's loops together.
constexpr uint32_t kLoopBudget = 65535;

template <typename T>
vec3<T> blockCentre(uint32_t face, uint32_t x, uint32_t y, uint32_t size) {
    return CubeFaceDirection<T>(face, (vec2<T>(T(x), T(y)) + T(0.5)) / T(size));
}

// The shader's NormalCdf, given the exponential exp(-z²/2) it shares with ClippedMean.
template <typename T>
T NormalCdf(T z, T gaussian) {
    const T t = T(1) / (T(1) + T(0.3275911) * T(0.70710678) * std::abs(z));
    const T polynomial =
        T(0.254829592) + t * (T(-0.284496736) + t * (T(1.421413741) + t * (T(-1.453152027) + t * T(1.061405429))));
    const T tail = T(0.5) * t * polynomial * gaussian;
    return z >= T(0) ? T(1) - tail : tail;
}

template <typename T>
T ClippedMean(T mean, T spread) {
    if (!(spread > T(0) && std::abs(mean) <= T(5) * spread)) return std::max(mean, T(0));
    const T z = mean / spread;
    const T gaussian = std::exp(T(-0.5) * z * z);
    return spread * gaussian * T(0.39894228) + mean * NormalCdf(z, gaussian);
}

// The shader's ExpectedLobeWeight: E[D(u) w(u)] for N.L = u of mean `ndotl` and variance
// `variance`, w(u) = max(u, 0) or G1(u), by a second-order expansion away from the horizon and a
// clipped normal across it.
template <typename T>
T ExpectedLobeWeight(T ndotl, T variance, T roughness, uint32_t weighting) {
    const T spread = std::sqrt(std::max(variance, T(0)));
    const T D = DistributionGGX(std::sqrt(T(0.5) + T(0.5) * std::max(ndotl, T(0))), roughness);
    const T k = T(0.5) * roughness * roughness;
    if (ndotl > T(3) * spread) {
        const T a2 = roughness * roughness * roughness * roughness;
        const T A = T(0.5) + T(0.5) * a2, B = T(0.5) * a2 - T(0.5);
        const T inverseS = T(1) / (A + B * ndotl);
        if (weighting == 0) return D * (ndotl + T(0.5) * variance * (-B) * (T(4) * A - T(2) * B * ndotl) * inverseS * inverseS);
        const T inverseQ = T(1) / ((T(1) - k) * ndotl + k);
        const T w = ndotl * inverseQ, w1 = k * inverseQ * inverseQ, w2 = T(-2) * (T(1) - k) * w1 * inverseQ;
        return D * (w + T(0.5) * variance * (w * T(6) * B * B * inverseS * inverseS - T(4) * B * w1 * inverseS + w2));
    }
    const T clipped = std::max(ClippedMean(ndotl, spread), T(0));
    return D * (weighting == 0 ? clipped : clipped / ((T(1) - k) * clipped + k));
}

// The shader's BlockLobeWeight: ExpectedLobeWeight over directions of first moment `mean`.
template <typename T>
T BlockLobeWeight(vec3<T> normal, vec3<T> mean, T roughness, uint32_t weighting) {
    const T length2 = glm::dot(mean, mean);
    const T meanCosine = glm::dot(normal, mean);
    const T variance =
        T(0.5) * std::max(T(1) - length2, T(0)) * std::max(T(1) - meanCosine * meanCosine / length2, T(0));
    return ExpectedLobeWeight(meanCosine, variance, roughness, weighting);
}

template <typename T>
void baseLevel(std::span<const float> mip0, ClusterPyramid<T>& pyramid) {
    const uint32_t size = pyramid.size;
    const vec3<T> luminance(T(0.2126), T(0.7152), T(0.0722));
    auto& energy = pyramid.energy.emplace_back(size_t(size) * size * 6);
    auto& centroid = pyramid.centroid.emplace_back(size_t(size) * size * 6);
    auto& geometry = pyramid.geometry.emplace_back(size_t(size) * size * 6);
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                const size_t i = pyramid.index(0, face, x, y);
                const vec3<T> radiance{T(mip0[i * 4]), T(mip0[i * 4 + 1]), T(mip0[i * 4 + 2])};
                const T solidAngle = CubeTexelSolidAngle<T>(x, y, size);
                const T weight = std::max(glm::dot(radiance, luminance), T(0)) * solidAngle;
                energy[i] = vec4<T>(radiance * solidAngle, solidAngle);
                centroid[i] = vec4<T>(blockCentre<T>(face, x, y, size) * weight, weight);
                geometry[i] = vec4<T>(blockCentre<T>(face, x, y, size) * solidAngle, solidAngle);
            }
}

// The shader's sum of the four children, in its order.
template <typename T>
vec4<T> childSum(const std::vector<vec4<T>>& below, const ClusterPyramid<T>& pyramid, uint32_t level, uint32_t face,
                 uint32_t x, uint32_t y) {
    const auto at = [&](uint32_t dx, uint32_t dy) { return below[pyramid.index(level - 1, face, 2 * x + dx, 2 * y + dy)]; };
    return at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1);
}

template <typename T>
void upperLevel(ClusterPyramid<T>& pyramid, uint32_t level) {
    const uint32_t size = pyramid.levelSize(level);
    std::vector<vec4<T>> energy(size_t(size) * size * 6), centroid(energy.size()), geometry(energy.size());
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                const size_t i = pyramid.index(level, face, x, y);
                energy[i] = childSum(pyramid.energy[level - 1], pyramid, level, face, x, y);
                centroid[i] = childSum(pyramid.centroid[level - 1], pyramid, level, face, x, y);
                geometry[i] = childSum(pyramid.geometry[level - 1], pyramid, level, face, x, y);
            }
    pyramid.energy.push_back(std::move(energy));
    pyramid.centroid.push_back(std::move(centroid));
    pyramid.geometry.push_back(std::move(geometry));
}

// PrefilterConvolutionCS's NextBlock: the block after (face, x, y, level) and its subtree in
// depth-first order, or face 6 when the walk is over.
struct Block {
    uint32_t face = 0, x = 0, y = 0, level = 0;
};

void nextBlock(Block& block, uint32_t topSize, uint32_t topLevel) {
    while (block.level < topLevel && (block.x & block.y & 1u) != 0) {
        block.x >>= 1, block.y >>= 1;
        ++block.level;
    }
    if (block.level == topLevel) {
        const uint32_t top = (block.face * topSize + block.y) * topSize + block.x + 1;
        block = {top / (topSize * topSize), top % topSize, (top / topSize) % topSize, topLevel};
    } else if ((block.x & 1u) == 0) {
        ++block.x;
    } else {
        --block.x, ++block.y;
    }
}

// The shader's MeanLuminance.
template <typename T>
T meanLuminance(const ClusterPyramid<T>& pyramid) {
    T light = 0, solidAngle = 0;
    for (uint32_t face = 0; face < 6; ++face) {
        light += pyramid.centroid.back()[face].w;
        solidAngle += pyramid.geometry.back()[face].w;
    }
    return light / solidAngle;
}

// The shader's Opens.
template <typename T>
bool opens(const ClusterPyramid<T>& pyramid, vec3<T> normal, const Block& block, uint32_t size,
           const ConvolutionTree& tree, T meanLight) {
    const T inverseSize = T(1) / T(size); // exact: sizes are powers of two
    const vec3<T> centre = CubeFacePoint<T>(block.face, (vec2<T>(T(block.x), T(block.y)) + T(0.5)) * inverseSize);
    const T cosine = glm::dot(normal, centre) * (T(1) / std::sqrt(glm::dot(centre, centre)));
    const size_t i = pyramid.index(block.level, block.face, block.x, block.y);
    const T brightness =
        pyramid.centroid[block.level][i].w / std::max(pyramid.geometry[block.level][i].w * meanLight, T(1e-30));
    const T widthsOut = T(size) * (T(0.5) / T(tree.refine));
    const T widths = (T(2) - T(2) * cosine) * widthsOut * widthsOut;
    const T light = std::max(brightness, T(1));
    const bool nearN = widths * widths * widths < light * light;
    const bool acrossHorizon = block.level > tree.horizonLevel && std::abs(cosine) < T(kHorizonOpen) * inverseSize;
    return nearN || acrossHorizon;
}

template <typename T>
vec3<T> convolveTexel(const ClusterPyramid<T>& pyramid, vec3<T> normal, T roughness, const ConvolutionTree& tree) {
    vec3<T> radiance(0);
    T weight = 0;
    const uint32_t topSize = std::max(pyramid.size >> tree.topLevel, 1u);
    const T meanLight = meanLuminance(pyramid);
    const uint32_t termCost = 3 + 2 * (tree.topLevel - tree.fineLevel);
    const uint32_t openLimit =
        kLoopBudget / termCost - std::min(6 * topSize * topSize + 3 * tree.topLevel + 1, kLoopBudget / termCost);
    uint32_t terms = 0;
    Block block{0, 0, 0, tree.topLevel};
    while (block.face < 6) {
        while (block.level > tree.fineLevel && terms < openLimit &&
               opens(pyramid, normal, block, std::max(pyramid.size >> block.level, 1u), tree, meanLight)) {
            block.x *= 2, block.y *= 2;
            --block.level;
        }
        const size_t i = pyramid.index(block.level, block.face, block.x, block.y);
        const vec4<T> energy = pyramid.energy[block.level][i], weighted = pyramid.centroid[block.level][i];
        const vec4<T> geometry = pyramid.geometry[block.level][i];
        const vec3<T> extent = vec3<T>(geometry) * (T(1) / geometry.w);
        const vec3<T> light = weighted.w > T(0) ? vec3<T>(weighted) * (T(1) / weighted.w) : extent;
        radiance += vec3<T>(energy) * BlockLobeWeight(normal, light, roughness, tree.weighting);
        weight += energy.w * BlockLobeWeight(normal, extent, roughness, tree.weighting);
        ++terms;
        nextBlock(block, topSize, tree.topLevel);
    }
    return radiance / weight;
}

} // namespace

template <typename T>
ClusterPyramid<T> clusterPyramid(std::span<const float> mip0, uint32_t size) {
    ClusterPyramid<T> pyramid{size, {}, {}, {}};
    baseLevel(mip0, pyramid);
    for (uint32_t level = 1; (size >> level) > 0; ++level) upperLevel(pyramid, level);
    return pyramid;
}

template <typename T>
std::vector<T> convolvePrefilter(const ClusterPyramid<T>& pyramid, T roughness, uint32_t outSize,
                                 const ConvolutionTree& tree) {
    std::vector<T> texels(size_t(outSize) * outSize * 6 * 4, T(0));
    forEachRow(outSize * 6, [&](uint32_t row) {
        const uint32_t face = row / outSize, y = row % outSize;
        for (uint32_t x = 0; x < outSize; ++x) {
            const vec3<T> normal = blockCentre<T>(face, x, y, outSize);
            const vec3<T> value = convolveTexel(pyramid, normal, roughness, tree);
            const size_t i = ((size_t(face) * outSize + y) * outSize + x) * 4;
            texels[i] = value.x, texels[i + 1] = value.y, texels[i + 2] = value.z;
        }
    });
    return texels;
}

template ClusterPyramid<float> clusterPyramid(std::span<const float>, uint32_t);
template ClusterPyramid<double> clusterPyramid(std::span<const float>, uint32_t);
template std::vector<float> convolvePrefilter(const ClusterPyramid<float>&, float, uint32_t, const ConvolutionTree&);
template std::vector<double> convolvePrefilter(const ClusterPyramid<double>&, double, uint32_t, const ConvolutionTree&);

} // namespace iblkit::reference
