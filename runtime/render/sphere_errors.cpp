#include "render/sphere_errors.hpp"

#include "render/render_settings.hpp"

#include <algorithm>
#include <cmath>

namespace iblkit::render {
namespace {

float fraction(uint32_t index, uint32_t count) { return count > 1 ? float(index) / float(count - 1) : 0.f; }

SphereError sphereOfCell(uint32_t row, uint32_t column) {
    SphereError sphere;
    sphere.row = row;
    sphere.column = column;
    sphere.roughness = std::max(fraction(column, kColumns), kMinRoughness);
    const bool glass = row >= kMetalRows;
    sphere.metalness = glass ? 0.f : fraction(row, kMetalRows);
    sphere.transmittance = glass ? 1.f : 0.f;
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

std::vector<SphereError> sphereErrors(const ReferenceImage& reference, const SphereImage& splitSum, uint32_t cellSize,
                                      double floor) {
    const auto& image = reference.mean;
    const auto errors = relativeErrors(image, splitSum, floor);
    std::vector<SphereError> spheres;
    for (uint32_t row = 0; row < kRows; ++row)
        for (uint32_t column = 0; column < kColumns; ++column) {
            auto sphere = sphereOfCell(row, column);
            double sumSplit = 0, sumReference = 0, sumError = 0;
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
                    sphere.maxRelativeStandardError =
                        std::max(sphere.maxRelativeStandardError,
                                 luminance(rgbAt(reference.standardError, pixel)) / relativeTo(value, floor));
                }
            if (sphere.pixels) {
                sphere.meanRelativeError = sumError / double(sphere.pixels);
                sphere.totalRelativeError = (sumSplit - sumReference) / relativeTo(sumReference, floor * double(sphere.pixels));
            }
            spheres.push_back(sphere);
        }
    return spheres;
}

} // namespace iblkit::render
