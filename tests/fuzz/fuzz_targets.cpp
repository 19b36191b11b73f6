#include "fuzz_targets.hpp"

#include "compile_error.hpp"
#include "compiler.hpp"
#include "dds.hpp"
#include "float_image.hpp"
#include "image_error.hpp"
#include "ktx2.hpp"
#include "lowering.hpp"
#include "lowering_error.hpp"
#include "run_error.hpp"
#include "run_file.hpp"
#include "shader_manifest.hpp"

#include <string>

namespace iblkit::fuzz {
namespace {

std::string text(std::span<const std::byte> bytes) { return {reinterpret_cast<const char*>(bytes.data()), bytes.size()}; }

// A decoder of bytes in memory, fed any bytes: an ImageError is its one allowed end.
template <typename Decode>
void decodeImage(std::span<const std::byte> bytes, Decode decode) {
    try {
        decode(bytes);
    } catch (const image_io::ImageError&) {}
}

void radianceHdr(std::span<const std::byte> bytes) {
    decodeImage(bytes, [](auto in) { image_io::decodeRadianceHdr(in, "fuzz.hdr"); });
}
void exr(std::span<const std::byte> bytes) {
    decodeImage(bytes, [](auto in) { image_io::decodeExr(in, "fuzz.exr"); });
}
void ktx2(std::span<const std::byte> bytes) {
    decodeImage(bytes, [](auto in) { image_io::decodeKtx2(in, "fuzz.ktx2"); });
}
void dds(std::span<const std::byte> bytes) {
    decodeImage(bytes, [](auto in) { image_io::decodeDds(in, "fuzz.dds"); });
}

void runFile(std::span<const std::byte> bytes) {
    try {
        run::parseRunFile(text(bytes), "fuzz.run.json");
    } catch (const run::RunError&) {}
}

void shaderManifest(std::span<const std::byte> bytes) {
    try {
        compiler::parseShaderManifest(text(bytes), "fuzz/shaders.json");
    } catch (const compiler::CompileError&) {}
}

// The whole compile entry as the command-line tool runs it (glslang first in a bounded child,
// since glslang itself crashes on some sources): preprocessing, glslang, SPIRV-Tools,
// reflection; no file is read.
void hlsl(std::span<const std::byte> bytes) {
    compiler::CompileOptions options;
    options.source = "fuzz.hlsl";
    options.sourceText = text(bytes);
    options.boundPreprocessing = true;
    try {
        compiler::compileShader(options);
    } catch (const compiler::CompileError&) {}
}

// The HLSL 2021 lowering alone, in process (the hlsl target runs it too, but forks per input).
void hlslLowering(std::span<const std::byte> bytes) {
    try {
        lowering::lowerHlsl(text(bytes), "fuzz.hlsl", lowering::HlslVersion::Hlsl2021);
    } catch (const lowering::LoweringError&) {}
}

} // namespace

const std::vector<Target>& targets() {
    static const std::vector<Target> all{{"radiance_hdr", radianceHdr}, {"exr", exr},
                                         {"ktx2", ktx2},                 {"dds", dds},
                                         {"run_file", runFile},          {"shader_manifest", shaderManifest},
                                         {"hlsl", hlsl},                 {"hlsl_lowering", hlslLowering}};
    return all;
}

} // namespace iblkit::fuzz
