#pragma once

#include <vector>

namespace iblkit::shading {

// Nodes of the GGX half-vector distribution about N: u = tan²θ / (α² + tan²θ) is uniform for
// D(h) cos θ_h dω_h / (2π dφ), and s = -ln(1 - u) spaces them so that GGX's long tail (whose
// sin² θ moment falls off only as 1 / (1 - u)) is resolved down to 1 - u = α² / 10⁴, where
// tan θ_h = 100 (θ_h within 0.6 degrees of the horizon). Each node carries its share of
// D cos θ_h dω_h over the hemisphere of h: the shares sum to 1 - α² / 10⁴.
struct HalfVectorNode {
    double cosH, sinH, weight;
};

std::vector<HalfVectorNode> halfVectorNodes(double alpha, int count);

// GGX's D at cos θ_h for α (D's argument is squared: a half vector pointing inside counts as its
// mirror image, as the document's D has it).
double ggxDistribution(double cosH, double alpha);

// The rest of the hemisphere, from tan θ_h = 100 to the horizon, by the midpoint rule in θ_h: for
// integrands that grow as 1 / cos θ_h there, which the nodes above would miss (a refracted lobe's
// is one; at α = 0.8, 0.4 % of its integral lies past tan θ_h = 100).
std::vector<HalfVectorNode> horizonNodes(double alpha, int count);

} // namespace iblkit::shading
