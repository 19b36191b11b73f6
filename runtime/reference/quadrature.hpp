#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace iblkit::reference {

// The n-point Gauss–Legendre rule on [0, 1]: exact for polynomials of degree below 2n, and for
// a function analytic inside the Bernstein ellipse of parameter rho its error falls as rho^-2n.
struct GaussLegendre {
    explicit GaussLegendre(uint32_t n);
    std::vector<double> nodes, weights; // weights sum to 1
};

// The rules for n = 1..32, built once and shared by every thread; n is clamped to that range.
const GaussLegendre& cachedGaussLegendre(uint32_t n);

// Visits panels [d0, d1], [d1, d2], ... covering [0, length]: d0 = 0, d1 = scale, each next one
// four times the last, the last one cut at length; one panel when scale >= length / 4 (or is
// not finite). With a (near-)singularity at distance >= scale outside 0, every panel sees it at
// least a third of its length away (Bernstein parameter >= 3), so a fixed number of nodes per
// panel converges at one rate whatever that distance, with log4(length / scale) panels.
template <typename Visit>
void forEachGradedPanel(double length, double scale, const Visit& visit) {
    if (!(scale < length / 4)) {
        visit(0.0, length);
        return;
    }
    // A scale of 0 (or a denormal) would never reach the length: the first panel is at least a
    // double's resolution of it.
    const double first = std::max(scale, length * 1e-16);
    for (double near = 0, far = first; near < length; near = far, far *= 4) visit(near, std::min(far, length));
}

} // namespace iblkit::reference
