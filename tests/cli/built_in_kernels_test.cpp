// The program's built-in kernels (runtime/kernels/built_in_kernels.hpp): a default bake compiles
// nothing, a kernel the store lacks is compiled as before, and a damaged entry is compiled and left
// where it is.
#include "bake_cli_fixture.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;

nlohmann::json compiledKernels(const ProcessResult& result) {
    EXPECT_EQ(result.exitCode, 0) << result.err;
    return result.exitCode == 0 ? nlohmann::json::parse(result.out)["compiled_kernels"] : nlohmann::json();
}

class BuiltInKernels : public BakeCli {
protected:
    std::string panorama() const {
        const auto path = scratch.path() / "flat.hdr";
        std::ofstream(path, std::ios::binary) << radianceHdr(16, 8, 129);
        return path.string();
    }
};

TEST_F(BuiltInKernels, DefaultBakesCompileNothing) {
    // The file's source cube kernel and the built-in sky's, with and without a cache.
    for (const auto& input : {std::vector<std::string>{panorama()}, std::vector<std::string>{}}) {
        for (const bool cached : {false, true}) {
            auto arguments = small({"bake", "-o", at("out"), "--json"});
            if (!cached) arguments.push_back("--no-cache");
            arguments.insert(arguments.begin() + 1, input.begin(), input.end());
            const auto kernels = compiledKernels(iblkit(arguments));
            const auto which = std::string(cached ? "cached " : "") + (input.empty() ? "sky" : "file");
            EXPECT_EQ(kernels["compiled"], 0) << which;
            // Nine kernels, the LUT's two fewer where the cache holds the LUT.
            EXPECT_GE(kernels["built_in"], cached ? 7 : 9) << which;
            EXPECT_EQ(kernels["hits"], 0) << "the program's own come first";
            fs::remove_all(at("out"));
        }
    }
}

TEST_F(BuiltInKernels, ScenesAndProfilesCompileNothing) {
    // A scene's plan needs some of the default's kernels; an engine's profile changes the recipe,
    // which the kernels read as parameters, not as defines.
    const auto scene = scratch.path() / "mirrors.gltf";
    std::ofstream(scene) << R"({"asset": {"version": "2.0"}, "materials": [{"name": "chrome", )"
                            R"("pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0.3}}]})";
    for (const auto& extra : {std::vector<std::string>{"--scene", scene.string()}, std::vector<std::string>{"--profile", "threejs"},
                              std::vector<std::string>{"--profile", "babylon"},
                              std::vector<std::string>{"--profile", "filament"}}) {
        auto arguments = small({"bake", panorama(), "-o", at("out"), "--json", "--no-cache"});
        arguments.insert(arguments.end(), extra.begin(), extra.end());
        const auto kernels = compiledKernels(iblkit(arguments));
        EXPECT_EQ(kernels["compiled"], 0) << extra[0] << " " << extra[1];
        EXPECT_GT(kernels["built_in"], 0) << extra[0] << " " << extra[1];
        fs::remove_all(at("out"));
    }
}

TEST_F(BuiltInKernels, KernelsTheProgramLacksAreCompiled) {
    // The pyramid prefilter and the full quadrature LUT are not the default's; the rest is.
    const auto kernels = compiledKernels(iblkit({"bake", "-o", at("out"), "--json", "--no-cache", "--size", "16", "--method",
                                                 "pyramid", "--lut-method", "quadrature", "--lut-size", "8", "--quiet"}));
    EXPECT_GE(kernels["compiled"], 2);
    EXPECT_GE(kernels["built_in"], 5);
}

TEST_F(BuiltInKernels, DamagedEntriesAreCompiledAndLeftAlone) {
    // A copy of the program with its launcher and store, every entry of the store damaged.
    const fs::path build = fs::path(IBLKIT_EXECUTABLE).parent_path();
    const auto copy = scratch.path() / "program";
    fs::create_directories(copy);
    for (const char* name : {"iblkit", "iblkit-program"}) fs::copy_file(build / name, copy / name);
    fs::copy(build / "kernels", copy / "kernels", fs::copy_options::recursive);
    std::map<fs::path, std::string> damaged;
    for (const auto& entry : fs::recursive_directory_iterator(copy / "kernels")) {
        if (!entry.is_regular_file()) continue;
        {
            std::fstream file(entry.path(), std::ios::binary | std::ios::in | std::ios::out);
            file.seekg(-1, std::ios::end);
            const char last = char(file.get());
            file.seekp(-1, std::ios::end);
            file.put(char(last ^ 0xff));
        }
        damaged[entry.path()] = readFile(entry.path());
    }
    ASSERT_GE(damaged.size(), 9u) << "the build made no built-in kernels";
    const auto result = runProcess(small({(copy / "iblkit").string(), "bake", "-o", at("out"), "--json", "--no-cache"}),
                                   {"XDG_CACHE_HOME=" + cache.path().string()});
    const auto kernels = compiledKernels(result);
    EXPECT_EQ(kernels["built_in"], 0);
    EXPECT_GE(kernels["compiled"], 9);
    for (const auto& [path, bytes] : damaged) EXPECT_EQ(readFile(path), bytes) << path << ": the built-in store is read-only";
}

} // namespace
} // namespace iblkit::testing
