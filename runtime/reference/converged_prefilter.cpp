#include "converged_prefilter.hpp"

#include "cube_environment.hpp"
#include "parallel_rows.hpp"
#include "pbr.hpp"
#include "prefilter_lobe.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>

namespace iblkit::reference {
namespace {

constexpr double mirrorBelowAlpha = 1e-10;

// What the sum over source texels needs of each, computed once per call.
struct SourceTexel {
    glm::dvec3 centre;   // unit direction
    glm::dvec3 radiance;
    double sinRadius;    // sin of an upper bound on the angle from the centre to any point of the texel
    double cosFar;       // cos of PrefilterLobe::farCentreAngle
};

struct Source {
    uint32_t size;
    double side; // of a texel in face coordinates
    std::vector<SourceTexel> texels;
};

double angleBetween(glm::dvec3 a, glm::dvec3 b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

// The farthest point of a texel (a convex spherical quadrilateral) from its centre is a corner;
// the bound is widened a little so that the horizon test using it is conservative.
double texelRadius(uint32_t face, uint32_t x, uint32_t y, uint32_t size, glm::dvec3 centre) {
    double radius = 0;
    for (const double dx : {-0.5, 0.5})
        for (const double dy : {-0.5, 0.5})
            radius = std::max(radius, angleBetween(centre, glm::normalize(cubeTexelDirection(face, x + dx, y + dy, size))));
    return radius * (1 + 1e-6) + 1e-12;
}

Source prepareSource(std::span<const float> texels, uint32_t size, double alpha, uint32_t supersampling) {
    Source source{size, 2.0 / size, {}};
    source.texels.reserve(size_t(6) * size * size);
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                const glm::dvec3 direction = cubeTexelDirection(face, x, y, size);
                const glm::dvec3 centre = glm::normalize(direction);
                const double radius = texelRadius(face, x, y, size, centre);
                const double angularSize = source.side / glm::length(direction);
                const double farAngle = PrefilterLobe::farCentreAngle(angularSize, alpha, supersampling);
                const size_t at = source.texels.size() * 4;
                source.texels.push_back({centre, glm::dvec3(texels[at], texels[at + 1], texels[at + 2]), std::sin(radius),
                                         std::cos(std::min(std::numbers::pi, farAngle))});
            }
    return source;
}

glm::dvec3 prefilteredAt(const Source& source, const PrefilterLobe& lobe, glm::dvec3 normal) {
    glm::dvec3 weighted(0);
    double total = 0;
    const SourceTexel* texel = source.texels.data();
    for (uint32_t face = 0; face < 6; ++face)
        for (uint32_t y = 0; y < source.size; ++y)
            for (uint32_t x = 0; x < source.size; ++x, ++texel) {
                const double cosAngle = glm::dot(normal, texel->centre);
                if (cosAngle <= -texel->sinRadius) continue; // wholly beyond the horizon
                const double a0 = -1 + x * source.side, b0 = -1 + y * source.side;
                const bool far = cosAngle >= texel->sinRadius && cosAngle <= texel->cosFar;
                const double w = far ? lobe.overFarSquare(face, a0, b0, source.side)
                                     : lobe.overSquare(face, a0, b0, source.side);
                weighted += w * texel->radiance;
                total += w;
            }
    return weighted / total;
}

// The texel a texture unit's face selection and nearest filtering would read at `direction`.
glm::dvec3 texelContaining(std::span<const float> texels, uint32_t size, glm::dvec3 direction) {
    uint32_t bestFace = 0;
    for (uint32_t face = 1; face < 6; ++face)
        if (glm::dot(direction, facePlane(face).origin) > glm::dot(direction, facePlane(bestFace).origin)) bestFace = face;
    const FacePlane plane = facePlane(bestFace);
    const double depth = glm::dot(direction, plane.origin);
    const auto texelIndex = [&](double coordinate) {
        return std::clamp(uint32_t(std::floor((coordinate / depth + 1) / 2 * size)), 0u, size - 1);
    };
    const size_t at = ((size_t(bestFace) * size + texelIndex(glm::dot(direction, plane.v))) * size +
                       texelIndex(glm::dot(direction, plane.u))) * 4;
    return {texels[at], texels[at + 1], texels[at + 2]};
}

// Unbiased and portable, unlike std::uniform_int_distribution whose algorithm is the library's.
uint64_t uniformBelow(std::mt19937_64& engine, uint64_t bound) {
    const uint64_t max = std::numeric_limits<uint64_t>::max();
    const uint64_t limit = max - max % bound; // a multiple of bound: [0, limit) maps evenly
    for (;;)
        if (const uint64_t value = engine(); value < limit) return value % bound;
}

void validate(std::span<const float> sourceTexels, uint32_t sourceSize, uint32_t outputSize,
              std::span<const PrefilterTexel> texels) {
    if (sourceSize == 0 || sourceTexels.size() != size_t(6) * sourceSize * sourceSize * 4)
        throw std::invalid_argument("convergedPrefilter: source texels do not match the source size");
    for (const PrefilterTexel& texel : texels)
        if (texel.face >= 6 || texel.x >= outputSize || texel.y >= outputSize)
            throw std::invalid_argument("convergedPrefilter: an output texel lies outside the output cube");
}

} // namespace

std::vector<PrefilterTexel> seededPrefilterTexels(uint32_t size, uint32_t count, uint64_t seed) {
    const uint64_t total = uint64_t(6) * size * size;
    std::set<uint64_t> chosen;
    if (count >= total)
        for (uint64_t index = 0; index < total; ++index) chosen.insert(index);
    else {
        // Floyd's sampling: `count` distinct indices, each subset equally likely.
        std::mt19937_64 engine(seed);
        for (uint64_t j = total - count; j < total; ++j)
            if (!chosen.insert(uniformBelow(engine, j + 1)).second) chosen.insert(j);
    }
    std::vector<PrefilterTexel> texels;
    for (const uint64_t index : chosen)
        texels.push_back({uint32_t(index / (uint64_t(size) * size)), uint32_t(index % size), uint32_t(index / size % size)});
    return texels;
}

std::vector<glm::dvec3> convergedPrefilter(std::span<const float> sourceTexels, uint32_t sourceSize, double roughness,
                                          uint32_t outputSize, std::span<const PrefilterTexel> texels,
                                          const ConvergedPrefilterOptions& options) {
    validate(sourceTexels, sourceSize, outputSize, texels);
    const double alpha = std::clamp(roughness, 0.0, 1.0) * std::clamp(roughness, 0.0, 1.0);
    const auto normalOf = [&](const PrefilterTexel& t) { return PrefilterFaceDirection<double>(t.face, t.x, t.y, outputSize); };
    std::vector<glm::dvec3> result(texels.size());
    if (alpha < mirrorBelowAlpha) {
        for (size_t i = 0; i < texels.size(); ++i) result[i] = texelContaining(sourceTexels, sourceSize, normalOf(texels[i]));
        return result;
    }
    const Source source = prepareSource(sourceTexels, sourceSize, alpha, options.supersampling);
    forEachRow(uint32_t(texels.size()), [&](uint32_t i) {
        const glm::dvec3 normal = normalOf(texels[i]);
        result[i] = prefilteredAt(source, PrefilterLobe(normal, alpha, options.supersampling, options.g1Weighting), normal);
    });
    return result;
}

} // namespace iblkit::reference
