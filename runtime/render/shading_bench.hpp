#pragma once

#include "render/irradiance_error.hpp"
#include "render/reference_render.hpp"
#include "render/sphere_errors.hpp"

#include "bake_progress.hpp"
#include "shading/shading_recipe.hpp"
#include "context_options.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::render {

// The environments the shading bench measures on unless told otherwise: the built-in sky, the
// small suns in front of, beside and behind the spheres, and blender-data's eight worlds.
std::vector<std::string> defaultShadingEnvironments();

struct ShadingBenchOptions {
    std::vector<std::string> environments = defaultShadingEnvironments();
    std::vector<std::string> recipes;  // names of shading::benchRecipes(); empty: all of them
    std::filesystem::path cache;       // the references, and where blender-data is fetched to
    std::filesystem::path pictures;    // each environment's images go under it, in a folder of its name
    uint32_t cellSize = 32;
    double standardErrorBound = 0.02;
    uint32_t seed = 1;
    vulkan::ContextOptions context;
};

struct RecipeResult {
    std::string recipe;
    std::vector<SphereError> spheres;
    std::vector<shading::EnvironmentLight> lights;
    uint32_t lightLevel = 0;
    double bakeMilliseconds = 0; // the maps' bake in process, device and host
    IrradianceError irradiance;  // the diffuse's source (its map and lights) against the exact sum
};

struct EnvironmentResult {
    std::string name;
    double meanSamples = 0;
    uint32_t maxSamples = 0;
    double maxRelativeStandardError = 0;
    bool converged = false;
    bool referenceCached = false;
    std::vector<RecipeResult> recipes;
};

// For each environment: the Monte Carlo reference of the split sum's own BSDF (--bsdf split-sum),
// kept in the content store under the hash of its kernel's SPIR-V, its source cube and its
// settings; then each recipe's bake and split sum, sphere by sphere against it. Writes the
// reference and the first recipe's error map under options.pictures / NAME.
std::vector<EnvironmentResult> runShadingBench(const ShadingBenchOptions& options, bake::BakeProgress& progress);

} // namespace iblkit::render
