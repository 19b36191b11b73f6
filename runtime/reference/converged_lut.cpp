#include "converged_lut.hpp"

#include "parallel_rows.hpp"
#include "quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

// Coordinates: N = z, V = (sin θv, 0, cos θv), H = (sin θ cos φ, sin θ sin φ, cos θ). Then
//   N·L = 2 (V·H)(N·H) - N·V = A cos φ + B,  A = sin θv sin 2θ,  B = cos θv cos 2θ,
// so N·L > 0 on the whole ring for θ < θ1 = π/4 - θv/2 = asin(N·V) / 2, on no part of it for
// θ > θ2 = π/2 - θ1, and on the arc |φ| < φmax, cos φmax = -B/A, in between. The integrand is
// bounded and analytic except where Schlick-GGX, G1(x) = x / (x (1 - k) + k), has its pole
// x = -κ, κ = k / (1 - k): just beyond the arc's N·L = 0 edge, a distance of order κ away. Every
// quadrature below is graded towards that edge (forEachGradedPanel) at the distance of the pole.

namespace iblkit::reference {
namespace {

constexpr double pi = std::numbers::pi;

struct Setting {
    double ndotv, sinV;   // cos θv, sin θv
    double alpha2, k;     // GGX α², Schlick-GGX k
    double kappa;         // -(N·L at G1's pole)
    double theta1;        // the edge of the fully visible cap
    const GaussLegendre& theta;
    const GaussLegendre& phi;
};

// The half-vectors at one polar angle θ.
struct Ring {
    double cosH, sinH;
    double amplitude, offset; // N·L = amplitude · cos φ + offset
};

Ring ringAt(const Setting& s, double cosH, double sinH) {
    return {cosH, sinH, 2 * s.sinV * sinH * cosH, s.ndotv * (cosH - sinH) * (cosH + sinH)};
}

double fresnelComplement(double vdoth) { // (1 - V·H)^5
    const double m = 1 - vdoth, m2 = m * m;
    return m2 * m2 * m;
}

// The estimator's per-sample weight, G(N·L, N·V) V·H / (N·H N·V) times (1 - Fc, Fc), times
// N·H. G(N·V) / N·V is written 1 / (N·V (1 - k) + k), finite at N·V = 0.
glm::dvec2 weightTimesNdotH(const Setting& s, const Ring& ring, double phi) {
    const double cosPhi = std::cos(phi);
    const double vdoth = std::max(0.0, s.sinV * ring.sinH * cosPhi + s.ndotv * ring.cosH);
    const double ndotl = std::max(0.0, ring.amplitude * cosPhi + ring.offset);
    const double visibility = ndotl / (ndotl * (1 - s.k) + s.k) / (s.ndotv * (1 - s.k) + s.k);
    const double fc = fresnelComplement(vdoth);
    return visibility * vdoth * glm::dvec2(1 - fc, fc);
}

// ∫_0^end of the weight over φ, graded towards `end` at `scale`, the distance of G1's pole.
glm::dvec2 arcIntegral(const Setting& s, const Ring& ring, double end, double scale) {
    glm::dvec2 sum(0);
    forEachGradedPanel(end, scale, [&](double near, double far) {
        for (size_t i = 0; i < s.phi.nodes.size(); ++i) {
            const double fromEnd = near + (far - near) * s.phi.nodes[i];
            sum += s.phi.weights[i] * (far - near) * weightTimesNdotH(s, ring, end - fromEnd);
        }
    });
    return sum;
}

// φ in [0, π] on a fully visible ring. N·L is least at φ = π; the pole G1 = ∞ lies at
// cos φ = -1 - (κ + N·L(π)) / A, i.e. φ = π ± i acosh(1 + (κ + N·L(π)) / A).
glm::dvec2 fullRingIntegral(const Setting& s, const Ring& ring) {
    const double x = (s.kappa + std::max(0.0, ring.offset - ring.amplitude)) / ring.amplitude;
    return arcIntegral(s, ring, pi, std::log1p(x + std::sqrt(x * (x + 2))));
}

// φ in [0, φmax]. The pole is at cos φ = cos φmax - κ / A: a distance κ / (A sin φmax) where
// the arc's edge is steep, sqrt(2κ / A) where it is flat (φmax near 0 or π); the sum of the
// two denominators gives the smaller of the two within a factor 2, which is all the grading needs.
glm::dvec2 visibleArcIntegral(const Setting& s, const Ring& ring, double phiMax) {
    const double scale = s.kappa / (ring.amplitude * std::sin(phiMax) + std::sqrt(2 * ring.amplitude * s.kappa));
    return arcIntegral(s, ring, phiMax, scale);
}

// θ in [0, θ1] in the variable η = 1 - ξ of the document's inverse CDF:
//   cos²θ = η / (η + α² (1 - η)),  η(θ) = α² / (tan²θ + α²),  D·N·H dω_h = dη dφ / 2π,
// so the integrand in (η, φ) is the bounded weight alone; η and 1 - η are both carried so that
// neither loses precision. The ring integral is even in θ (analytic in sin²θ ∝ 1 - η) at θ = 0;
// towards η1 = η(θ1) it has the pole's pinch at θ1 + asin(κ)/2 and the map's branch point
// η = 0, η1 away: graded towards η1 at the nearer of the two.
glm::dvec2 fullCapIntegral(const Setting& s) {
    const double tan2 = [](double t) { return std::tan(t) * std::tan(t); }(s.theta1);
    const double eta1 = s.alpha2 / (tan2 + s.alpha2), eta1Complement = tan2 / (tan2 + s.alpha2);
    if (!(eta1Complement > 0)) return glm::dvec2(0);
    const double thetaScale = std::min(std::asin(std::min(s.kappa, 1.0)), s.theta1) / 2;
    const double tanScaled = std::tan(s.theta1 + thetaScale);
    const double scale = eta1 - s.alpha2 / (tanScaled * tanScaled + s.alpha2);
    glm::dvec2 sum(0);
    forEachGradedPanel(eta1Complement, scale, [&](double near, double far) {
        for (size_t i = 0; i < s.theta.nodes.size(); ++i) {
            const double u = near + (far - near) * s.theta.nodes[i];
            const double eta = eta1 + u, etaComplement = eta1Complement - u;
            const double denominator = eta + s.alpha2 * etaComplement;
            const Ring ring = ringAt(s, std::sqrt(eta / denominator), std::sqrt(s.alpha2 * etaComplement / denominator));
            sum += s.theta.weights[i] * (far - near) * fullRingIntegral(s, ring) / ring.cosH;
        }
    });
    return sum / pi; // 2 (for φ in [π, 2π]) / 2π
}

// One ring of [θ1, θ2] with D·N·H dω_h = D N·H sin θ dθ dφ; its distances from θ1 and θ2 come
// exactly from the quadrature, so that the arc, tan²(φmax / 2) = (1 - cos φmax) / (1 + cos φmax)
// = sin 2(θ2 - θ) / sin 2(θ - θ1), keeps full precision at both ends.
glm::dvec2 partialRingIntegral(const Setting& s, double fromTheta1, double toTheta2) {
    const double theta = s.theta1 + fromTheta1;
    const double cosH = std::cos(theta), sinH = std::sin(theta);
    const double phiMax = 2 * std::atan2(std::sqrt(std::sin(2 * toTheta2)), std::sqrt(std::sin(2 * fromTheta1)));
    const double spread = sinH * sinH + s.alpha2 * cosH * cosH;
    const double distribution = s.alpha2 / (pi * spread * spread);
    return 2 * distribution * sinH * visibleArcIntegral(s, ringAt(s, cosH, sinH), phiMax); // 2: φ < 0
}

// θ in [θ1, θ2], each half graded towards its end. Near an end the arc opens or closes like
// sqrt(θ - θ1) (so the ring integral goes as its 1st or 3rd power), smoothed by u = scale · t²
// on the end panel; further in, the ring integral is analytic on the scale of κ (the pole) and
// of θ1 (the points θ = 0 and θ = π/2, θ1 beyond the ends, where the arc's shape degenerates).
glm::dvec2 partialBandIntegral(const Setting& s) {
    const double width = pi / 2 - 2 * s.theta1;
    if (!(width > 0)) return glm::dvec2(0);
    const double kappaScale = std::asin(std::min(s.kappa, 1.0)) / 2;
    const double scale = std::max(s.theta1 > 0 ? std::min(s.theta1, kappaScale) : kappaScale, 1e-15);
    glm::dvec2 sum(0);
    for (const bool fromTheta1Side : {true, false})
        forEachGradedPanel(width / 2, scale, [&](double near, double far) {
            for (size_t i = 0; i < s.theta.nodes.size(); ++i) {
                const double t = s.theta.nodes[i];
                const bool endPanel = near == 0;
                const double fromEnd = endPanel ? far * t * t : near + (far - near) * t;
                const double jacobian = endPanel ? far * 2 * t : far - near;
                const double fromTheta1 = fromTheta1Side ? fromEnd : width - fromEnd;
                sum += s.theta.weights[i] * jacobian * partialRingIntegral(s, fromTheta1, width - fromTheta1);
            }
        });
    return sum;
}

glm::dvec2 mirrorLimit(double ndotv) {
    const double fc = fresnelComplement(ndotv);
    return {1 - fc, fc};
}

glm::dvec2 integrate(double ndotv, double roughness, const GaussLegendre& theta, const GaussLegendre& phi) {
    ndotv = std::clamp(ndotv, 0.0, 1.0);
    roughness = std::clamp(roughness, 0.0, 1.0);
    const double alpha = roughness * roughness, alpha2 = alpha * alpha, k = alpha / 2;
    // As α → 0, G → 1 and V·H / (N·H N·V) → 1 over a lobe at H = N.
    if (alpha2 < std::numeric_limits<double>::min()) return mirrorLimit(ndotv);
    const Setting s{ndotv, std::sqrt((1 - ndotv) * (1 + ndotv)), alpha2, k, k / (1 - k), std::asin(ndotv) / 2, theta, phi};
    return fullCapIntegral(s) + partialBandIntegral(s);
}

} // namespace

glm::dvec2 convergedBrdf(double ndotv, double roughness, const LutQuadrature& quadrature) {
    return integrate(ndotv, roughness, GaussLegendre(quadrature.thetaNodes), GaussLegendre(quadrature.phiNodes));
}

std::vector<double> convergedBrdfLut(uint32_t size, const LutQuadrature& quadrature) {
    const GaussLegendre theta(quadrature.thetaNodes), phi(quadrature.phiNodes);
    std::vector<double> lut(size_t(size) * size * 2);
    forEachRow(size, [&](uint32_t y) {
        for (uint32_t x = 0; x < size; ++x) {
            const glm::dvec2 scaleBias = integrate((x + 0.5) / size, (y + 0.5) / size, theta, phi);
            lut[(size_t(y) * size + x) * 2] = scaleBias.x;
            lut[(size_t(y) * size + x) * 2 + 1] = scaleBias.y;
        }
    });
    return lut;
}

} // namespace iblkit::reference
