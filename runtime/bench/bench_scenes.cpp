#include "bench_scenes.hpp"

#include "bench_error.hpp"

#include <fstream>

namespace iblkit::bench {
namespace {

std::string gltf(const std::string& materials, const std::string& extensionsUsed = "") {
    return R"({"asset": {"version": "2.0"},)" + extensionsUsed + R"( "materials": [)" + materials + "]}\n";
}

std::string material(const std::string& name, double metallic, double roughness) {
    return R"({"name": ")" + name + R"(", "pbrMetallicRoughness": {"metallicFactor": )" + std::to_string(metallic) +
           R"(, "roughnessFactor": )" + std::to_string(roughness) + "}}";
}

} // namespace

const std::vector<BenchScene>& benchScenes() {
    static const std::vector<BenchScene> scenes{
        // Chrome and polished gold: the sharpest mip alone, which is the source's own, and no irradiance.
        {"all-mirror metal", gltf(material("chrome", 1, 0) + ", " + material("polished gold", 1, 0))},
        // Plaster and rubber: the rough mips alone.
        {"rough dielectric", gltf(material("plaster", 0, 0.7) + ", " + material("rubber", 0, 1))},
        // Brushed steel, lacquered wood and fabric: most of the chain.
        {"mixed", gltf(material("brushed steel", 1, 0.3) + ", " + material("lacquered wood", 0, 0.45) + ", " +
                       material("fabric", 0, 0.9))},
        // A scene of emissive and baked-lighting materials: nothing but the preview.
        {"unlit", gltf(R"({"name": "sign", "extensions": {"KHR_materials_unlit": {}}}, )"
                       R"({"name": "lightmapped floor", "extensions": {"KHR_materials_unlit": {}}})",
                       R"( "extensionsUsed": ["KHR_materials_unlit"],)")},
    };
    return scenes;
}

std::filesystem::path writeBenchScene(const BenchScene& scene, const std::filesystem::path& folder) {
    std::string file = scene.name + ".gltf";
    for (char& c : file)
        if (c == ' ') c = '-';
    const auto path = folder / file;
    std::ofstream out(path);
    out << scene.gltf;
    if (!out) throw BenchError(path.string() + ": cannot write a bench scene");
    return path;
}

} // namespace iblkit::bench
