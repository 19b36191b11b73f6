// The glass tables built with the kit (glass_tables_main.cpp) against the same functions run here:
// texel by texel, exactly, on a stride through every layer.
#include "shading/built_glass_tables.hpp"
#include "shading/sphere_transmission.hpp"
#include "shading/transmission_table.hpp"

#include <gtest/gtest.h>

namespace iblkit::shading {
namespace {

constexpr uint32_t kTableSize = kTransmissionTableSize;
// A prime stride: about 130 texels of the 8192, at every layer, N·V and roughness.
constexpr size_t kStride = 61;

struct Texel {
    double ndotv, roughness, eta;
};

Texel texelAt(size_t index) {
    const size_t x = index % kTableSize, y = index / kTableSize % kTableSize, layer = index / (kTableSize * kTableSize);
    return {(x + 0.5) / kTableSize, (y + 0.5) / kTableSize, kTransmissionEtas[layer]};
}

TEST(BuiltGlassTables, TheInterfaceTableIsTransmittedShareAtEveryTexel) {
    const auto table = builtTransmissionTable();
    ASSERT_EQ(table.size(), size_t(kTableSize) * kTableSize * kTransmissionEtas.size() * 2);
    for (size_t index = 0; index < table.size() / 2; index += kStride) {
        const auto [ndotv, roughness, eta] = texelAt(index);
        EXPECT_EQ(table[2 * index], float(transmittedShare(ndotv, roughness, eta, Crossing::Entering))) << index;
        EXPECT_EQ(table[2 * index + 1], float(transmittedShare(ndotv, roughness, eta, Crossing::Leaving))) << index;
    }
}

TEST(BuiltGlassTables, TheSphereTableIsTheSphereTransmissionAtEveryTexel) {
    const auto table = builtSphereTransmissionTable();
    ASSERT_EQ(table.size(), size_t(kTableSize) * kTableSize * kTransmissionEtas.size() * 4);
    for (size_t index = 0; index < table.size() / 4; index += kStride) {
        const auto [ndotv, roughness, eta] = texelAt(index);
        const auto fit = sphereTransmission(ndotv, roughness, eta, kSphereTransmissionPaths);
        EXPECT_EQ(table[4 * index], fit.energy) << index;
        EXPECT_EQ(table[4 * index + 1], fit.angle) << index;
        EXPECT_EQ(table[4 * index + 2], fit.roughness) << index;
        EXPECT_EQ(table[4 * index + 3], 0.f) << index;
    }
}

} // namespace
} // namespace iblkit::shading
