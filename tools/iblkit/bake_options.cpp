#include "bake_options.hpp"

#include "bake_settings.hpp"
#include "kernels/lut_methods.hpp"
#include "kernels/specular_method.hpp"
#include "profiles/engine_profile.hpp"
#include "shading/shading_recipe.hpp"

#include <fmt/core.h>

namespace iblkit::cli {

namespace {

// "table 1 to 65535, filtered 1 to ...": each method's range, as resolveSettings checks it.
template <typename Low, typename High>
std::string rangesOf(const std::vector<std::string>& methods, Low low, High high) {
    std::string ranges;
    for (const auto& method : methods)
        if (high(method) > 0) ranges += fmt::format("{}{} {} to {}", ranges.empty() ? "" : ", ", method, low(method), high(method));
    return ranges;
}

} // namespace

void addBakeSettingOptions(CLI::App& command, BakeRequest& s, std::string& lutFormat) {
    command.add_option("--size", s.size, fmt::format("Cube face size, a power of two up to {} (default 256)", bake::kMaxCubeSize));
    command.add_option("--mips", s.mips, "Specular mips, 1 to the full chain (log2 of the size, plus 1; default: down to 8x8)");
    command.add_option("--method", s.method,
                        "Prefilter method: convolution (default; an exact sum over the source's texels as a tree), "
                        "table (filtered importance sampling from a host sample table), filtered (the same, per "
                        "sample on the GPU), pyramid (a few reads of the source's mips along the normal, fitted to "
                        "the lobe), mipchain (the source's own mips where the lobe is narrow, the pyramid's ring "
                        "where it is wide: the cheapest) or document (the documents' importance sampling)");
    std::string recipes;
    for (const auto& recipe : shading::benchRecipes()) recipes += (recipes.empty() ? "" : ", ") + recipe.name;
    command.add_option("--recipe", s.recipe,
                       fmt::format("Shading recipe the maps are made for (docs/shading.md): which bright sources become "
                                   "lights, the prefilter's lobe, each mip's roughness; one of {} (default: kit for the "
                                   "convolution, document for every other method)", recipes));
    std::string profiles;
    for (const auto& profile : profiles::engineProfiles()) profiles += (profiles.empty() ? "" : ", ") + std::string(profile.name);
    command.add_option("--profile", s.profile,
                       fmt::format("The engine whose conventions the files follow (docs/engines.md): its recipe, cube "
                                   "frame and chain; one of {} (default: iblkit)", profiles));
    command.add_option("--samples", s.samples,
                        fmt::format("Prefilter samples per texel (for table, mip 1's, doubling per mip; for pyramid, reads "
                                    "per texel; mipchain takes none), or for the convolution its budget of terms per texel: "
                                    "{} (default 1024, 128 for convolution, 1 for pyramid and mipchain)",
                                    rangesOf(kernels::specularMethods(), [](const auto&) { return 1; }, kernels::maxSamplesOf)));
    command.add_option("--lut-size", s.lutSize, fmt::format("BRDF LUT size, 1 to {} (default 512)", bake::kMaxLutSize));
    command.add_option("--lut-method", s.lutMethod,
                        "BRDF LUT method: quadrature-grid (default; the quadrature on a grid of nodes, interpolated), "
                        "quadrature (a deterministic quadrature at every texel, exact in azimuth), fit (a polynomial "
                        "fitted to the converged LUT) or document (the documents' importance sampling)");
    command.add_option("--lut-samples", s.lutSamples,
                        fmt::format("BRDF LUT samples per texel, for the quadrature its Gauss-Legendre nodes per panel, "
                                    "for the quadrature grid its nodes per side, for the fit its degree: {} (default {} "
                                    "for document, {} for quadrature, {} for quadrature-grid, {} for fit)",
                                    rangesOf(kernels::lutMethods(), kernels::minLutSamplesOf, kernels::maxLutSamplesOf),
                                    bake::kDocumentSamples, kernels::kDefaultQuadratureNodes, kernels::kDefaultLutGrid,
                                    bake::kDefaultLutFitDegree));
    command.add_option("--lut-format", lutFormat, "rg16f (default) or rg32f")
        ->check(CLI::IsMember({"rg16f", "rg32f"}));
    command.add_option("--irradiance-size", s.irradianceSize,
                       fmt::format("Irradiance cube face size, 1 to {} (default 32)", bake::kMaxIrradianceSize));
}

void addBakeLineOptions(CLI::App& command, BakeLineArguments& line) {
    auto& s = line.request;
    command.add_option("ENV", line.environment,
                       "Equirectangular .hdr/.exr, a folder of six faces, or a .ktx2/.dds cube (default: built-in sky)");
    addBakeSettingOptions(command, s, line.lutFormat);
    command.add_option("--scene", s.scene,
                       "A glTF scene (.gltf or .glb): bake only what its materials need (iblkit plan SCENE shows what)");
    command.add_flag("--dds", s.dds, "Also write .dds files");
    command.add_flag("--exr", s.exr, "Also write every face and mip as EXR under exr/");
    command.add_flag("--sanitize", s.sanitize, "Replace NaN/Inf input texels by 0 instead of refusing them");
    command.add_flag("--strict", s.strict,
                     "Refuse negative input texels, values beyond 65504 in 16-bit outputs and a scene's material "
                     "factors outside [0, 1] instead of clamping them (to 0, to 65504 and into [0, 1], each reported)");
}

BakeRequest BakeLineArguments::resolved() const {
    auto out = request;
    if (!environment.empty()) out.environment = environment;
    out.lutFormat = lutFormatNamed(lutFormat);
    return out;
}

LutFormat lutFormatNamed(const std::string& name) { return name == "rg32f" ? LutFormat::Rg32Float : LutFormat::Rg16Float; }

} // namespace iblkit::cli
