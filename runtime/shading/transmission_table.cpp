#include "shading/transmission_table.hpp"

#include "reference/parallel_rows.hpp"
#include "reference/pbr.hpp"
#include "shading/half_vector_nodes.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace iblkit::shading {

using reference::GeometrySchlickGGXForIBL;

namespace {

// φ over [0, π]: the lobe is symmetric about the plane of N and V. At these counts the share is
// within 4e-5 of 16 times as many nodes (the lobe's edges, at total internal reflection and at the
// facets V sees edge on, are steps the midpoint rule resolves only as 1 / count).
constexpr int kTransmissionS = 256, kHorizon = 64, kTransmissionPhi = 64;
constexpr int kBandCosines = 96, kBandAngles = 48; // the inward band's grid over L

double fifthPower(double x) { return x * x * x * x * x; }

double dielectricF0(double eta) { return (1 - eta) * (1 - eta) / ((1 + eta) * (1 + eta)); }

// 1 - F, Schlick's F on the outside's cosine with the facet's normal.
double schlickTransmitted(double f0, const glm::dvec3& outside, const glm::dvec3& h) {
    return (1 - f0) * (1 - fifthPower(1 - std::clamp(glm::dot(outside, h), 0.0, 1.0)));
}

// The document's BTDF has no χ+(N·h): where its generalized half vector -(eta_L L + eta_V V)
// points inside, D(N·h) still counts it, on a band of L at the far side's horizon
// (where eta_L L.z + eta_V V.z > 0), and the Monte Carlo reference integrates it there. No facet refracts
// V into that band, so the half vectors above miss it: a grid over L's band counts it (up to 0.08
// of the share at N·V = 0.3, roughness 0.9, where D is wide). The BTDF there is transcribed from
// BtdfAsSplitSum.
double inwardBandShare(const glm::dvec3& V, double roughness, double eta, Crossing crossing) {
    const bool entering = crossing == Crossing::Entering;
    const double etaV = entering ? 1 : eta, etaL = entering ? eta : 1;
    // eta_L L.z + eta_V V.z > 0: |L.z| below eta_V |V.z| / eta_L entering, above it leaving.
    const double edge = std::min(etaV * std::abs(V.z) / etaL, 1.0);
    const double low = entering ? 0 : edge, width = entering ? edge : 1 - edge;
    const double f0 = dielectricF0(eta), alpha = roughness * roughness;
    double sum = 0;
    for (int i = 0; i < kBandCosines; ++i) {
        const double c = low + width * (i + 0.5) / kBandCosines, s = std::sqrt(1 - c * c);
        for (int j = 0; j < kBandAngles; ++j) {
            const double phi = std::numbers::pi * (j + 0.5) / kBandAngles;
            const glm::dvec3 L(s * std::cos(phi), s * std::sin(phi), V.z > 0 ? -c : c);
            const glm::dvec3 h = -glm::normalize(etaL * L + etaV * V);
            if (h.z >= 0) continue;
            const double ldoth = glm::dot(L, h), vdoth = glm::dot(V, h), denominator = etaL * ldoth + etaV * vdoth;
            const double g = GeometrySchlickGGXForIBL(c, roughness) * GeometrySchlickGGXForIBL(std::abs(V.z), roughness);
            // f |N·L| with f's 1 / |N·L| cancelled, times (eta_L / eta_V)²: the BTDF's eta_V² cancels.
            sum += std::abs(ldoth * vdoth) * etaL * etaL * schlickTransmitted(f0, entering ? V : L, h) / (denominator * denominator) *
                   g / std::abs(V.z) * ggxDistribution(h.z, alpha);
        }
    }
    return sum * 2 * std::numbers::pi * width / (double(kBandCosines) * kBandAngles);
}

} // namespace

FacetRefraction refractThroughFacet(const glm::dvec3& V, const glm::dvec3& h, double roughness, double eta, Crossing crossing) {
    // The split sum's BTDF |N·L| over the density of L that refracting V about h gives,
    // D cos θ_h eta_L² |L·h| / (eta_V V·h + eta_L L·h)², times (eta_L / eta_V)², leaves
    // |V·h| (1 - F) G / (|N·V| cos θ_h).
    const bool entering = crossing == Crossing::Entering;
    const glm::dvec3 facing = entering ? h : -h; // the facet's normal on V's side
    const double vdoth = glm::dot(V, facing);
    if (vdoth <= 0) return {};
    const glm::dvec3 L = glm::refract(-V, facing, entering ? 1 / eta : eta);
    if (glm::dot(L, L) == 0 || L.z * V.z >= 0) return {};
    const double g = GeometrySchlickGGXForIBL(std::abs(L.z), roughness) * GeometrySchlickGGXForIBL(std::abs(V.z), roughness);
    return {L, vdoth * schlickTransmitted(dielectricF0(eta), entering ? V : L, h) * g / (std::abs(V.z) * h.z)};
}

double transmittedShare(double ndotv, double roughness, double eta, Crossing crossing) {
    const double mu = std::clamp(ndotv, 1e-4, 1.0);
    const double side = crossing == Crossing::Entering ? 1 : -1;
    const glm::dvec3 V(std::sqrt(1 - mu * mu), 0, side * mu);
    const double alpha = std::max(roughness * roughness, 1e-6);
    auto nodes = halfVectorNodes(alpha, kTransmissionS);
    const auto horizon = horizonNodes(alpha, kHorizon);
    nodes.insert(nodes.end(), horizon.begin(), horizon.end());
    double share = 0;
    for (int j = 0; j < kTransmissionPhi; ++j) {
        const double phi = std::numbers::pi * (j + 0.5) / kTransmissionPhi, cosPhi = std::cos(phi), sinPhi = std::sin(phi);
        for (const auto& node : nodes) {
            const glm::dvec3 h(node.sinH * cosPhi, node.sinH * sinPhi, node.cosH);
            share += node.weight * refractThroughFacet(V, h, roughness, eta, crossing).weight;
        }
    }
    return share / kTransmissionPhi + inwardBandShare(V, roughness, eta, crossing);
}

std::vector<float> tablePerEta(uint32_t size, uint32_t channels,
                               const std::function<void(double ndotv, double roughness, double eta, float* texel)>& fill) {
    const auto layers = uint32_t(kTransmissionEtas.size());
    std::vector<float> table(size_t(size) * size * layers * channels);
    reference::forEachRow(size * layers, [&](uint32_t row) {
        const uint32_t layer = row / size, y = row % size;
        for (uint32_t x = 0; x < size; ++x)
            fill((x + 0.5) / size, (y + 0.5) / size, kTransmissionEtas[layer], &table[((size_t(layer) * size + y) * size + x) * channels]);
    });
    return table;
}

std::vector<float> transmissionTable(uint32_t size) {
    return tablePerEta(size, 2, [](double ndotv, double roughness, double eta, float* texel) {
        texel[0] = float(transmittedShare(ndotv, roughness, eta, Crossing::Entering));
        texel[1] = float(transmittedShare(ndotv, roughness, eta, Crossing::Leaving));
    });
}

} // namespace iblkit::shading
