#pragma once

#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace iblkit::reference {

// ClusterCubeCS's energy pyramid: per level (0 = the source's mip 0), per texel ordered face,
// row, column: energy (rgb: radiance times solid angle, a: solid angle) and centroid (xyz: the
// sum of w times direction, a: the sum of w; w = max(luminance, 0) times solid angle) and
// geometry (xyz: the sum of solid angle times direction, a: solid angle).
template <typename T>
struct ClusterPyramid {
    uint32_t size = 0;
    std::vector<std::vector<glm::vec<4, T>>> energy, centroid, geometry;

    uint32_t levelSize(uint32_t level) const { return size >> level; }
    size_t index(uint32_t level, uint32_t face, uint32_t x, uint32_t y) const {
        return (size_t(face) * levelSize(level) + y) * levelSize(level) + x;
    }
};

// ClusterCubeCS over every level, in its arithmetic: T = float follows the shader, T = double
// sums the same terms without rounding. `mip0` is RGBA, face, row, column; size a power of two.
template <typename T>
ClusterPyramid<T> clusterPyramid(std::span<const float> mip0, uint32_t size);

// PrefilterConvolutionCS's parameters (pyramid levels counted from the source's mip 0).
struct ConvolutionTree {
    uint32_t topLevel = 0, fineLevel = 0;
    double refine = 0;
    uint32_t horizonLevel = 0;
    uint32_t weighting = 0; // the lobe: 0 D N·L, 1 D G1(N·L) (the shader's Weighting)
};

// PrefilterConvolutionCS for one roughness over outSize x outSize faces, visiting the blocks in
// the shader's order: RGBA (alpha 0) per texel, face, row, column.
template <typename T>
std::vector<T> convolvePrefilter(const ClusterPyramid<T>& pyramid, T roughness, uint32_t outSize,
                                 const ConvolutionTree& tree);

} // namespace iblkit::reference
