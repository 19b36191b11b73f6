#pragma once

#include "render/heat_map.hpp"
#include "render/reference_render.hpp"
#include "render/render_settings.hpp"
#include "render/sphere_errors.hpp"
#include "render/sphere_grid.hpp"

#include "bake_outputs.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::render {

// `text` into `path`, whole; RenderError naming the path when it cannot be written.
void writeText(const std::filesystem::path& path, const std::string& text);

// The preview's display transform (hlsl/PreviewCS.hlsl's ToneMap): exposure, Narkowicz's ACES
// fit, the sRGB curve; uncovered pixels black.
Rgba8Image toneMapped(const SphereImage& image, float exposure);

// What errors.json says of a render.
struct RenderReport {
    std::string environment;
    ReferenceBsdf bsdf = ReferenceBsdf::Document;
    std::string recipe; // the split sum's shading recipe
    const SphereGrid* grid = nullptr;
    uint32_t cellSize = 0;
    double floor = 0;
    double standardErrorBound = 0;
    float exposure = 1;
    const ReferenceImage* reference = nullptr;         // none for the split sum alone
    const std::vector<SphereError>* spheres = nullptr; // the same
};
nlohmann::json errorsJson(const RenderReport& report);

// splitsum.png/.exr and errors.json into `folder`, and with a reference also reference.png/.exr,
// standard_error.exr and error.png; the files written, with their hashes, for the manifest.
std::vector<bake::WrittenFile> writeRenderFiles(const std::filesystem::path& folder, const RenderReport& report,
                                                const SphereImage& splitSum);

} // namespace iblkit::render
