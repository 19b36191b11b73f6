#include "quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace iblkit::reference {
namespace {

struct Legendre {
    double value, derivative;
};

// P_n(x) by the three-term recurrence, and P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1).
Legendre legendre(uint32_t n, double x) {
    double previous = 1, current = x;
    for (uint32_t k = 2; k <= n; ++k) {
        const double next = ((2.0 * k - 1) * x * current - (k - 1.0) * previous) / k;
        previous = current;
        current = next;
    }
    if (n == 0) return {1, 0};
    return {current, n * (x * current - previous) / (x * x - 1)};
}

} // namespace

GaussLegendre::GaussLegendre(uint32_t n) : nodes(n), weights(n) {
    for (uint32_t i = 0; i < n; ++i) {
        // Newton from Tricomi's estimate of the i-th root, converging in a few steps in double.
        double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
        for (int step = 0; step < 100; ++step) {
            const double dx = legendre(n, x).value / legendre(n, x).derivative;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        const double derivative = legendre(n, x).derivative;
        nodes[i] = (1 - x) / 2;
        weights[i] = 1 / ((1 - x * x) * derivative * derivative);
    }
}

const GaussLegendre& cachedGaussLegendre(uint32_t n) {
    static const auto rules = [] {
        std::vector<GaussLegendre> built;
        for (uint32_t order = 1; order <= 32; ++order) built.emplace_back(order);
        return built;
    }();
    return rules[std::clamp(n, 1u, 32u) - 1];
}

} // namespace iblkit::reference
