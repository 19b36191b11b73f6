#include "prefilter_lobe.hpp"

#include "cube_environment.hpp"
#include "quadrature.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace iblkit::reference {
namespace {

// A square of angular size h whose nearest point is d from N sees the lobe vary on the scale
// λ = sqrt(d² + 4α²) (2α: the lobe's half-width in L). With q = h / λ, the n x n Gauss–Legendre
// rule's relative error, measured against deeply refined sums, is about 0.5 q² for n = 1 (the
// centre times the solid angle), 0.3 q⁴ for n = 2, 0.01 q⁶ for n = 3, and for higher n at most
// 5e-11 (n = 4, q < 0.125), 9e-11 (5, 0.35), 2e-10 (6, 0.5), 3e-11 (8, 1). Each square takes the
// cheapest order whose limit covers its q, which keeps it under ~3e-9 (2 x 2) and ~1e-9 (the
// rest); beyond the last limit it splits in four. High orders make the refinement near N cheap:
// a few dozen squares per octave of distance from N. The centre rule would need q < 5e-5 for
// 1e-9, which no practical source reaches.
struct Rule {
    double qLimit;
    uint32_t order;
};
constexpr Rule rules[] = {{0.01, 2}, {0.06, 3}, {0.15, 4}, {0.3, 5}, {0.5, 6}, {0.8, 8}};
// Splitting stops at squares 2^-40 of a texel, far below the smallest lobe converged (α = 1e-10).
constexpr uint32_t maxDepth = 40;
// A square's angular radius is at most side / sqrt(2) / sqrt(1 + a² + b²) for small squares.
constexpr double radiusPerSize = 0.75;
// The clipped rule's order per supersampling step: the horizon's squares are far from N, so
// the integrand is smooth on them once cut; 4 points per direction is ample.
constexpr uint32_t clippedOrder = 4;

struct Point {
    double a, b;
};

double distance2(double a, double b) { return 1 + a * a + b * b; }

} // namespace

FacePlane facePlane(uint32_t face) {
    const glm::dvec3 origin = cubeTexelDirection(face, 0.5, 0.5, 2); // a = b = 0
    return {origin, cubeTexelDirection(face, 1.5, 0.5, 2) - origin, cubeTexelDirection(face, 0.5, 1.5, 2) - origin};
}

PrefilterLobe::PrefilterLobe(glm::dvec3 normal, double alpha, uint32_t supersampling, bool g1Weighting)
    : normal_(glm::normalize(normal)), alpha2_(alpha * alpha), inverseAlpha2_(1 / (alpha * alpha)),
      g1K_(g1Weighting ? alpha / 2 : 0), supersampling_(std::max(1u, supersampling)) {
    for (uint32_t face = 0; face < 6; ++face) {
        faces_[face] = facePlane(face);
        normalOnFace_[face] = {glm::dot(normal_, faces_[face].origin), glm::dot(normal_, faces_[face].u),
                               glm::dot(normal_, faces_[face].v)};
    }
}

double PrefilterLobe::farCentreAngle(double size, double alpha, uint32_t supersampling) {
    const double lambda = std::max(1u, supersampling) * size / rules[0].qLimit;
    return radiusPerSize * size + std::sqrt(std::max(0.0, lambda * lambda - 4 * alpha * alpha));
}

double PrefilterLobe::aboveHorizon(uint32_t face, double a, double b) const {
    const glm::dvec3 n = normalOnFace_[face];
    return n.x + n.y * a + n.z * b;
}

// 1 - N·L as |L - N|² / 2 keeps its relative precision where L is near N and the lobe narrow.
double PrefilterLobe::atNode(uint32_t face, double a, double b) const {
    const FacePlane& plane = faces_[face];
    const double r2 = distance2(a, b), r = std::sqrt(r2);
    const glm::dvec3 l = (plane.origin + a * plane.u + b * plane.v) / r;
    const double ndotl = glm::dot(normal_, l);
    if (ndotl <= 0) return 0;
    const glm::dvec3 offset = l - normal_;
    return weight(ndotl, glm::dot(offset, offset) / 2) / (r2 * r);
}

double PrefilterLobe::tensorRule(uint32_t face, double a0, double b0, double side, uint32_t order) const {
    const GaussLegendre& rule = cachedGaussLegendre(order);
    double sum = 0;
    for (size_t j = 0; j < rule.nodes.size(); ++j)
        for (size_t i = 0; i < rule.nodes.size(); ++i)
            sum += rule.weights[i] * rule.weights[j] * atNode(face, a0 + side * rule.nodes[i], b0 + side * rule.nodes[j]);
    return sum * side * side;
}

