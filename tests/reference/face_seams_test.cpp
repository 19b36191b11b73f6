// The bench's face-seam metric: the pairs it compares straddle the cube's edges.
#include "cube_environment.hpp"
#include "face_seams.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <set>

namespace iblkit::reference {
namespace {

TEST(FaceSeams, PairsAreNeighboursAcrossEveryEdgeOnce) {
    const uint32_t size = 16, perEdge = 4;
    const auto pairs = faceEdgePairs(size, perEdge);
    EXPECT_EQ(pairs.size(), 12u * perEdge);
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (const auto& [a, b] : pairs) {
        EXPECT_NE(a.face, b.face);
        edges.insert({a.face, b.face});
        const auto da = glm::normalize(cubeTexelDirection(a.face, a.x, a.y, size));
        const auto db = glm::normalize(cubeTexelDirection(b.face, b.x, b.y, size));
        // Texels that share an edge of the cube are about one edge texel's width apart (1 / size
        // radians there): measured 0.064 at 16²; bound 2 / size, where the next texel would start.
        EXPECT_LT(std::acos(glm::dot(da, db)), 2.0 / size);
    }
    EXPECT_EQ(edges.size(), 12u) << "each of the cube's 12 edges";
}

TEST(FaceSeams, JumpIsRelativeToTheMeanLuminance) {
    EXPECT_DOUBLE_EQ(largestSeamJump({glm::dvec3(1), glm::dvec3(1), glm::dvec3(0), glm::dvec3(0)}), 0.0);
    EXPECT_NEAR(largestSeamJump({glm::dvec3(1), glm::dvec3(3)}), 1.0, 1e-12);
}

} // namespace
} // namespace iblkit::reference
