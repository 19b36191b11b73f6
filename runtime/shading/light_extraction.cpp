#include "shading/light_extraction.hpp"

#include "reference/cube_geometry.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

namespace iblkit::shading {
namespace {

using reference::CubeFaceDirection;

double luminanceOf(const float* rgba) { return 0.2126 * rgba[0] + 0.7152 * rgba[1] + 0.0722 * rgba[2]; }

glm::vec3 rgbOf(const std::vector<float>& rgba, size_t texel) { return {rgba[4 * texel], rgba[4 * texel + 1], rgba[4 * texel + 2]}; }

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

// Each texel's solid angle, the same on every face: one face's, not six copies (at 1024², 48 MiB),
// from the area element at the face's (size + 1)² texel corners, each evaluated once (CubeTexelSolidAngle
// evaluates the four of every texel: at 1024², 4 million arctangents instead of 1).
struct CubeSolidAngles {
    std::vector<double> face;
    double operator[](size_t texel) const { return face[texel % face.size()]; }
};

CubeSolidAngles cubeSolidAngles(uint32_t size) {
    std::vector<double> corner(size + 1);
    const double inverseSize = 1.0 / size; // as CubeTexelSolidAngle has it
    for (uint32_t i = 0; i <= size; ++i) corner[i] = 2.0 * i * inverseSize - 1;
    std::vector<double> area(size_t(size + 1) * (size + 1));
    for (uint32_t y = 0; y <= size; ++y)
        for (uint32_t x = 0; x <= size; ++x) area[size_t(y) * (size + 1) + x] = reference::CubeAreaElement(corner[x], corner[y]);
    CubeSolidAngles solidAngle{std::vector<double>(size_t(size) * size)};
    const auto at = [&](uint32_t x, uint32_t y) { return area[size_t(y) * (size + 1) + x]; };
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x)
            solidAngle.face[size_t(y) * size + x] = at(x, y) - at(x, y + 1) - at(x + 1, y) + at(x + 1, y + 1);
    return solidAngle;
}

std::vector<Region> brightRegions(const std::vector<bool>& bright, std::span<const float> faces, const CubeSolidAngles& solidAngle,
                                  uint32_t size) {
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
            region.light += std::max(luminanceOf(&faces[4 * texel]), 0.0) * solidAngle[texel];
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

Extraction extractLights(std::vector<float> faces, uint32_t size, const ExtractionSettings& settings) {
    const size_t texels = size_t(6) * size * size;
    const auto solidAngle = cubeSolidAngles(size);
    double total = 0;
    for (size_t texel = 0; texel < texels; ++texel) total += std::max(luminanceOf(&faces[4 * texel]), 0.0) * solidAngle[texel];
    if (!(total > 0) || !std::isfinite(total)) return {{}, std::move(faces), {}};
    const double mean = total / (4 * std::numbers::pi);
    std::vector<bool> bright(texels);
    for (size_t texel = 0; texel < texels; ++texel) bright[texel] = luminanceOf(&faces[4 * texel]) > settings.threshold * mean;
    auto regions = brightRegions(bright, faces, solidAngle, size);
    std::erase_if(regions, [&](const Region& region) {
        return region.light < settings.minShare * total || diskRadius(region.solidAngle) > settings.maxRadius;
    });
    std::sort(regions.begin(), regions.end(), [](const Region& a, const Region& b) { return a.light > b.light; });
    if (regions.size() > settings.maxLights) regions.resize(settings.maxLights);
    Extraction result{{}, std::move(faces), {}};
    auto& residual = result.residual;
    for (const auto& region : regions) {
        std::vector<glm::vec3> before;
        before.reserve(region.texels.size());
        for (const size_t texel : region.texels) before.push_back(rgbOf(residual, texel));
        fillFromSurroundings(residual, region, size);
        EnvironmentLight light;
        glm::dvec3 power(0), centre(0);
        for (size_t i = 0; i < region.texels.size(); ++i) {
            const size_t texel = region.texels[i];
            const auto x = uint32_t(texel % size), y = uint32_t(texel / size % size), face = uint32_t(texel / (size_t(size) * size));
            const glm::vec3 after = rgbOf(residual, texel);
            const glm::dvec3 removed = glm::dvec3(before[i]) - glm::dvec3(after);
            power += removed * solidAngle[texel];
            const glm::dvec3 d = CubeFaceDirection<double>(face, glm::dvec2((x + 0.5) / size, (y + 0.5) / size));
            centre += (0.2126 * removed.r + 0.7152 * removed.g + 0.0722 * removed.b) * solidAngle[texel] * d;
            if (before[i] != after) result.taken.push_back({texel, before[i] - after});
        }
        light.direction = glm::normalize(centre);
        light.solidAngle = region.solidAngle;
        light.angularRadius = diskRadius(region.solidAngle);
        light.radiance = power / region.solidAngle;
        light.share = (0.2126 * power.r + 0.7152 * power.g + 0.0722 * power.b) / total;
        result.lights.push_back(light);
    }
    std::sort(result.taken.begin(), result.taken.end(), [](const TakenTexel& a, const TakenTexel& b) { return a.texel < b.texel; });
    return result;
}

} // namespace iblkit::shading
