// The transmission table against what it must be where it is known: smooth, the interface passes
// 1 - F and refuses past the critical angle; rough, it is the split sum's BTDF integrated over L
// directly, a quadrature that shares nothing with the table's over half vectors.
#include "shading/transmission_table.hpp"

#include "reference/path_tracer_bsdf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace iblkit::shading {
namespace {

using glm::dvec3;

// hlsl/Common/SplitSumMaterial.fxh's BtdfAsSplitSum, transcribed line by line.
double splitSumBtdf(const reference::SurfacePoint<double>& X, dvec3 L, dvec3 V) {
    const dvec3 N = X.Normal;
    const bool LightOutside = glm::dot(L, N) > 0;
    const double EtaI = LightOutside ? 1 : X.Eta, EtaO = LightOutside ? X.Eta : 1;
    const dvec3 H = -glm::normalize(EtaI * L + EtaO * V);
    const dvec3 Rarer = EtaI <= EtaO ? L : V;
    const double Fresnel = reference::F(Rarer, H, reference::BaseReflectance(X)).x;
    const double LdotH = glm::dot(L, H), VdotH = glm::dot(V, H), Sum = EtaI * LdotH + EtaO * VdotH;
    const double g = reference::GeometrySmithForIBL(std::abs(glm::dot(N, L)), std::abs(glm::dot(N, V)), X.Roughness);
    return std::abs(LdotH) * std::abs(VdotH) * EtaO * EtaO * (1 - Fresnel) / (Sum * Sum) * g /
           (std::abs(glm::dot(N, V)) * std::abs(glm::dot(N, L))) * reference::D(N, H, X.Roughness);
}

// The share by a midpoint rule over L's hemisphere in (cos θ, φ).
double shareOverL(double ndotv, double roughness, double eta, Crossing crossing) {
    reference::SurfacePoint<double> X;
    X.Roughness = roughness, X.Eta = eta, X.Transmittance = 1;
    const double side = crossing == Crossing::Entering ? 1 : -1;
    const dvec3 V(std::sqrt(1 - ndotv * ndotv), 0, side * ndotv);
    const int cosines = 2400, angles = 1200;
    double sum = 0;
    for (int i = 0; i < cosines; ++i) {
        const double c = (i + 0.5) / cosines, s = std::sqrt(1 - c * c);
        for (int j = 0; j < angles; ++j) {
            const double phi = 2 * std::numbers::pi * (j + 0.5) / angles;
            const dvec3 L(s * std::cos(phi), s * std::sin(phi), -side * c);
            sum += splitSumBtdf(X, L, V) * c;
        }
    }
    const double etaV = crossing == Crossing::Entering ? 1 : eta, etaL = crossing == Crossing::Entering ? eta : 1;
    return sum * 2 * std::numbers::pi / (double(cosines) * angles) * (etaL / etaV) * (etaL / etaV);
}

double schlickTransmission(double cosine, double eta) {
    const double f0 = std::pow((1 - eta) / (1 + eta), 2);
    return 1 - (f0 + (1 - f0) * std::pow(1 - cosine, 5));
}

TEST(TransmissionTable, RoughItIsTheBtdfIntegratedOverTheFarHemisphere) {
    // Midpoint over 2400 x 1200 directions against the half vectors' nodes: they agree within
    // 9.7e-4 at these points (the most at N·V = 0.8, roughness 0.9, leaving: the half vectors'
    // 64 angles resolve the lobe's step at total internal reflection only as 1 / count; the grid
    // over L is stable to 1e-6 at twice its cosines).
    for (const double ndotv : {0.3, 0.8})
        for (const double roughness : {0.5, 0.9})
            for (const auto crossing : {Crossing::Entering, Crossing::Leaving})
                EXPECT_NEAR(transmittedShare(ndotv, roughness, 1.5, crossing), shareOverL(ndotv, roughness, 1.5, crossing), 1e-3)
                    << ndotv << ' ' << roughness << ' ' << int(crossing);
}

TEST(TransmissionTable, SmoothItPassesOneMinusFresnelAndNothingPastTheCriticalAngle) {
    const double eta = 1.5;
    for (const double ndotv : {0.2, 0.6, 1.0})
        EXPECT_NEAR(transmittedShare(ndotv, 0.01, eta, Crossing::Entering), schlickTransmission(ndotv, eta), 2e-3) << ndotv;
    // Leaving, Schlick's F takes the outside's cosine, the refracted one.
    const double inside = 0.9, outside = std::sqrt(1 - eta * eta * (1 - inside * inside));
    EXPECT_NEAR(transmittedShare(inside, 0.01, eta, Crossing::Leaving), schlickTransmission(outside, eta), 2e-3);
    EXPECT_LT(transmittedShare(0.6, 0.01, eta, Crossing::Leaving), 1e-3) << "cos θ_c = 0.745: reflected totally";
}

TEST(TransmissionTable, RougherPassesLessAndTheLayersFollowTheIndex) {
    EXPECT_LT(transmittedShare(0.8, 1.0, 1.5, Crossing::Entering), transmittedShare(0.8, 0.3, 1.5, Crossing::Entering));
    EXPECT_LT(transmittedShare(0.8, 0.5, 2.5, Crossing::Entering), transmittedShare(0.8, 0.5, 1.1, Crossing::Entering));
    const uint32_t size = 4;
    const auto table = transmissionTable(size);
    ASSERT_EQ(table.size(), size_t(size) * size * kTransmissionEtas.size() * 2);
    const size_t layer = 2, x = 3, y = 1; // eta 1.5, N·V 0.875, roughness 0.375
    const float* texel = &table[((layer * size + y) * size + x) * 2];
    EXPECT_FLOAT_EQ(texel[0], float(transmittedShare(0.875, 0.375, 1.5, Crossing::Entering)));
    EXPECT_FLOAT_EQ(texel[1], float(transmittedShare(0.875, 0.375, 1.5, Crossing::Leaving)));
}

} // namespace
} // namespace iblkit::shading
