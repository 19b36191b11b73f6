#include "bake.hpp"

#include "kernels/specular_method.hpp"

#include "bake_directory.hpp"
#include "bake_kernels.hpp"
#include "bake_error.hpp"
#include "bake_manifest.hpp"
#include "bake_plan.hpp"
#include "environment_input.hpp"
#include "float_image.hpp"
#include "gpu_steps.hpp"
#include "sha256.hpp"
#include "vulkan_context.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <unistd.h>

namespace iblkit::bake {
namespace {

using Clock = std::chrono::steady_clock;

double cubeChainBytes(uint32_t size) { return 6.0 * size * size * 16 * 4 / 3; }

std::string gigabytes(double bytes) { return fmt::format("{:.1f} GB", bytes / 1e9); }

// Refuses sizes whose images would not fit, before any of them is made.
void checkMemory(const vulkan::VulkanContext& context, const BakeSettings& settings, const EnvironmentInput& input,
                 uint32_t size) {
    const double panorama = double(input.panorama.width) * input.panorama.height * 16;
    // The convolution's energy, centroid and geometry pyramids are each a full RGBA32F chain.
    const double pyramids = kernels::isConvolutionMethod(settings.specularMethod) ? 3 * cubeChainBytes(size) : 0;
    const double device = 2 * cubeChainBytes(size) + pyramids + panorama + double(settings.lutSize) * settings.lutSize * 8 +
                          6.0 * settings.irradianceSize * settings.irradianceSize * 16;
    // The host holds each image as floats while it downloads and encodes it.
    const double host = device + 2 * cubeChainBytes(size);
    const double heap = double(context.largestHeapSize());
    const double ram = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    if (device > heap)
        throw BakeError(fmt::format("this bake needs about {} of device memory; the device's largest heap is {} "
                                    "(lower --size or --lut-size)", gigabytes(device), gigabytes(heap)));
    if (host > ram)
        throw BakeError(fmt::format("this bake needs about {} of memory; the machine has {} (lower --size or --lut-size)",
                                    gigabytes(host), gigabytes(ram)));
}

// Exposure that maps the environment's mean luminance to 0.4 before the filmic curve, within
// [kMinPreviewExposure, kMaxPreviewExposure]: a black or near-black environment previews black
// rather than as its rounding noise amplified, and a mean of 0 or less (radiance that cancels
// out) gets exposure 1, never a negative or infinite one.
float previewExposure(const Irradiance& irradiance) {
    const glm::dvec3 mean = irradiance.shRadiance[0] * 0.282094791773878;
    const double luminance = 0.2126 * mean.r + 0.7152 * mean.g + 0.0722 * mean.b;
    if (!(luminance > 0) || !std::isfinite(luminance)) return 1.f;
    return float(std::clamp(0.4 / luminance, kMinPreviewExposure, kMaxPreviewExposure));
}

std::vector<uint8_t> toRgba8(const std::vector<float>& rgba) {
    std::vector<uint8_t> bytes(rgba.size());
    std::transform(rgba.begin(), rgba.end(), bytes.begin(),
                   [](float v) { return uint8_t(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); });
    return bytes;
}

void checkFiniteOutput(const std::string& name, const std::vector<float>& values) {
    const auto bad = std::count_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); });
    if (bad > 0) throw BakeError(fmt::format("internal error: {} has {} NaN/Inf values", name, bad));
}

BakedTexture download(const vulkan::VulkanContext& context, const vulkan::Image& image, const std::string& name,
                      image_io::PixelFormat format) {
    auto values = image.download(context);
    checkFiniteOutput(name, values);
    if (image.desc().format->channels != image_io::channelCount(format))
        throw BakeError("internal error: " + name + " has the wrong channel count");
    return {name, format, image.desc().width, image.desc().layers, image.desc().mips, std::move(values)};
}

} // namespace

BakeSummary bakeEnvironment(const BakeSettings& settings, const std::string& toolVersion, BakeProgress& progress) {
    const auto started = Clock::now();
    validateSettings(settings);
    // A scene that cannot be read fails before any device work.
    const auto scene = settings.scene ? std::optional(scene::readSceneMaterials(*settings.scene)) : std::nullopt;
    BakeDirectory directory(settings.outputDir, settings.environment);

    progress.begin("load");
    const vulkan::VulkanContext context(settings.context);
    BakeKernels kernels(context, settings, neededOutputs(scene));
    const auto input = loadEnvironment(settings.environment, {settings.sanitize, settings.strict});
    const uint32_t size = resolvedSize(settings, input.cubeSize);
    if (!std::has_single_bit(size))
        throw BakeError(fmt::format("the input cube's faces are {}x{}; the bake needs a power of two", size, size));
    const uint32_t mips = resolvedMips(settings, size);
    checkMemory(context, settings, input, size);
    const auto plan = planBake(settings, size, scene);
    progress.end();

    auto source = buildSourceCube(context, input, size, progress);
    std::vector<bool> prefiltered;
    for (const auto& mip : plan.mips) prefiltered.push_back(mip.needed);
    auto specular = prefilterSpecular(context, source, prefiltered, kernels.specular(), progress);
    auto lut = plan.lut ? integrateBrdfLut(context, settings.lutSize, *kernels.lut(), progress) : blankBrdfLut(context);
    auto irradiance =
        computeIrradiance(context, kernels.irradiance(), source, settings.irradianceSize, progress, plan.irradiance);
    const float exposure = previewExposure(irradiance);
    const auto preview = renderPreview(context, kernels.preview(), specular, irradiance.cube, lut, exposure, progress);

    progress.begin("write");
    const auto lutFormat =
        settings.lutFormat == LutFormat::Rg16Float ? image_io::PixelFormat::Rg16Float : image_io::PixelFormat::Rg32Float;
    std::vector<BakedTexture> textures; // what the plan needs: a skipped output is no file
    if (plan.specular) textures.push_back(download(context, specular, "specular", image_io::PixelFormat::Rgba16Float));
    if (plan.lut) textures.push_back(download(context, lut, "brdf_lut", lutFormat));
    if (plan.irradiance) textures.push_back(download(context, irradiance.cube, "irradiance", image_io::PixelFormat::Rgba16Float));
    std::vector<HalfRangeClamp> clamps;
    for (auto& texture : textures)
        if (auto clamp = applyHalfRangePolicy(texture, settings.strict)) clamps.push_back(std::move(*clamp));
    const std::string writer = "iblkit " + toolVersion;
    std::vector<WrittenFile> files;
    for (const auto& texture : textures)
        for (auto& file : writeTexture(directory.staging(), texture, settings, writer)) files.push_back(std::move(file));
    const auto png = directory.staging() / "preview.png";
    image_io::writePng(png, preview.width, preview.height, toRgba8(preview.rgba));
    files.push_back({"preview.png", sha256OfFile(png), size_t(std::filesystem::file_size(png))});

    auto manifest = bakeManifest({toolVersion, context.deviceInfo().name, &input, &settings, size, mips, &irradiance,
                                  &clamps, exposure, &plan});
    manifest["files"] = filesJson(files);
    const std::string manifestText = manifest.dump(2) + "\n";
    files.push_back(writeBytes(directory.staging(), "manifest.json", std::as_bytes(std::span(manifestText))));
    directory.commit();
    progress.end();

    const double wall = std::chrono::duration<double, std::milli>(Clock::now() - started).count();
    return {settings.outputDir, context.deviceInfo().name, progress.steps(), wall, files,
            irradiance.shRadiance, clamps, input.sanitizedTexels, input.negative};
}

} // namespace iblkit::bake
