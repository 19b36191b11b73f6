// Compiles a compute shader to every form, runs it as its run file says, bakes the built-in sky
// in memory and reads a texel. Run from the kit's source folder: the paths are relative to it.
#include <iblkit/iblkit.hpp>

#include <cstdio>
#include <iostream>
#include <string>

int main() {
    try {
        // 1. PBR.fxh's functions behind one compute shader, in every form.
        iblkit::CompileRequest compile;
        compile.source = "hlsl/PbrProbeCS.hlsl";
        compile.includeDirs = {"hlsl/document"};
        compile.defines = {{"SAMPLE_COUNT", "1024"}};
        const auto shader = iblkit::compileShader(compile);
        std::printf("SPIR-V: %zu words\n", shader.spirv.size());
        for (const auto& [form, source] : shader.forms)
            std::printf("%s: %zu characters\n", std::string(iblkit::shaderFormName(form)).c_str(), source.size());
        for (const auto& [form, reason] : shader.refusedForms) std::printf("refused: %s\n", reason.c_str());

        // 2. The same shader run on the device as its run file says, each result checked against
        // the C++ twin of PBR.fxh. A failed expectation is a result, not an exception.
        iblkit::RunRequest run;
        run.runFile = "docs/examples/pbr_functions.run.json";
        const auto result = iblkit::executeRunFile(run);
        std::cout << result.report;
        if (!result.passed) return 3;

        // 3. The built-in sky baked in memory, small for a quick first run.
        iblkit::BakeRequest bake;
        bake.size = 64;
        bake.lutSize = 128;
        const auto maps = iblkit::bakeToMemory(bake);
        const auto& mip = maps.specular[1];
        const uint32_t row = mip.size / 2, column = mip.size / 2;
        const float* texel = &mip.faces[2][(row * mip.size + column) * 4]; // face +Y: the sky overhead
        std::printf("specular mip 1 at roughness %.3f, +Y centre: %g %g %g\n", maps.specularRoughness[1], texel[0],
                    texel[1], texel[2]);
        std::printf("%zu light(s) taken out, on %s\n", maps.lights.size(), maps.device.c_str());
        return 0;
    } catch (const iblkit::Error& error) {
        std::fprintf(stderr, "%s (%s)\n", error.what(), std::string(iblkit::errorKindName(error.kind())).c_str());
        return 1;
    }
}
