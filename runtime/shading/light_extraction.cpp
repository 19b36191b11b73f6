#include "shading/light_extraction.hpp"

#include "reference/cube_geometry.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace iblkit::shading {
namespace {

using reference::CubeFaceDirection;
using reference::CubeTexelSolidAngle;

double luminanceOf(const float* rgba) { return 0.2126 * rgba[0] + 0.7152 * rgba[1] + 0.0722 * rgba[2]; }

// The texel a direction falls in.
size_t texelOf(glm::dvec3 d, uint32_t size) {
    glm::dvec2 uv;
    const uint32_t face = reference::CubeFaceOf(d, uv);
    const auto at = [&](double v) { return std::min(uint32_t(std::floor(v * size)), size - 1); };
    return (size_t(face) * size + at(uv.y)) * size + at(uv.x);
}

// The eight texels around one, across face edges where they lie on another face (found through
// the direction of where the neighbour's centre would be on this face's plane).
std::array<size_t, 8> neighboursOf(size_t texel, uint32_t size) {
    const auto face = uint32_t(texel / (size_t(size) * size));
    const auto row = int(texel / size % size), column = int(texel % size);
    std::array<size_t, 8> result{};
    size_t count = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (!dx && !dy) continue;
            const int x = column + dx, y = row + dy, n = int(size);
            if (x >= 0 && x < n && y >= 0 && y < n) {
                result[count++] = (size_t(face) * size + y) * size + x;
                continue;
            }
            const glm::dvec2 uv((x + 0.5) / size, (y + 0.5) / size);
            result[count++] = texelOf(CubeFaceDirection<double>(face, uv), size);
        }
    return result;
}

struct Region {
    std::vector<size_t> texels;
    double light = 0, solidAngle = 0; // luminance times solid angle, and solid angle
};

// Each texel's solid angle, the same on every face: one face's, not six copies (at 1024², 48 MiB).
struct CubeSolidAngles {
    std::vector<double> face;
    double operator[](size_t texel) const { return face[texel % face.size()]; }
};

std::vector<Region> brightRegions(const std::vector<bool>& bright, const std::vector<double>& luminance,
                                  const CubeSolidAngles& solidAngle, uint32_t size) {
    std::vector<bool> seen(bright.size(), false);
    std::vector<Region> regions;
    for (size_t start = 0; start < bright.size(); ++start) {
        if (!bright[start] || seen[start]) continue;
        Region region;
        std::vector<size_t> stack{start};
        seen[start] = true;
        while (!stack.empty()) {
            const size_t texel = stack.back();
            stack.pop_back();
            region.texels.push_back(texel);
            region.light += luminance[texel] * solidAngle[texel];
            region.solidAngle += solidAngle[texel];
            for (const size_t next : neighboursOf(texel, size))
                if (bright[next] && !seen[next]) seen[next] = true, stack.push_back(next);
        }
        regions.push_back(std::move(region));
    }
    return regions;
}

double diskRadius(double solidAngle) { return std::acos(std::clamp(1 - solidAngle / (2 * std::numbers::pi), -1.0, 1.0)); }

// Fills `hole`'s texels of `residual` from outside it, a ring at a time.
void fillFromSurroundings(std::vector<float>& residual, const Region& hole, uint32_t size) {
    std::vector<bool> known(residual.size() / 4, true);
    for (const size_t texel : hole.texels) known[texel] = false;
    std::vector<size_t> unknown = hole.texels;
    while (!unknown.empty()) {
        std::vector<size_t> ring, rest;
        std::vector<glm::dvec3> values;
        for (const size_t texel : unknown) {
            glm::dvec3 sum(0);
            int count = 0;
            for (const size_t next : neighboursOf(texel, size))
                if (known[next]) sum += glm::dvec3(residual[4 * next], residual[4 * next + 1], residual[4 * next + 2]), ++count;
            if (count) ring.push_back(texel), values.push_back(sum / double(count));
            else rest.push_back(texel);
        }
        if (ring.empty()) break; // a region covering the whole sphere: nothing to fill from
        for (size_t i = 0; i < ring.size(); ++i) {
            float* rgb = &residual[4 * ring[i]];
            for (int c = 0; c < 3; ++c) rgb[c] = std::min(rgb[c], float(values[i][c]));
            known[ring[i]] = true;
        }
        unknown = std::move(rest);
    }
}

} // namespace

Extraction extractLights(std::span<const float> faces, uint32_t size, const ExtractionSettings& settings) {
    const size_t texels = size_t(6) * size * size, perFace = size_t(size) * size;
    CubeSolidAngles solidAngle{std::vector<double>(perFace)}; // computed once, not six times
    for (size_t texel = 0; texel < perFace; ++texel)
        solidAngle.face[texel] = CubeTexelSolidAngle<double>(uint32_t(texel % size), uint32_t(texel / size), size);
    std::vector<double> luminance(texels);
    double total = 0;
    for (size_t texel = 0; texel < texels; ++texel) {
        luminance[texel] = std::max(luminanceOf(&faces[4 * texel]), 0.0);
        total += luminance[texel] * solidAngle[texel];
    }
    Extraction result{{}, std::vector<float>(faces.begin(), faces.end())};
    if (!(total > 0) || !std::isfinite(total)) return result;
    const double mean = total / (4 * std::numbers::pi);
    std::vector<bool> bright(texels);
    for (size_t texel = 0; texel < texels; ++texel) bright[texel] = luminance[texel] > settings.threshold * mean;
    auto regions = brightRegions(bright, luminance, solidAngle, size);
    std::erase_if(regions, [&](const Region& region) {
        return region.light < settings.minShare * total || diskRadius(region.solidAngle) > settings.maxRadius;
    });
    std::sort(regions.begin(), regions.end(), [](const Region& a, const Region& b) { return a.light > b.light; });
    if (regions.size() > settings.maxLights) regions.resize(settings.maxLights);
    for (const auto& region : regions) {
        fillFromSurroundings(result.residual, region, size);
        EnvironmentLight light;
        glm::dvec3 power(0), centre(0);
        for (const size_t texel : region.texels) {
            const auto x = uint32_t(texel % size), y = uint32_t(texel / size % size), face = uint32_t(texel / (size_t(size) * size));
            glm::dvec3 removed(0);
            for (int c = 0; c < 3; ++c) removed[c] = double(faces[4 * texel + c]) - double(result.residual[4 * texel + c]);
            power += removed * solidAngle[texel];
            const glm::dvec3 d = CubeFaceDirection<double>(face, glm::dvec2((x + 0.5) / size, (y + 0.5) / size));
            centre += (0.2126 * removed.r + 0.7152 * removed.g + 0.0722 * removed.b) * solidAngle[texel] * d;
        }
        light.direction = glm::normalize(centre);
        light.solidAngle = region.solidAngle;
        light.angularRadius = diskRadius(region.solidAngle);
        light.radiance = power / region.solidAngle;
        light.share = (0.2126 * power.r + 0.7152 * power.g + 0.0722 * power.b) / total;
        result.lights.push_back(light);
    }
    return result;
}

} // namespace iblkit::shading
