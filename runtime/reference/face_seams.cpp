#include "face_seams.hpp"

#include "cube_environment.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace iblkit::reference {

std::vector<std::array<PrefilterTexel, 2>> faceEdgePairs(uint32_t size, uint32_t perEdge) {
    std::vector<std::array<PrefilterTexel, 2>> pairs;
    const int last = int(size) - 1;
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t j = 0; j < perEdge; ++j) {
            const int along = int((j + 0.5) * size / perEdge);
            // (inside column, row) and the step across the edge, for the left, right, top and bottom edges.
            const int edges[4][4] = {{0, along, -1, 0}, {last, along, 1, 0}, {along, 0, 0, -1}, {along, last, 0, 1}};
            for (const auto& edge : edges) {
                const auto across = cubeTexelOf(cubeTexelDirection(face, edge[0] + edge[2], edge[1] + edge[3], size), size);
                if (across.face < face) continue;
                pairs.push_back({PrefilterTexel{face, uint32_t(edge[0]), uint32_t(edge[1])},
                                 PrefilterTexel{across.face, across.column, across.row}});
            }
        }
    return pairs;
}

double largestSeamJump(const std::vector<glm::dvec3>& radiance) {
    const glm::dvec3 luminance(0.2126, 0.7152, 0.0722);
    double largest = 0;
    for (size_t i = 0; i + 1 < radiance.size(); i += 2) {
        const double a = glm::dot(radiance[i], luminance), b = glm::dot(radiance[i + 1], luminance);
        if (a + b > 0) largest = std::max(largest, std::abs(a - b) / ((a + b) / 2));
    }
    return largest;
}

} // namespace iblkit::reference
