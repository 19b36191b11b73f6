#include "shading/lobe_table.hpp"

#include "reference/parallel_rows.hpp"
#include "reference/pbr.hpp"
#include "shading/half_vector_nodes.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace iblkit::shading {

std::string_view nameOf(LobeWeighting weighting) { return weighting == LobeWeighting::G1 ? "G1" : "N·L"; }

using reference::GeometrySchlickGGXForIBL;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSteps = 512; // roughness steps of KernelRoughness's table

double ggx(double ndoth, double roughness) {
    const double a2 = std::pow(roughness, 4);
    const double d = ndoth * ndoth * (a2 - 1) + 1;
    return a2 / (kPi * d * d);
}

constexpr int kLobeS = 256, kLobePhi = 64; // φ over [0, π]: the lobe is symmetric about the plane of N and V

} // namespace

double prefilterKernel(double cosine, double roughness, LobeWeighting weighting) {
    if (cosine <= 0) return 0;
    const double d = ggx(std::sqrt((1 + cosine) / 2), roughness);
    return d * (weighting == LobeWeighting::NdotL ? cosine : GeometrySchlickGGXForIBL(cosine, roughness));
}

double kernelTangentVariance(double roughness, LobeWeighting weighting) {
    // At N = V = d the half vector's polar angle alone sets L's: cos θ_l = 2 cos² θ_h - 1, and
    // dω_l = 4 cos θ_h dω_h, so each node carries the kernel's weighting of d·L (D cancels into the
    // nodes' own weight).
    double spread = 0, total = 0;
    for (const auto& node : halfVectorNodes(roughness * roughness, kLobeS)) {
        const double cosL = 2 * node.cosH * node.cosH - 1;
        if (cosL <= 0) continue;
        const double w = node.weight * (weighting == LobeWeighting::NdotL ? cosL : GeometrySchlickGGXForIBL(cosL, roughness));
        spread += w * (1 - cosL * cosL) / 2;
        total += w;
    }
    return total > 0 ? spread / total : 0;
}

KernelRoughness::KernelRoughness(LobeWeighting weighting) {
    for (int i = 1; i <= kSteps; ++i) variances_.push_back(kernelTangentVariance(double(i) / kSteps, weighting));
}

double KernelRoughness::roughnessFor(double variance) const {
    const auto above = std::lower_bound(variances_.begin(), variances_.end(), variance);
    if (above == variances_.end()) return 1;
    const auto i = size_t(above - variances_.begin());
    const double low = i ? variances_[i - 1] : 0, high = variances_[i];
    const double fraction = high > low ? (variance - low) / (high - low) : 1;
    return (double(i) + fraction) / kSteps;
}

LobeFit fitLobe(double ndotv, double roughness, LobeWeighting weighting) {
    const double mu = std::clamp(ndotv, 1e-4, 1.0);
    const glm::dvec3 V(std::sqrt(1 - mu * mu), 0, mu); // N = +Z
    const double thetaR = std::acos(mu);
    if (roughness <= 1e-4) return {1.f, float(roughness), float(roughness), 0.f};
    const double alpha = roughness * roughness;
    // First moment, then the second moments about the mean direction.
    const auto nodes = halfVectorNodes(alpha, kLobeS);
    // f (N·L) dω_l = D G1(L) G1(V) / (4 N·V) · 4 (V·H) dω_h, and the nodes carry D cos θ_h dω_h.
    const auto forEachDirection = [&](const auto& visit) {
        for (int j = 0; j < kLobePhi; ++j) {
            const double phi = kPi * (j + 0.5) / kLobePhi, cosPhi = std::cos(phi), sinPhi = std::sin(phi);
            for (const auto& node : nodes) {
                const glm::dvec3 h(node.sinH * cosPhi, node.sinH * sinPhi, node.cosH);
                const double vdoth = glm::dot(V, h);
                if (vdoth <= 0) continue;
                const glm::dvec3 l = 2 * vdoth * h - V;
                if (l.z > 0) visit(l, node.weight * GeometrySchlickGGXForIBL(l.z, roughness) * vdoth / node.cosH);
            }
        }
    };
    glm::dvec3 mean(0);
    double total = 0;
    forEachDirection([&](const glm::dvec3& l, double w) { mean += w * l, total += w; });
    const glm::dvec3 centre = glm::normalize(glm::dvec3(mean.x, 0, mean.z));
    const glm::dvec3 across(0, 1, 0), along = glm::cross(across, centre);
    double alongVariance = 0, acrossVariance = 0;
    forEachDirection([&](const glm::dvec3& l, double w) {
        alongVariance += w * std::pow(glm::dot(l, along), 2);
        acrossVariance += w * l.y * l.y;
    });
    alongVariance /= total, acrossVariance /= total;
    const double meanAngle = std::acos(std::clamp(centre.z, -1.0, 1.0));
    const KernelRoughness& kernel = [&]() -> const KernelRoughness& {
        static const KernelRoughness byNdotL(LobeWeighting::NdotL), byG1(LobeWeighting::G1);
        return weighting == LobeWeighting::NdotL ? byNdotL : byG1;
    }();
    LobeFit fit;
    fit.blend = float(thetaR > 1e-6 ? meanAngle / thetaR : 1.0);
    fit.roughness = float(kernel.roughnessFor((alongVariance + acrossVariance) / 2));
    fit.pairRoughness = float(kernel.roughnessFor(acrossVariance));
    fit.pairSpread = float(std::asin(std::sqrt(std::clamp(alongVariance - acrossVariance, 0.0, 1.0))));
    return fit;
}

std::vector<float> lobeTable(uint32_t size, LobeWeighting weighting) {
    std::vector<float> table(size_t(size) * size * 4);
    reference::forEachRow(size, [&](uint32_t y) {
        for (uint32_t x = 0; x < size; ++x) {
            const auto fit = fitLobe((x + 0.5) / size, (y + 0.5) / size, weighting);
            float* texel = &table[(size_t(y) * size + x) * 4];
            texel[0] = fit.blend, texel[1] = fit.roughness, texel[2] = fit.pairRoughness, texel[3] = fit.pairSpread;
        }
    });
    return table;
}

} // namespace iblkit::shading
