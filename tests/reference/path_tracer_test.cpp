// The path tracer document's model in the C++ reference, checked against analysis: the generator
// is uniform, each sampling routine's density integrates to 1 and its histogram follows it (χ²),
// the BRDF keeps energy and is reciprocal, the BTDF obeys Walter's generalized reciprocity, and
// the point and area lights meet their closed forms.
#include "path_tracer_lights.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace iblkit::reference {
namespace {

using dvec3 = vec3<double>;

// The χ² statistic of `count` draws of a cosine in [0, 1] sorted into equal bins of the CDF.
double chiSquare(uint32_t bins, uint32_t count, const std::function<double(RandomState&)>& drawCosine,
                 const std::function<double(double)>& cdf) {
    std::vector<double> observed(bins, 0);
    RandomState rng = SeedRandom(7, 0);
    for (uint32_t i = 0; i < count; ++i) {
        const double cdfValue = std::clamp(cdf(drawCosine(rng)), 0.0, 1.0 - 1e-12);
        observed[size_t(cdfValue * bins)] += 1;
    }
    const double expected = double(count) / bins;
    double chi2 = 0;
    for (const double o : observed) chi2 += (o - expected) * (o - expected) / expected;
    return chi2;
}

// 19 degrees of freedom: P(χ² > 43.8) = 0.001.
constexpr uint32_t kBins = 20;
constexpr double kChiSquare999 = 43.8;

TEST(PathTracerRandom, DrawsAreUniformInTheHalfOpenUnitInterval) {
    RandomState rng = SeedRandom(1, 2);
    double sum = 0, sumSquares = 0;
    const int count = 200000;
    for (int i = 0; i < count; ++i) {
        const double x = Random<double>(rng);
        ASSERT_GE(x, 0.0);
        ASSERT_LT(x, 1.0);
        sum += x;
        sumSquares += x * x;
    }
    // Standard errors of the mean and of the mean square: 6.5e-4 and 6.7e-4; bounds at 5 of them.
    EXPECT_NEAR(sum / count, 0.5, 3.3e-3);
    EXPECT_NEAR(sumSquares / count, 1.0 / 3.0, 3.4e-3);
    EXPECT_LT(chiSquare(kBins, 100000, [](RandomState& r) { return Random<double>(r); }, [](double x) { return x; }),
              kChiSquare999);
}

TEST(PathTracerRandom, SeedsAndStreamsStartApartAndFloatDrawsAreTheDoubleOnes) {
    RandomState a = SeedRandom(1, 0), b = SeedRandom(1, 1), c = SeedRandom(2, 0);
    EXPECT_NE(a.State, b.State);
    EXPECT_NE(a.State, c.State);
    RandomState f = a, d = a;
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(double(Random<float>(f)), Random<double>(d)) << "24-bit draws are exact in both";
}

TEST(PathTracerSampling, CosineHemisphereFollowsItsDensity) {
    RandomState rng = SeedRandom(3, 0);
    for (int i = 0; i < 1000; ++i) {
        const auto direction = SampleCosineHemisphere<double>(rng);
        ASSERT_NEAR(glm::length(direction), 1.0, 1e-12);
        ASSERT_GT(direction.z, 0.0);
    }
    // P(cos θ <= c) = c² for the density cos θ / π.
    const double chi2 = chiSquare(kBins, 100000, [](RandomState& r) { return SampleCosineHemisphere<double>(r).z; },
                                  [](double c) { return c * c; });
    EXPECT_LT(chi2, kChiSquare999);
}

// The GGX half-vector density's CDF in cos θ: 1 - (1 - c²) / (1 + c² (α² - 1)), α = roughness².
double ggxCdf(double c, double roughness) {
    const double alpha2 = std::pow(roughness, 4);
    return 1 - (1 - c * c) / (1 + c * c * (alpha2 - 1));
}

TEST(PathTracerSampling, GgxFollowsItsDensityAtEveryRoughness) {
    for (const double roughness : {0.1, 0.35, 0.7, 1.0}) {
        const double chi2 = chiSquare(kBins, 100000, [roughness](RandomState& r) { return SampleGGX<double>(roughness, r).z; },
                                      [roughness](double c) { return ggxCdf(c, roughness); });
        EXPECT_LT(chi2, kChiSquare999) << "roughness " << roughness;
    }
}

// ∫ pdf dω over the hemisphere, as ∫_0^1 pdf(μ) 2π dμ, μ = cos θ, by the midpoint rule on panels
// that shrink geometrically towards μ = 1, where the GGX density of a low roughness peaks.
double hemisphereIntegral(const std::function<double(double)>& pdf) {
    double sum = 0;
    for (int panel = 0; panel <= 12; ++panel) {
        const double from = panel == 0 ? 0.0 : 1 - std::pow(10.0, -panel), to = panel == 12 ? 1.0 : 1 - std::pow(10.0, -panel - 1);
        const int steps = 20000;
        for (int i = 0; i < steps; ++i) sum += pdf(from + (to - from) * (i + 0.5) / steps) * (to - from) / steps;
    }
    return sum * 2 * PI<double>;
}

TEST(PathTracerSampling, EachDensityIntegratesToOne) {
    // The panels' midpoint rule: 3.7e-9 off at worst (roughness 0.1), against 1 for a density off by a factor.
    EXPECT_NEAR(hemisphereIntegral([](double mu) { return CosineHemispherePdf(mu); }), 1.0, 1e-8);
    for (const double roughness : {0.1, 0.35, 0.7, 1.0})
        EXPECT_NEAR(hemisphereIntegral([roughness](double mu) { return GgxHalfVectorPdf(mu, roughness); }), 1.0, 1e-8)
            << "roughness " << roughness;
}

dvec3 direction(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// ∫ BRDF |N.L| dL in double, by one-sample multiple importance sampling of the diffuse lobe
// (cosine-weighted) and the specular one (GGX half vectors) with the balance heuristic: unbiased,
// and of bounded variance whatever the roughness.
dvec3 directionalAlbedo(const SurfacePoint<double>& X, dvec3 V, uint32_t count) {
    RandomState rng = SeedRandom(11, 0);
    dvec3 sum(0);
    for (uint32_t i = 0; i < count; ++i) {
        dvec3 L;
        if (Random<double>(rng) < 0.5) {
            L = SampleCosineHemisphere<double>(rng);
        } else {
            const dvec3 H = SampleGGX<double>(X.Roughness, rng);
            L = 2 * glm::dot(V, H) * H - V;
        }
        if (L.z <= 0) continue;
        const dvec3 H = glm::normalize(L + V);
        const double specularPdf = GgxHalfVectorPdf(H.z, X.Roughness) / (4 * glm::dot(V, H));
        const double pdf = 0.5 * CosineHemispherePdf(L.z) + 0.5 * specularPdf;
        sum += BRDF(X, L, V) * L.z / pdf;
    }
    return sum / double(count);
}

// At 200000 samples the estimator's standard error is below 2.5e-3 (measured against 2 million
// samples: 2.5e-3 apart at worst), so the bounds below are 1 + 1e-2.
constexpr double kAlbedoBound = 1 + 1e-2;

TEST(PathTracerBsdf, AWhiteMetalReflectsAtMostWhatArrivesAndAllOfItHeadOn) {
    SurfacePoint<double> X;
    X.Metalness = 1;
    X.Albedo = dvec3(1);
    for (const double roughness : {0.05, 0.3, 0.6, 1.0})
        for (const double theta : {0.0, 0.6, 1.2, 1.5}) {
            X.Roughness = roughness;
            const double albedo = directionalAlbedo(X, direction(theta, 0), 200000).x;
            EXPECT_LE(albedo, kAlbedoBound) << "roughness " << roughness << ", theta " << theta;
            if (roughness == 0.05 && theta == 0.0) {
                EXPECT_NEAR(albedo, 1.0, 1e-2) << "a mirror seen head on";
            }
        }
}

// The document's BRDF is not energy conserving everywhere: k_d = (1 - F(L, H))(1 - metalness)
// weighs the diffuse term by the Fresnel of each pair, not by what the specular lobe took from
// that view, so a smooth dielectric at grazing views returns more than arrives: 1.042 at
// roughness 0.05 and 69° (1.018 at roughness 0.3). Half-metals and rough dielectrics stay below 1.
TEST(PathTracerBsdf, ASmoothDielectricAtGrazingViewsReturnsMoreThanArrives) {
    SurfacePoint<double> X;
    X.Albedo = dvec3(1);
    X.Roughness = 0.05;
    const double grazing = directionalAlbedo(X, direction(1.2, 0), 200000).x;
    EXPECT_GT(grazing, 1.03);
    EXPECT_LT(grazing, 1.055);
    for (const double metalness : {0.0, 0.5})
        for (const double roughness : {0.6, 1.0})
            for (const double theta : {0.0, 1.0, 1.5}) {
                X.Metalness = metalness;
                X.Roughness = roughness;
                EXPECT_LE(directionalAlbedo(X, direction(theta, 0), 200000).x, kAlbedoBound)
                    << "metalness " << metalness << ", roughness " << roughness << ", theta " << theta;
            }
}

TEST(PathTracerBsdf, TheBrdfIsReciprocal) {
    SurfacePoint<double> X;
    X.Albedo = dvec3(0.9, 0.5, 0.2);
    X.Metalness = 0.3;
    X.Roughness = 0.4;
    RandomState rng = SeedRandom(5, 0);
    for (int i = 0; i < 1000; ++i) {
        const dvec3 L = SampleCosineHemisphere<double>(rng), V = SampleCosineHemisphere<double>(rng);
        const dvec3 there = BRDF(X, L, V), back = BRDF(X, V, L);
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(there[c], back[c], 1e-12 * std::max(1.0, there[c]));
    }
}

TEST(PathTracerBsdf, TheBtdfObeysGeneralizedReciprocity) {
    SurfacePoint<double> X;
    X.Transmittance = 1;
    X.Roughness = 0.5;
    X.Eta = 1.5;
    RandomState rng = SeedRandom(6, 0);
    for (int i = 0; i < 1000; ++i) {
        const dvec3 L = SampleCosineHemisphere<double>(rng);
        dvec3 V = SampleCosineHemisphere<double>(rng);
        V.z = -V.z; // inside
        // f(L, V) / η_o² = f(V, L) / η_i²: L outside (η_i = 1), V inside (η_o = 1.5).
        const dvec3 there = BTDF(X, L, V) / (1.5 * 1.5), back = BTDF(X, V, L) / 1.0;
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(there[c], back[c], 1e-12 * std::max(1.0, there[c]));
    }
}

TEST(PathTracerBsdf, TheBsdfPicksTheBtdfAcrossTheSurface) {
    SurfacePoint<double> X;
    X.Transmittance = 0.25;
    const dvec3 above = glm::normalize(dvec3(0.3, 0, 1)), below = glm::normalize(dvec3(-0.2, 0, -1));
    const dvec3 reflected = BSDF(X, above, glm::normalize(dvec3(-0.3, 0.1, 1)));
    EXPECT_EQ(reflected, 0.75 * BRDF(X, above, glm::normalize(dvec3(-0.3, 0.1, 1))));
    EXPECT_EQ(BSDF(X, above, below), 0.25 * BTDF(X, above, below));
    EXPECT_GT(BTDF(X, above, below).x, 0.0) << "light enters the glass";
    EXPECT_GT(BTDF(X, below, above).x, 0.0) << "and leaves it";
}

// A Lambert-like plane lit head on: seen along the light, H = L and F = F0 = 0 (η = 1), so the
// BSDF is albedo / π alone.
SurfacePoint<double> lambertPlane() {
    SurfacePoint<double> X;
    X.Albedo = dvec3(0.5);
    X.Eta = 1;
    return X;
}

TEST(PathTracerLights, APointLightOnAPlaneIsItsClosedForm) {
    const auto X = lambertPlane();
    const PointLight<double> light{{0, 0, 2}, dvec3(8)};
    // ρ / π · I cos θ / d² with cos θ = 1, d = 2.
    EXPECT_NEAR(PointLightTerm(X, dvec3(0, 0, 1), light, 1.0).x, 0.5 / PI<double> * 8 / 4, 1e-12);
    EXPECT_EQ(PointLightTerm(X, dvec3(0, 0, 1), light, 0.0).x, 0.0) << "occluded";
}

TEST(PathTracerLights, ASmallAreaLightConvergesToThePointLight) {
    const auto X = lambertPlane();
    const double side = 0.01, radiance = 8;
    const AreaLight<double> area{{-side / 2, -side / 2, 2}, {0, side, 0}, {side, 0, 0}, dvec3(radiance)}; // faces down
    const PointLight<double> point{{0, 0, 2}, dvec3(radiance * side * side)};
    RandomState rng = SeedRandom(9, 0);
    dvec3 sum(0);
    const int count = 4096;
    for (int i = 0; i < count; ++i) sum += AreaLightTerm(X, dvec3(0, 0, 1), area, SampleAreaLight(area, rng), 1.0);
    // Over a 0.01² square at distance 2 the integrand varies by 2e-5 relative.
    EXPECT_NEAR(sum.x / count, PointLightTerm(X, dvec3(0, 0, 1), point, 1.0).x, 1e-4 * sum.x / count);
    const AreaLight<double> backwards{area.Corner, area.EdgeV, area.EdgeU, area.Radiance};
    EXPECT_EQ(AreaLightTerm(X, dvec3(0, 0, 1), backwards, SampleAreaLight(backwards, rng), 1.0).x, 0.0)
        << "nothing from the back of the light";
}

TEST(PathTracerLights, ADirectionalLightIsTheBsdfTimesItsCosine) {
    const auto X = lambertPlane();
    const DirectionalLight<double> light{{0, 0, -1}, dvec3(3)};
    EXPECT_NEAR(DirectionalLightTerm(X, dvec3(0, 0, 1), light, 1.0).x, 0.5 / PI<double> * 3, 1e-12);
}

} // namespace
} // namespace iblkit::reference
