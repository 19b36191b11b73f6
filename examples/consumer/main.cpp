// Runs the shader the build compiled (argv[1]: its run file), then bakes the built-in sky in
// memory and checks its LUT where the split sum reduces to Schlick's terms. Exit 0 when both hold.
#include <iblkit/iblkit.hpp>

#include <cmath>
#include <iostream>

namespace {

bool runTheShader(const char* runFile) {
    iblkit::RunRequest request;
    request.runFile = runFile;
    const auto result = iblkit::executeRunFile(request);
    std::cout << result.report;
    return result.passed;
}

// At N·V near 1 and roughness near 0, Schlick's F is F0 and G is 1: the LUT's scale is 1 and its
// bias 0, within the distance of the texel's centre from that corner ((1 - N·V)^5 ~ 1e-9 here,
// G's 1 - G1(0.98) ~ 1e-4 at roughness 1/64), and the 16-bit rounding of nothing: the LUT in
// memory is 32-bit floats.
bool checkTheLut(const iblkit::BakedMaps& maps) {
    const auto& lut = maps.brdfLut;
    const size_t texel = size_t(lut.width - 1) * lut.channels; // row 0: the lowest roughness
    const float scale = lut.values[texel], bias = lut.values[texel + 1];
    std::cout << "LUT at N.V " << (lut.width - 0.5) / lut.width << ", roughness " << 0.5 / lut.height << ": scale "
              << scale << ", bias " << bias << "\n";
    return std::abs(scale - 1) < 1e-3 && std::abs(bias) < 1e-3;
}

bool checkTheSpecular(const iblkit::BakedMaps& maps) {
    const auto& mirror = maps.specular.at(0);
    for (const auto& face : mirror.faces)
        for (const float value : face)
            if (!std::isfinite(value) || value < 0) return false;
    std::cout << maps.specular.size() << " specular mips from " << mirror.size << "², baked on " << maps.device << "\n";
    return true;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: consumer RUN.json\n";
        return 2;
    }
    try {
        std::cout << "iblkit " << iblkit::version() << "\n";
        const bool ran = runTheShader(argv[1]);
        iblkit::BakeRequest request; // no environment: the built-in sky
        request.size = 32;
        request.lutSize = 64;
        request.irradianceSize = 8;
        const auto maps = iblkit::bakeToMemory(request);
        const bool baked = checkTheLut(maps) && checkTheSpecular(maps);
        return ran && baked ? 0 : 1;
    } catch (const iblkit::Error& error) {
        std::cerr << "consumer: " << iblkit::errorKindName(error.kind()) << ": " << error.what() << "\n";
        return 1;
    }
}
