#include "prefilter_sample_table.hpp"

#include "pbr.hpp"

#include <cmath>

namespace iblkit::reference {

double filteredSourceLod(double ndoth, double roughness, uint32_t samples, uint32_t sourceSize) {
    const double d = DistributionGGX(ndoth, roughness);
    if (!(d > 0) || std::isinf(d)) return kMirrorLod;
    const double texelSolidAngle = 4.0 / (double(sourceSize) * sourceSize);
    return 0.5 * std::log2(4.0 / (samples * d * texelSolidAngle));
}

// PBR.fxh's samples, through its C++ twin in double: about N = +Z the sampling frame is the
// identity, so H and L come out in the normal's frame.
std::vector<glm::vec4> prefilterSampleTable(double roughness, uint32_t samples, uint32_t sourceSize) {
    const glm::dvec3 normal(0, 0, 1);
    std::vector<glm::vec4> table;
    for (uint32_t i = 0; i < samples; ++i) {
        const glm::dvec3 halfWay = ImportanceSampleGGX(Hammersley<double>(i, samples), normal, roughness);
        const glm::dvec3 toLight = 2 * halfWay.z * halfWay - normal; // 2 (V·H) H - V with V = N
        if (!(toLight.z > 0)) continue;
        table.emplace_back(glm::vec3(glm::normalize(toLight)),
                           float(filteredSourceLod(halfWay.z, roughness, samples, sourceSize)));
    }
    return table;
}

} // namespace iblkit::reference
