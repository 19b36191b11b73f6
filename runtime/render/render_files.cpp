#include "render/render_files.hpp"

#include "render/render_error.hpp"
#include "render/render_settings.hpp"

#include "float_image.hpp"
#include "sha256.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

namespace iblkit::render {
namespace {

float filmic(float value) {
    value = std::max(value, 0.f);
    const float curved = std::clamp(value * (2.51f * value + 0.03f) / (value * (2.43f * value + 0.59f) + 0.14f), 0.f, 1.f);
    return curved <= 0.0031308f ? 12.92f * curved : 1.055f * std::pow(curved, 1.f / 2.4f) - 0.055f;
}

image_io::FloatImage floatImage(const SphereImage& image) { return {image.width, image.height, 4, image.rgba}; }

void writePng(const std::filesystem::path& path, const Rgba8Image& image) {
    image_io::writePng(path, image.width, image.height, image.rgba);
}

nlohmann::json sphereJson(const SphereError& sphere) {
    return {{"row", sphere.row},
            {"column", sphere.column},
            {"material", sphere.material},
            {"roughness", sphere.roughness},
            {"metalness", sphere.metalness},
            {"transmittance", sphere.transmittance},
            {"pixels", sphere.pixels},
            {"mean_relative_error", sphere.meanRelativeError},
            {"max_relative_error", sphere.maxRelativeError},
            {"total_relative_error", sphere.totalRelativeError},
            {"max_relative_standard_error", sphere.maxRelativeStandardError},
            {"mean_relative_standard_error", sphere.meanRelativeStandardError}};
}

nlohmann::json gridJson(const SphereGrid& grid, uint32_t cellSize) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : grid.rows)
        rows.push_back({{"name", row.name}, {"albedo", {row.albedo.r, row.albedo.g, row.albedo.b}}, {"metalness", row.metalness},
                        {"transmittance", row.transmittance}, {"eta", row.eta}});
    return {{"roughness", grid.roughness}, {"rows", rows}, {"cell_size", cellSize}};
}

} // namespace

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream stream(path, std::ios::binary);
    stream << text;
    stream.close();
    if (!stream) throw RenderError("cannot write " + path.string());
}

Rgba8Image toneMapped(const SphereImage& image, float exposure) {
    Rgba8Image result{image.width, image.height, std::vector<uint8_t>(image.rgba.size(), 255)};
    for (size_t pixel = 0; pixel < size_t(image.width) * image.height; ++pixel)
        for (size_t c = 0; c < 3; ++c) {
            const float value = image.covered(pixel) ? filmic(exposure * image.rgba[4 * pixel + c]) : 0.f;
            result.rgba[4 * pixel + c] = uint8_t(std::lround(255.f * value));
        }
    return result;
}

nlohmann::json referenceJson(const RenderReport& report) {
    const auto& reference = *report.reference;
    return {{"samples_per_pixel", {{"min", reference.minSamples}, {"mean", reference.meanSamples}, {"max", reference.maxSamples}}},
            {"standard_error_bound", report.standardErrorBound},
            {"max_relative_standard_error", reference.maxRelativeStandardError},
            {"p99_relative_standard_error", reference.p99RelativeStandardError},
            {"converged", reference.converged},
            {"device_ms", reference.deviceMilliseconds}};
}

nlohmann::json errorsJson(const RenderReport& report) {
    nlohmann::json json = {{"generator", "iblkit"},
                           {"environment", report.environment},
                           {"recipe", report.recipe},
                           {"grid", gridJson(*report.grid, report.cellSize)},
                           {"exposure", report.exposure}};
    if (!report.reference) return json;
    nlohmann::json spheres = nlohmann::json::array();
    for (const auto& sphere : *report.spheres) spheres.push_back(sphereJson(sphere));
    json["reference_bsdf"] = nameOf(report.bsdf);
    json["relative_to"] = {{"floor", report.floor}, {"floor_share_of_mean_radiance", kRelativeFloor}};
    json["reference"] = referenceJson(report);
    json["spheres"] = spheres;
    return json;
}

namespace {

void writeReferenceFiles(const std::filesystem::path& folder, const RenderReport& report, const SphereImage& splitSum) {
    const auto& reference = *report.reference;
    writePng(folder / "reference.png", toneMapped(reference.mean, report.exposure));
    std::vector<bool> covered(size_t(splitSum.width) * splitSum.height);
    for (size_t pixel = 0; pixel < covered.size(); ++pixel) covered[pixel] = reference.mean.covered(pixel);
    writePng(folder / "error.png",
             heatMap(relativeErrors(reference.mean, splitSum, report.floor), covered, splitSum.width, splitSum.height));
    image_io::writeExr(folder / "reference.exr", floatImage(reference.mean));
    image_io::writeExr(folder / "standard_error.exr", {splitSum.width, splitSum.height, 4, reference.standardError});
}

} // namespace

std::vector<bake::WrittenFile> writeRenderFiles(const std::filesystem::path& folder, const RenderReport& report,
                                                const SphereImage& splitSum) {
    if (report.reference) writeReferenceFiles(folder, report, splitSum);
    const auto names = report.reference ? std::vector<std::string>{"reference.png", "reference.exr", "standard_error.exr",
                                                                   "splitsum.png", "splitsum.exr", "error.png", "errors.json"}
                                        : std::vector<std::string>{"splitsum.png", "splitsum.exr", "errors.json"};
    writePng(folder / "splitsum.png", toneMapped(splitSum, report.exposure));
    image_io::writeExr(folder / "splitsum.exr", floatImage(splitSum));
    writeText(folder / "errors.json", errorsJson(report).dump(2) + "\n");
    std::vector<bake::WrittenFile> files;
    for (const auto& name : names)
        files.push_back({name, cache::sha256OfFile(folder / name), size_t(std::filesystem::file_size(folder / name))});
    return files;
}

} // namespace iblkit::render
