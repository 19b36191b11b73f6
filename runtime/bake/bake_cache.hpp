#pragma once

#include "bake_outputs.hpp"
#include "bake_plan.hpp"
#include "bake_settings.hpp"
#include "environment_input.hpp"
#include "gpu_steps.hpp"
#include "kernels/kernel_table.hpp"
#include "context_options.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit::bake {

// The cache key of each output: the SHA-256 of everything it depends on — the tool's version and
// the program's own bytes (so any rebuild starts afresh), the device, the HLSL of its kernels with
// every header and their defines, the settings it reads and, but for the LUT, the environment's
// bytes. The LUT's key holds no environment, so one LUT serves every environment baked with its
// settings.
struct BakeKeys {
    std::string specular, lut, irradiance, lights, lobeTable, preview;
};
BakeKeys bakeKeys(const ResolvedSettings& settings, const EnvironmentInput& input, const BakePlan& plan,
                  const vulkan::DeviceInfo& device, const std::string& toolVersion,
                  const kernels::ShaderFiles& files = kernels::embeddedShaderFiles());

// The digest of the named kernels' sources and defines and of every header (.fxh) in `files`.
std::string kernelSourcesDigest(const std::vector<std::string>& kernelNames, const kernels::ShaderFiles& files);

// Cache payloads: the device's values of an output (before any 16-bit rounding), and what goes
// with them; the preview's is its PNG file. A payload that does not parse is a miss.
// A payload of floats in two parts, its text and the floats' bytes (a view of the texture's own
// values), so that tens of megabytes go to the cache without a copy.
struct FloatPayload {
    std::string text;
    std::string_view floats;
    std::array<std::string_view, 2> parts() const { return {text, floats}; }
};
FloatPayload texturePayload(const BakedTexture& texture);
std::optional<BakedTexture> textureFromPayload(std::string_view payload);
FloatPayload irradiancePayload(const IrradianceSh& sh, const BakedTexture& cube);
std::optional<std::pair<IrradianceSh, BakedTexture>> irradianceFromPayload(std::string_view payload);
std::string lightsPayload(const std::vector<shading::EnvironmentLight>& lights);
std::optional<std::vector<shading::EnvironmentLight>> lightsFromPayload(std::string_view payload);

} // namespace iblkit::bake
