#include "profiles/engine_profile.hpp"

#include <stdexcept>
#include <string>

namespace iblkit::profiles {
namespace {

std::vector<EngineProfile> makeProfiles() {
    EngineProfile kit{.name = "iblkit",
                      .engine = "iblkit's IblShadeOpaque (hlsl/Common/ImageBasedLighting.fxh)",
                      .recipe = "kit",
                      .lodFormula = "the recipe's logarithmic mapping (manifest shading.mips)",
                      .lookup = "the lobe table's fitted direction and lookup pair",
                      .shForm = "radiance coefficients (manifest irradiance.sh)",
                      .lightsForm = "lights.gltf (KHR_lights_punctual) with each light's angular radius",
                      .loader = "docs/bake.md"};
    // three.js r187: WebGLPrograms.js, envmap_common_pars_fragment.glsl.js, envmap_physical_pars_fragment.glsl.js,
    // WebGLMaterials.js (the x-negating _m for a cube texture), PMREMGenerator.js (a chain down to 8²).
    EngineProfile three{.name = "threejs",
                        .engine = "three.js r187 (0.187.0), CompressedCubeTexture with isPMREMTexture",
                        .recipe = "quadratic-lights",
                        .frame = CubeFrame::MirroredX,
                        .lastMipSize = 8,
                        .diffuse = DiffuseSource::LastSpecularMip,
                        .readsKitLut = false,
                        .lodFormula = "lod = ENVMAP_MAX_LOD r (2 - r), ENVMAP_MAX_LOD = mips - 1",
                        .lookup = "normalize(mix(R, N, r^4)), x negated",
                        .shForm = "LightProbe: radiance coefficients in the same basis and order (not used "
                                  "beside the map: three's diffuse is pi times the last mip)",
                        .lightsForm = "DirectionalLight per light of lights.gltf, intensity its irradiance",
                        .loader = "docs/engines.md#threejs"};
    // Babylon.js 9: CubeTexture.CreateFromPrefilteredData and DDSTools (a DX10 float cube, face by
    // face with its mips), pbrBlockReflection / pbrIBLFunctions (lod = log2(size alphaG) 0.8,
    // alphaG = r² + 0.0005), materialHelper.functions (REFLECTIONMAP_OPPOSITEZ: z negated in a
    // right-handed scene, the file's cube left-handed in either).
    EngineProfile babylon{.name = "babylon",
                          .engine = "Babylon.js 9 (@babylonjs/core 9.35.0), CubeTexture.CreateFromPrefilteredData",
                          .recipe = "babylon-lights",
                          .frame = CubeFrame::MirroredZ,
                          .file = SpecularFile::Dds,
                          .lastMipSize = 1,
                          .diffuse = DiffuseSource::EngineSh,
                          .readsKitLut = false,
                          .lodFormula = "lod = 0.8 log2(size (r^2 + 0.0005)), the full chain to 1x1",
                          .lookup = "reflect(-V, N); z negated in a right-handed scene",
                          .shForm = "its own sphericalPolynomial, projected from specular.dds's mip 0 as it loads",
                          .lightsForm = "DirectionalLight per light of lights.gltf, direction the light travels",
                          .loader = "docs/engines.md#babylonjs"};
    // Filament 1.53 (web): Engine.createTextureFromKtx1 (cmgen's KTX1), surface_light_indirect
    // (lod = (levels - 1) r (2 - r), lerp(R, N, α²)), IndirectLight.irradianceSh (cmgen --sh-shader).
    EngineProfile filament{.name = "filament",
                           .engine = "Filament 1.53 (npm filament 1.53.4), Engine.createTextureFromKtx1 and IndirectLight",
                           .recipe = "quadratic-lights",
                           .frame = CubeFrame::Kit,
                           .file = SpecularFile::Ktx1,
                           .shCoefficients = ShForm::IrradianceShader,
                           .lastMipSize = 8,
                           .diffuse = DiffuseSource::IrradianceMap,
                           .readsKitLut = false,
                           .lodFormula = "lod = (levels - 1) r (2 - r)",
                           .lookup = "lerp(R, N, alpha^2)",
                           .shForm = "IndirectLight irradianceSh(3, ...): radiance coefficients times A_l / pi and the basis constants",
                           .lightsForm = "a SUN light per light of lights.gltf, its angular radius in degrees",
                           .loader = "docs/engines.md#filament"};
    // glTF-Sample-Renderer 1.1 (npm @khronosgroup/gltf-viewer 1.1.0): ibl.glsl (lod = roughness
    // (u_MipCount - 1), reflect(-v, n), the LUT at (N·V, roughness)), ibl_sampler.js (its own chain
    // stops lowestMipLevel = 4 levels short of 1², at 16²; its Lambertian cube holds E/π).
    EngineProfile gltf{.name = "gltf",
                       .engine = "glTF Sample Viewer (glTF-Sample-Renderer 1.1, npm @khronosgroup/gltf-viewer 1.1.0), its IBL shader",
                       .recipe = "linear-lights",
                       .frame = CubeFrame::Kit,
                       .file = SpecularFile::Ktx2,
                       .lastMipSize = 16,
                       .diffuse = DiffuseSource::IrradianceMap,
                       .readsKitLut = true,
                       .lodFormula = "lod = roughness (u_MipCount - 1), u_MipCount = mips (its own chain ends at 16x16)",
                       .lookup = "u_EnvRotation reflect(-V, N), u_EnvRotation the identity (environmentRotation 0)",
                       .shForm = "none: its diffuse is the Lambertian cube, the kit's irradiance.ktx2 (E/pi)",
                       .lightsForm = "KHR_lights_punctual directional lights: lights.gltf as it is",
                       .loader = "docs/engines.md#gltf-sample-viewer"};
    return {kit, three, babylon, filament, gltf};
}

} // namespace

const std::vector<EngineProfile>& engineProfiles() {
    static const auto profiles = makeProfiles();
    return profiles;
}

const EngineProfile& defaultProfile() { return engineProfiles().front(); }

const EngineProfile& profileNamed(std::string_view name) {
    std::string names;
    for (const auto& profile : engineProfiles()) {
        if (profile.name == name) return profile;
        names += (names.empty() ? "" : ", ") + std::string(profile.name);
    }
    throw std::invalid_argument("no profile named '" + std::string(name) + "' (there are: " + names + ")");
}

const EngineProfile& profileMadeFor(std::string_view recipe) {
    for (const auto& profile : engineProfiles())
        if (profile.recipe == recipe) return profile;
    return defaultProfile();
}

} // namespace iblkit::profiles
