#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace iblkit::reference {

// Mip 0 of a cube environment as a texture unit reads it: bilinear filtering, seamless across
// faces (Vulkan always filters cubes seamlessly). Texels are RGBA floats ordered face (+X, -X,
// +Y, -Y, +Z, -Z), row, column — the runtime's upload order.
class CubeEnvironment {
public:
    CubeEnvironment(uint32_t size, std::vector<float> texels);

    // A sky with a horizon, a ground, colour variation and a soft bright sun: structure in every
    // direction, smooth enough that bilinear filtering differences stay small.
    static CubeEnvironment testEnvironment(uint32_t size);
    static glm::dvec3 testRadiance(glm::dvec3 direction);

    uint32_t size() const { return size_; }
    const std::vector<float>& texels() const { return texels_; }

    glm::dvec3 sample(glm::dvec3 direction) const;

private:
    glm::dvec3 texel(uint32_t face, int column, int row) const; // seamless beyond the face's edges

    uint32_t size_;
    std::vector<float> texels_;
};

// The direction through texel (column, row) of a face in Vulkan's face-selection convention;
// the column and row may lie outside the face, extrapolating its plane.
glm::dvec3 cubeTexelDirection(uint32_t face, double column, double row, uint32_t size);

// The texel of a size² face set that `direction` falls in, by Vulkan's face selection.
struct CubeTexelIndex {
    uint32_t face, column, row;
};
CubeTexelIndex cubeTexelOf(glm::dvec3 direction, uint32_t size);

} // namespace iblkit::reference
