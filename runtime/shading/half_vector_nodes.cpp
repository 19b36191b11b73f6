#include "shading/half_vector_nodes.hpp"

#include <cmath>
#include <numbers>

namespace iblkit::shading {

std::vector<HalfVectorNode> halfVectorNodes(double alpha, int count) {
    const double tail = std::log(1e4 / (alpha * alpha));
    std::vector<HalfVectorNode> nodes;
    nodes.reserve(size_t(count));
    for (int i = 0; i < count; ++i) {
        const double s = tail * (i + 0.5) / count, oneMinusU = std::exp(-s);
        const double tan2 = alpha * alpha * (1 - oneMinusU) / oneMinusU;
        const double cosH = 1 / std::sqrt(1 + tan2);
        nodes.push_back({cosH, std::sqrt(tan2) * cosH, oneMinusU * tail / count});
    }
    return nodes;
}

double ggxDistribution(double cosH, double alpha) {
    const double a2 = alpha * alpha, d = cosH * cosH * (a2 - 1) + 1;
    return a2 / (std::numbers::pi * d * d);
}

std::vector<HalfVectorNode> horizonNodes(double alpha, int count) {
    const double from = std::atan(100.0), step = (std::numbers::pi / 2 - from) / count;
    std::vector<HalfVectorNode> nodes;
    nodes.reserve(size_t(count));
    for (int i = 0; i < count; ++i) {
        const double theta = from + (i + 0.5) * step, cosH = std::cos(theta), sinH = std::sin(theta);
        nodes.push_back({cosH, sinH, 2 * std::numbers::pi * ggxDistribution(cosH, alpha) * cosH * sinH * step});
    }
    return nodes;
}

} // namespace iblkit::shading
