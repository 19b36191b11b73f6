#pragma once

#include "parallel_rows.hpp"
#include "pbr.hpp"

#include <cstdint>
#include <vector>

namespace iblkit::reference {

// A prefilter's output over size x size faces: prefilter(normal) at each texel centre (the
// shaders' face table), RGBA with alpha 0, ordered face, row, column; rows in parallel.
template <typename T, typename Prefilter>
std::vector<T> prefilterFaces(uint32_t size, const Prefilter& prefilter) {
    std::vector<T> faces(size_t(6) * size * size * 4);
    forEachRow(6 * size, [&](uint32_t faceRow) {
        const uint32_t face = faceRow / size, y = faceRow % size;
        for (uint32_t x = 0; x < size; ++x) {
            const vec3<T> color = prefilter(PrefilterFaceDirection<T>(face, x, y, size));
            const size_t at = ((size_t(face) * size + y) * size + x) * 4;
            faces[at] = color.r;
            faces[at + 1] = color.g;
            faces[at + 2] = color.b;
            faces[at + 3] = T(0);
        }
    });
    return faces;
}

} // namespace iblkit::reference
