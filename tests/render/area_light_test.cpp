// An area light in the render's Monte Carlo reference: found both by its own draws and by the
// BSDF's, the two weighted by the power heuristic, and hiding the environment behind it. Sphere
// centres (N = V = +Z) under a lit square in front of them, in an environment of 1 whose +Z face is
// 10 (so that the environment's own draws go behind the square often), against the integrals of
// the BSDF over the environment and of the document's area-light term over the square; and the
// two ways of getting it wrong, which that comparison must catch.
#include "grid_render.hpp"
#include "reference/path_tracer_lights.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace iblkit::render {
namespace {

using namespace grid_test;

constexpr float kEnvironment = 1.f, kFront = 10.f, kPanel = 4.f;

bake::EnvironmentInput brightFront() {
    auto input = uniformEnvironment(kEnvironment);
    const size_t face = 4 * 16 * 16 * 4; // +Z
    std::fill(input.cubeTexels.begin() + long(face), input.cubeTexels.begin() + long(face + 16 * 16 * 4), kFront);
    return input;
}

// ∫ BSDF cos over the directions of the +Z face, in double: (x, y, 1) / r over the face, dω = dx dy / r³.
glm::dvec3 frontFaceIntegral(const reference::SurfacePoint<double>& X) {
    const int steps = 600;
    glm::dvec3 sum(0);
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const double x = (i + 0.5) / steps * 2 - 1, y = (j + 0.5) / steps * 2 - 1, r = std::sqrt(x * x + y * y + 1);
            const glm::dvec3 L(x / r, y / r, 1 / r);
            sum += reference::BSDF(X, L, glm::dvec3(0, 0, 1)) * L.z / (r * r * r);
        }
    return sum * (4.0 / (double(steps) * steps));
}

// A 2 x 2 square 3 units above the sphere centres' points (0, 0, 1), facing them: it covers a
// cone of about 25 degrees about +Z.
RenderLight panel() { return {RenderLight::Kind::Area, {-1, -1, 4}, {0, 2, 0}, {2, 0, 0}, {kPanel, kPanel, kPanel}}; }

// ∫ BSDF cos over the square, unit radiance, in double: the document's area-light term (which is
// f G Area for a point of the square) averaged over a grid of its points.
glm::dvec3 panelIntegral(const reference::SurfacePoint<double>& X) {
    const auto light = panel();
    const reference::AreaLight<double> square{glm::dvec3(light.a), glm::dvec3(light.b), glm::dvec3(light.c), {1, 1, 1}};
    const int steps = 600;
    glm::dvec3 sum(0);
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const glm::dvec3 point = square.Corner + (i + 0.5) / steps * square.EdgeU + (j + 0.5) / steps * square.EdgeV;
            sum += reference::AreaLightTerm(X, glm::dvec3(0, 0, 1), square, point, 1.0);
        }
    return sum / double(steps * steps);
}

// The most standard errors any rough enough sphere centre is from the environment's integral
// with the square's share replaced by the square's radiance.
double worstDeviation(const kernels::ShaderFiles& files = kernels::embeddedShaderFiles()) {
    const auto rendered = renderCentres(brightFront(), {panel()}, ReferenceBsdf::Document, 0.005, files);
    double worst = 0;
    for (uint32_t row = 0; row < opaqueRows(); ++row)
        for (uint32_t column = 0; column < columns(); ++column) {
            auto X = opaqueSphere(row, column);
            // Below 0.3 the lobe is too narrow for the grid of points: 600² points of 0.2° each.
            if (X.Roughness < 0.3) continue;
            X.Normal = X.Position = glm::dvec3(0, 0, 1);
            const auto expected = double(kEnvironment) * directionalAlbedo(X) + double(kFront - kEnvironment) * frontFaceIntegral(X) +
                                  double(kPanel - kFront) * panelIntegral(X);
            const size_t pixel = centreOf(row, column);
            const auto value = rgbAt(rendered.reference.mean.rgba, pixel);
            const auto error = rgbAt(rendered.reference.standardError, pixel);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(value[c] - expected[c]) / (error[c] + 1e-4));
        }
    return worst;
}

kernels::ShaderFiles mutated(const std::string& from, const std::string& to) {
    auto files = kernels::embeddedShaderFiles();
    auto& source = files.at("hlsl/RenderReferenceCS.hlsl");
    const auto at = source.find(from);
    EXPECT_NE(at, std::string::npos) << "the mutated code moved: update the mutation";
    if (at != std::string::npos) source.replace(at, from.size(), to);
    return files;
}

TEST(AreaLight, TheSquareIsItsIntegralAndHidesTheEnvironmentBehindIt) {
    const double worst = worstDeviation();
    std::printf("[ measured ] sphere centres under the square: worst %.1f standard errors\n", worst);
    // 5 standard errors over 8 x 3 comparisons (each beyond it with odds of 6e-7).
    EXPECT_LT(worst, 5.0);
}

TEST(BrokenAreaLight, CountingTheBsdfsDrawsOnTheSquareUnweightedFails) {
    const auto files = mutated("PowerHeuristic( bsdfPdf, AreaLightPdf( light, L, t ) )", "1.f");
    const double worst = worstDeviation(files);
    std::printf("[ measured ] the square counted twice: worst %.1f standard errors\n", worst);
    EXPECT_GT(worst, 20.0);
}

TEST(BrokenAreaLight, SeeingTheEnvironmentThroughTheSquareFails) {
    const auto files = mutated("|| HiddenByAreaLight( vertex.X.Position, L )", "");
    const double worst = worstDeviation(files);
    std::printf("[ measured ] the environment seen through the square: worst %.1f standard errors\n", worst);
    EXPECT_GT(worst, 20.0);
}

} // namespace
} // namespace iblkit::render
