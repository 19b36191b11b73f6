#pragma once

#include "cube_environment.hpp"
#include "mipped_cube.hpp"
#include "pyramid_fit.hpp"
#include "pyramid_ring.hpp"

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace iblkit::reference {

// A cube with its mips as a texture unit reads it with linear min, mag and mip filters:
// SampleLevel is bilinear (seamless) on the two mips around lod, then their lerp, with lod
// clamped to the chain.
class MippedEnvironment {
public:
    explicit MippedEnvironment(const MippedCube& cube);
    uint32_t size() const { return levels_.front().size(); }
    glm::dvec3 sampleLevel(glm::dvec3 direction, double lod) const;

private:
    std::vector<CubeEnvironment> levels_;
};

// PrefilterFilteredCS for one roughness over size x size faces, following its arithmetic in T:
// RGBA (alpha 0) per texel, ordered face, row, column.
template <typename T>
std::vector<T> referenceFilteredPrefilter(const MippedEnvironment& source, T roughness, uint32_t size, uint32_t sampleCount);

// PrefilterTableCS over size x size faces with the table it is given (prefilterSampleTable's).
template <typename T>
std::vector<T> referenceTablePrefilter(const MippedEnvironment& source, const std::vector<glm::vec4>& table, uint32_t size);

// PrefilterPyramidCS over size x size faces with the reads it is given (fitPyramidReads's).
template <typename T>
std::vector<T> referencePyramidPrefilter(const MippedEnvironment& source, const std::vector<PyramidRead>& reads, uint32_t size);

// PrefilterRingCS over size x size faces with `ring` (pyramidRing's) and ringReads reads on it.
template <typename T>
std::vector<T> referenceRingPrefilter(const MippedEnvironment& source, const PyramidRing& ring, uint32_t ringReads,
                                      uint32_t size);

} // namespace iblkit::reference
