#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace iblkit::profiles {

// How a file's cube relates to the kit's: the texel an engine samples at direction g holds the
// kit's radiance at g, or at (-g.x, g.y, g.z) for an engine that negates x before every lookup
// (three.js does for a cube that is not a render target), or at (g.x, g.y, -g.z) for an engine
// whose cubes are left-handed (Babylon.js, in either handedness of its scene).
enum class CubeFrame { Kit, MirroredX, MirroredZ };

// Where the engine's diffuse light comes from.
enum class DiffuseSource {
    IrradianceMap,   // the kit's irradiance cube (E/π) or its SH
    LastSpecularMip, // π × the roughest mip (three.js): no separate diffuse file
    EngineSh,        // SH the engine projects from the specular cube's mip 0 as it loads it (Babylon.js)
};


// How the engine takes the diffuse SH: the kit's radiance coefficients, or coefficients of
// E(n)/π over the plain polynomials 1, y, z, x, xy, yz, 3z² - 1, xz, x² - y² (the radiance's times
// A_l/π and the basis constant: cmgen's --sh-shader, Filament's IndirectLight).
enum class ShForm { Radiance, IrradianceShader };

// The specular cube's file the engine loads.
enum class SpecularFile { Ktx2, Dds, Ktx1 };

// One engine's conventions for a prefiltered cube: everything a profile changes in a bake is here,
// and nowhere else is an engine's name tested.
struct EngineProfile {
    std::string_view name;      // --profile's value
    std::string_view engine;    // the engine and version whose source the conventions were read from
    std::string_view recipe;    // the shading recipe the maps are made for (runtime/shading/shading_recipe.hpp)
    CubeFrame frame = CubeFrame::Kit;
    SpecularFile file = SpecularFile::Ktx2;
    ShForm shCoefficients = ShForm::Radiance;
    uint32_t lastMipSize = 8;   // the chain ends at this face size (its roughest level at roughness 1)
    DiffuseSource diffuse = DiffuseSource::IrradianceMap;
    bool readsKitLut = true;    // false: the engine has its own DFG table and takes none
    std::string_view lodFormula; // the engine's roughness → lod, as its shader writes it
    std::string_view lookup;     // the engine's lookup direction, as its shader writes it
    std::string_view shForm;     // how the engine takes the SH, if at all
    std::string_view lightsForm; // how the engine takes the lights the bake took out
    std::string_view loader;     // where its loader is documented
};

// Every profile; the first is the kit's own, the default.
const std::vector<EngineProfile>& engineProfiles();
const EngineProfile& defaultProfile();
// Throws std::invalid_argument listing the names.
const EngineProfile& profileNamed(std::string_view name);
// The first profile whose maps are made for the recipe named, else the kit's: its chain is the one
// the kit's own render of that recipe reads, as the engine would.
const EngineProfile& profileMadeFor(std::string_view recipe);

} // namespace iblkit::profiles
