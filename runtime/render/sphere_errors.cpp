#include "render/sphere_errors.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::render {
namespace {

SphereError sphereOfCell(const SphereGrid& grid, uint32_t row, uint32_t column) {
    SphereError sphere;
    sphere.row = row;
    sphere.column = column;
    sphere.material = grid.rows[row].name;
    sphere.roughness = grid.roughness[column];
    sphere.metalness = grid.rows[row].metalness;
    sphere.transmittance = grid.rows[row].transmittance;
    return sphere;
}

std::span<const float> rgbAt(const std::vector<float>& rgba, size_t pixel) { return std::span(rgba).subspan(4 * pixel, 3); }

} // namespace

std::vector<double> relativeErrors(const SphereImage& reference, const SphereImage& splitSum, double floor) {
    std::vector<double> errors(size_t(reference.width) * reference.height, 0.0);
    for (size_t pixel = 0; pixel < errors.size(); ++pixel) {
        if (!reference.covered(pixel)) continue;
        const double expected = luminance(rgbAt(reference.rgba, pixel));
        errors[pixel] = (luminance(rgbAt(splitSum.rgba, pixel)) - expected) / relativeTo(expected, floor);
    }
    return errors;
}

std::vector<SphereError> sphereErrors(const SphereGrid& grid, const ReferenceImage& reference, const SphereImage& splitSum,
                                      uint32_t cellSize, double floor) {
    const auto& image = reference.mean;
    const auto errors = relativeErrors(image, splitSum, floor);
    std::vector<SphereError> spheres;
    for (uint32_t row = 0; row < grid.rowCount(); ++row)
        for (uint32_t column = 0; column < grid.columns(); ++column) {
            auto sphere = sphereOfCell(grid, row, column);
            double sumSplit = 0, sumReference = 0, sumError = 0, sumNoise = 0;
            for (uint32_t y = row * cellSize; y < (row + 1) * cellSize; ++y)
                for (uint32_t x = column * cellSize; x < (column + 1) * cellSize; ++x) {
                    const size_t pixel = size_t(y) * image.width + x;
                    if (!image.covered(pixel)) continue;
                    const double value = luminance(rgbAt(image.rgba, pixel));
                    ++sphere.pixels;
                    sumError += std::abs(errors[pixel]);
                    sphere.maxRelativeError = std::max(sphere.maxRelativeError, std::abs(errors[pixel]));
                    sumSplit += luminance(rgbAt(splitSum.rgba, pixel));
                    sumReference += value;
                    const double noise = luminance(rgbAt(reference.standardError, pixel)) / relativeTo(value, floor);
                    sphere.maxRelativeStandardError = std::max(sphere.maxRelativeStandardError, noise);
                    sumNoise += noise;
                }
            if (sphere.pixels) {
                sphere.meanRelativeError = sumError / double(sphere.pixels);
                sphere.meanRelativeStandardError = sumNoise / double(sphere.pixels);
                sphere.totalRelativeError = (sumSplit - sumReference) / relativeTo(sumReference, floor * double(sphere.pixels));
            }
            spheres.push_back(sphere);
        }
    return spheres;
}

} // namespace iblkit::render
