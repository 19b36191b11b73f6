#include "shading/sphere_transmission.hpp"

#include "shading/lobe_table.hpp"
#include "shading/transmission_table.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace iblkit::shading {

namespace {

// Roberts' R4 sequence: the fractional parts of n times the powers of 1 / φ₄, where φ₄ is the
// real root of x⁵ = x + 1: low discrepancy in four dimensions, two per crossing.
struct R4Sequence {
    double step[4];
    R4Sequence() {
        double phi = 1.2;
        for (int i = 0; i < 20; ++i) phi = std::pow(1 + phi, 1.0 / 5);
        for (int d = 0; d < 4; ++d) step[d] = std::pow(1 / phi, d + 1);
    }
    double at(uint32_t n, int d) const { return std::fmod(0.5 + n * step[d], 1.0); }
};

// A half vector about +Z drawn by D(h) cos θ_h: tan² θ_h = α² u / (1 - u).
glm::dvec3 halfVectorAt(double u, double v, double alpha) {
    const double tan2 = alpha * alpha * u / (1 - u), cosH = 1 / std::sqrt(1 + tan2), sinH = std::sqrt(tan2) * cosH;
    const double phi = 2 * std::numbers::pi * v;
    return {sinH * std::cos(phi), sinH * std::sin(phi), cosH};
}

struct Frame {
    glm::dvec3 t, b, n;
    explicit Frame(const glm::dvec3& normal) : n(normal) {
        const glm::dvec3 helper = std::abs(n.z) < 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
        t = glm::normalize(glm::cross(helper, n));
        b = glm::cross(n, t);
    }
    glm::dvec3 toLocal(const glm::dvec3& w) const { return {glm::dot(w, t), glm::dot(w, b), glm::dot(w, n)}; }
    glm::dvec3 toWorld(const glm::dvec3& l) const { return l.x * t + l.y * b + l.z * n; }
};

const KernelRoughness& g1Kernel() {
    static const KernelRoughness kernel(LobeWeighting::G1);
    return kernel;
}

} // namespace

SphereTransmission sphereTransmission(double ndotv, double roughness, double eta, uint32_t paths) {
    static const R4Sequence sequence;
    const double mu = std::clamp(ndotv, 1e-4, 1.0), alpha = std::max(roughness * roughness, 1e-6);
    const glm::dvec3 N(0, 0, 1), V(std::sqrt(1 - mu * mu), 0, mu);
    double total = 0;
    glm::dvec3 sum(0); // Σ w L
    std::vector<std::pair<glm::dvec3, double>> exits;
    exits.reserve(paths);
    for (uint32_t i = 0; i < paths; ++i) {
        const auto in = refractThroughFacet(V, halfVectorAt(sequence.at(i, 0), sequence.at(i, 1), alpha), roughness, eta,
                                            Crossing::Entering);
        if (in.weight <= 0) continue;
        const glm::dvec3 exitPoint = N - 2 * glm::dot(N, in.direction) * in.direction; // the chord's far end
        const Frame frame(exitPoint);
        const auto out = refractThroughFacet(frame.toLocal(-in.direction),
                                             halfVectorAt(sequence.at(i, 2), sequence.at(i, 3), alpha), roughness, eta,
                                             Crossing::Leaving);
        if (out.weight <= 0) continue;
        const double w = in.weight * out.weight;
        const glm::dvec3 L = frame.toWorld(out.direction);
        exits.emplace_back(L, w);
        total += w;
        sum += w * L;
    }
    if (total <= 0) return {};
    // The lobe is symmetric about the plane of N and V: its mean lies in it.
    const glm::dvec3 mean = glm::normalize(glm::dvec3(sum.x, 0, sum.z));
    const glm::dvec3 across(0, 1, 0), along = glm::cross(across, mean);
    double alongVariance = 0, acrossVariance = 0;
    for (const auto& [L, w] : exits) {
        alongVariance += w * std::pow(glm::dot(L, along), 2);
        acrossVariance += w * L.y * L.y;
    }
    const double variance = (alongVariance + acrossVariance) / (2 * total);
    // The angle from -V towards N: u is the unit in the plane, perpendicular to V, on N's side.
    const glm::dvec3 u = mu < 1 - 1e-9 ? glm::normalize(N - mu * V) : glm::dvec3(1, 0, 0);
    return {float(total / paths), float(std::atan2(glm::dot(mean, u), glm::dot(mean, -V))),
            float(g1Kernel().roughnessFor(variance))};
}

std::vector<float> sphereTransmissionTable(uint32_t size) {
    return tablePerEta(size, 4, [](double ndotv, double roughness, double eta, float* texel) {
        const auto fit = sphereTransmission(ndotv, roughness, eta, kSphereTransmissionPaths);
        texel[0] = fit.energy, texel[1] = fit.angle, texel[2] = fit.roughness, texel[3] = 0;
    });
}

} // namespace iblkit::shading