// Far from N, 1 - N·L is not small and is taken directly; the nodes are 2-point Gauss–Legendre's.
double PrefilterLobe::overFarSquare(uint32_t face, double a0, double b0, double side) const {
    const double offsets[2] = {(1 - 1 / std::sqrt(3.0)) / 2, (1 + 1 / std::sqrt(3.0)) / 2};
    double sum = 0;
    for (const double v : offsets)
        for (const double u : offsets) {
            const double a = a0 + side * u, b = b0 + side * v;
            const double r2 = distance2(a, b), inverseR = 1 / std::sqrt(r2);
            const double ndotl = std::max(0.0, aboveHorizon(face, a, b) * inverseR);
            sum += weight(ndotl, 1 - ndotl) * inverseR / r2;
        }
    return sum * side * side / 4;
}

// The square cut by the line N·P = 0 is a convex polygon; each triangle of its fan is mapped
// from the unit square by (s, t) -> A + s (B - A) + s t (C - B), Jacobian s |(B - A) x (C - B)|
// (Duffy), which keeps tensor Gauss–Legendre exponentially convergent on a triangle.
double PrefilterLobe::clippedRule(uint32_t face, double a0, double b0, double side, uint32_t order) const {
    const Point corners[4] = {{a0, b0}, {a0 + side, b0}, {a0 + side, b0 + side}, {a0, b0 + side}};
    Point polygon[5];
    size_t count = 0;
    for (size_t i = 0; i < 4; ++i) {
        const Point p = corners[i], q = corners[(i + 1) % 4];
        const double hp = aboveHorizon(face, p.a, p.b), hq = aboveHorizon(face, q.a, q.b);
        if (hp > 0) polygon[count++] = p;
        if ((hp > 0) != (hq > 0)) {
            const double t = hp / (hp - hq);
            polygon[count++] = {p.a + t * (q.a - p.a), p.b + t * (q.b - p.b)};
        }
    }
    const GaussLegendre& rule = cachedGaussLegendre(order);
    double sum = 0;
    for (size_t k = 1; k + 1 < count; ++k) {
        const Point a = polygon[0], b = polygon[k], c = polygon[k + 1];
        const double area2 = std::abs((b.a - a.a) * (c.b - b.b) - (b.b - a.b) * (c.a - b.a));
        for (size_t i = 0; i < rule.nodes.size(); ++i)
            for (size_t j = 0; j < rule.nodes.size(); ++j) {
                const double s = rule.nodes[i], t = rule.nodes[j];
                const double pa = a.a + s * (b.a - a.a) + s * t * (c.a - b.a);
                const double pb = a.b + s * (b.b - a.b) + s * t * (c.b - b.b);
                sum += rule.weights[i] * rule.weights[j] * s * area2 * atNode(face, pa, pb);
            }
    }
    return sum;
}

double PrefilterLobe::overSquare(uint32_t face, double a0, double b0, double side) const {
    return overSquareAtDepth(face, a0, b0, side, 0);
}

double PrefilterLobe::overSquareAtDepth(uint32_t face, double a0, double b0, double side, uint32_t depth) const {
    // N·P is linear on the face, so the square is wholly beyond the horizon if all corners are.
    const double corners[4] = {aboveHorizon(face, a0, b0), aboveHorizon(face, a0 + side, b0),
                               aboveHorizon(face, a0, b0 + side), aboveHorizon(face, a0 + side, b0 + side)};
    const auto above = std::count_if(std::begin(corners), std::end(corners), [](double h) { return h > 0; });
    if (above == 0) return 0;

    const double ac = a0 + side / 2, bc = b0 + side / 2, r = std::sqrt(distance2(ac, bc));
    const FacePlane& plane = faces_[face];
    const glm::dvec3 centre = (plane.origin + ac * plane.u + bc * plane.v) / r;
    const double angle = std::atan2(glm::length(glm::cross(normal_, centre)), glm::dot(normal_, centre));
    const double size = side / r;
    const double nearest = std::max(0.0, angle - radiusPerSize * size);
    const double q = supersampling_ * size / std::sqrt(nearest * nearest + 4 * alpha2_);
    if (q > std::end(rules)[-1].qLimit && depth < maxDepth) {
        const double half = side / 2;
        return overSquareAtDepth(face, a0, b0, half, depth + 1) + overSquareAtDepth(face, a0 + half, b0, half, depth + 1) +
               overSquareAtDepth(face, a0, b0 + half, half, depth + 1) +
               overSquareAtDepth(face, a0 + half, b0 + half, half, depth + 1);
    }
    if (above < 4) return clippedRule(face, a0, b0, side, clippedOrder * supersampling_);
    const Rule* rule = std::find_if(std::begin(rules), std::end(rules), [q](Rule r) { return q <= r.qLimit; });
    return tensorRule(face, a0, b0, side, rule == std::end(rules) ? std::end(rules)[-1].order : rule->order);
}

} // namespace iblkit::reference
