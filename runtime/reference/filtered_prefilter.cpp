#include "filtered_prefilter.hpp"

#include "prefilter_faces.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::reference {
namespace {

// Where a direction falls on the cube changes its texels' solid angle: (2 / size)² |L_major|³
// sr for a unit L, so the lod grows by 1.5 log2 of 1 / |L_major| towards the corners.
template <typename T>
T majorAxisCube(vec3<T> direction) {
    const vec3<T> m = glm::abs(direction);
    const T major = std::max(m.x, std::max(m.y, m.z));
    return major * major * major;
}

// The shader's SourceLod: 0 for a lod below mip 0 or a D that is 0 or not a number.
template <typename T>
T filteredLod(T ndoth, T roughness, uint32_t sampleCount, T texelSolidAngle) {
    const T d = DistributionGGX(ndoth, roughness);
    const T texelsPerSample = T(4) / (T(sampleCount) * d * texelSolidAngle);
    const T lod = T(0.5) * std::log2(texelsPerSample);
    return (d > T(0) && lod > T(0)) ? lod : T(0);
}

} // namespace

MippedEnvironment::MippedEnvironment(const MippedCube& cube) {
    for (uint32_t mip = 0; mip < cube.mips; ++mip) {
        const auto texels = cube.mip(mip);
        levels_.emplace_back(cube.mipSize(mip), std::vector<float>(texels.begin(), texels.end()));
    }
}

glm::dvec3 MippedEnvironment::sampleLevel(glm::dvec3 direction, double lod) const {
    lod = std::clamp(lod, 0.0, double(levels_.size() - 1));
    const auto below = static_cast<size_t>(std::floor(lod));
    const double fraction = lod - double(below);
    const glm::dvec3 fine = levels_[below].sample(direction);
    if (fraction == 0) return fine;
    return glm::mix(fine, levels_[below + 1].sample(direction), fraction);
}

template <typename T>
std::vector<T> referenceFilteredPrefilter(const MippedEnvironment& source, T roughness, uint32_t size, uint32_t sampleCount) {
    const T texelSolidAngle = T(4) / (T(source.size()) * T(source.size()));
    return prefilterFaces<T>(size, [&](vec3<T> normal) {
        const vec3<T> viewDirection = normal;
        T totalWeight = T(0);
        vec3<T> color(0);
        for (uint32_t i = 0; i < sampleCount; ++i) {
            const vec3<T> halfWay = ImportanceSampleGGX(Hammersley<T>(i, sampleCount), normal, roughness);
            const vec3<T> toLight = glm::normalize(T(2) * glm::dot(viewDirection, halfWay) * halfWay - viewDirection);
            const T ndotl = saturate(glm::dot(normal, toLight));
            if (ndotl > T(0)) {
                const T lod = filteredLod(saturate(glm::dot(normal, halfWay)), roughness, sampleCount,
                                          texelSolidAngle * majorAxisCube(toLight));
                color += vec3<T>(source.sampleLevel(glm::dvec3(toLight), double(lod))) * ndotl;
                totalWeight += ndotl;
            }
        }
        return color / totalWeight;
    });
}

template <typename T>
std::vector<T> referenceTablePrefilter(const MippedEnvironment& source, const std::vector<glm::vec4>& table, uint32_t size) {
    return prefilterFaces<T>(size, [&](vec3<T> normal) {
        // ImportanceSampleGGX's frame around the normal.
        vec3<T> up = std::abs(normal.y) < T(0.999) ? vec3<T>(0, 1, 0) : vec3<T>(0, 0, 1);
        const vec3<T> right = glm::normalize(glm::cross(up, normal));
        up = glm::normalize(glm::cross(normal, right));
        T totalWeight = T(0);
        vec3<T> color(0);
        for (const glm::vec4& entry : table) {
            const vec3<T> toLight = T(entry.x) * right + T(entry.y) * up + T(entry.z) * normal;
            const T lod = std::max(T(entry.w) - T(0.5) * std::log2(majorAxisCube(toLight)), T(0));
            color += vec3<T>(source.sampleLevel(glm::dvec3(toLight), double(lod))) * T(entry.z);
            totalWeight += T(entry.z);
        }
        return color / totalWeight;
    });
}

template <typename T>
std::vector<T> referencePyramidPrefilter(const MippedEnvironment& source, const std::vector<PyramidRead>& reads, uint32_t size) {
    return prefilterFaces<T>(size, [&](vec3<T> normal) {
        const T lodShift = -T(0.5) * std::log2(majorAxisCube(normal));
        vec3<T> color(0);
        for (const auto& read : reads)
            color += vec3<T>(source.sampleLevel(glm::dvec3(normal), double(std::max(T(read.lod) + lodShift, T(0))))) *
                     T(read.weight);
        return color;
    });
}

template <typename T>
std::vector<T> referenceRingPrefilter(const MippedEnvironment& source, const PyramidRing& ring, uint32_t ringReads,
                                      uint32_t size) {
    return prefilterFaces<T>(size, [&](vec3<T> normal) {
        vec3<T> up = std::abs(normal.y) < T(0.999) ? vec3<T>(0, 1, 0) : vec3<T>(0, 0, 1);
        const vec3<T> right = glm::normalize(glm::cross(up, normal));
        up = glm::normalize(glm::cross(normal, right));
        const T cosAngle = T(ring.cosAngle), sinAngle = std::sqrt(std::clamp(T(1) - cosAngle * cosAngle, T(0), T(1)));
        vec3<T> sum(0);
        for (uint32_t k = 0; k < ringReads; ++k) {
            const T phi = T(6.28318530718) * T(k) / T(ringReads);
            const vec3<T> toLight = cosAngle * normal + sinAngle * (std::cos(phi) * right + std::sin(phi) * up);
            sum += vec3<T>(source.sampleLevel(glm::dvec3(toLight), double(ring.ringLod)));
        }
        const T centreWeight = T(ring.centreWeight);
        return vec3<T>(source.sampleLevel(glm::dvec3(normal), double(ring.centreLod))) * centreWeight +
               sum * ((T(1) - centreWeight) / T(ringReads));
    });
}

template std::vector<float> referenceFilteredPrefilter<float>(const MippedEnvironment&, float, uint32_t, uint32_t);
template std::vector<double> referenceFilteredPrefilter<double>(const MippedEnvironment&, double, uint32_t, uint32_t);
template std::vector<float> referenceTablePrefilter<float>(const MippedEnvironment&, const std::vector<glm::vec4>&, uint32_t);
template std::vector<double> referenceTablePrefilter<double>(const MippedEnvironment&, const std::vector<glm::vec4>&,
                                                             uint32_t);
template std::vector<float> referencePyramidPrefilter<float>(const MippedEnvironment&, const std::vector<PyramidRead>&,
                                                            uint32_t);
template std::vector<double> referencePyramidPrefilter<double>(const MippedEnvironment&, const std::vector<PyramidRead>&,
                                                              uint32_t);
template std::vector<float> referenceRingPrefilter<float>(const MippedEnvironment&, const PyramidRing&, uint32_t, uint32_t);
template std::vector<double> referenceRingPrefilter<double>(const MippedEnvironment&, const PyramidRing&, uint32_t, uint32_t);

} // namespace iblkit::reference
