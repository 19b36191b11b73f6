// `iblkit bake` as a user runs it: the default bake, progress and --json, and for every kind
// of bad input one line naming the problem, a non-zero exit and the output folder untouched.
#include "bake_cli_fixture.hpp"
#include "float_image.hpp"
#include "ktx2.hpp"

#include <nlohmann/json.hpp>

#include <csignal>
#include <fstream>
#include <limits>
#include <span>
#include <sys/stat.h>

namespace iblkit::testing {
namespace {

namespace fs = std::filesystem;

TEST_F(BakeCli, DefaultBakeWritesEveryOutputWithProgress) {
    const auto result = iblkit({"bake", "-o", at("out")});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    for (const char* name : {"specular.ktx2", "brdf_lut.ktx2", "irradiance.ktx2", "manifest.json", "preview.png"})
        EXPECT_GT(fs::file_size(scratch.path() / "out" / name), 0u) << name;
    for (const char* step : {"source cube", "prefilter", "brdf lut", "irradiance", "preview", "100%"})
        EXPECT_NE(result.err.find(step), std::string::npos) << step << " is not reported:\n" << result.err;
    // Not a terminal (a pipe, as a log file): one line per step, written when it ends, and no
    // carriage returns (a render's log once took 1,243 lines in 25 s).
    EXPECT_EQ(result.err.find('\r'), std::string::npos);
    for (const char* step : {"\nprefilter ", "\nbrdf lut ", "\nirradiance "}) {
        const auto first = result.err.find(step);
        EXPECT_EQ(result.err.find(step, first + 1), std::string::npos) << step << " has more than one line:\n" << result.err;
    }
    const auto manifest = nlohmann::json::parse(readFile(scratch.path() / "out" / "manifest.json"));
    EXPECT_EQ(manifest["specular"]["size"], 256);
    EXPECT_EQ(manifest["specular"]["mips"], 6);
    EXPECT_EQ(manifest["brdf_lut"]["size"], 512);
    EXPECT_EQ(manifest["brdf_lut"]["format"], "R16G16_SFLOAT");
    EXPECT_EQ(manifest["settings"]["method"], "convolution");
    EXPECT_EQ(manifest["settings"]["samples"], 128);
    EXPECT_EQ(manifest["specular"]["terms_per_texel"], 128);
    EXPECT_EQ(manifest["specular"]["shader"], "hlsl/PrefilterConvolutionCS.hlsl");
}

TEST_F(BakeCli, QuietIsSilentAndJsonReportsEveryStep) {
    const auto result = iblkit(small({"bake", "-o", at("out"), "--json"}));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_EQ(result.err, "");
    const auto summary = nlohmann::json::parse(result.out);
    std::vector<std::string> steps;
    for (const auto& step : summary["steps"]) {
        steps.push_back(step["name"]);
        EXPECT_GE(step["wall_ms"].get<double>(), 0);
        EXPECT_GE(step["device_ms"].get<double>(), 0);
    }
    EXPECT_EQ(steps, (std::vector<std::string>{"start", "load", "cache", "device", "source cube", "lights", "irradiance",
                                               "prefilter", "brdf lut", "preview", "outputs", "tear-down", "write"}))
        << "the built-in sky's sun is taken out as a light";
    const auto& prefilter = summary["steps"][7];
    EXPECT_GT(prefilter["device_ms"].get<double>(), 0) << "the prefilter's dispatches are timed";
    double mipsDeviceTime = 0;
    std::vector<std::string> mips;
    for (const auto& part : prefilter["parts"]) {
        mips.push_back(part["name"]);
        mipsDeviceTime += part["device_ms"].get<double>();
    }
    EXPECT_EQ(mips, std::vector<std::string>{"mip 1"}) << "each prefiltered mip: a 16² chain has two mips";
    EXPECT_DOUBLE_EQ(mipsDeviceTime, prefilter["device_ms"].get<double>()) << "the mips hold every dispatch of the step";
    std::vector<std::string> deviceParts;
    for (const auto& part : summary["steps"][3]["parts"]) deviceParts.push_back(part["name"]);
    EXPECT_EQ(deviceParts, (std::vector<std::string>{"instance and device", "pipeline cache", "kernel threads", "memory check"}));
    EXPECT_GT(summary["compiled_kernels"]["compile_ms"].get<double>(), 0);
    EXPECT_GE(summary["process_ms"].get<double>(), summary["wall_ms"].get<double>()) << "the process holds the bake";
    double peak = 0;
    for (const auto& step : summary["steps"]) {
        if (step["name"] == "start") continue; // the program's own, before the bake
        // The kernel counts each thread's pages apart and adds them up every 64 faults, so the
        // peak it shows may step back by up to 64 pages per thread (1 MiB for four) when threads end.
        EXPECT_GE(step["peak_mib"].get<double>(), peak - 2) << step["name"] << ": the largest resident set only grows";
        peak = std::max(peak, step["peak_mib"].get<double>());
    }
    EXPECT_GT(peak, 20) << "lavapipe maps LLVM";
    EXPECT_NEAR(summary["peak_mib"].get<double>(), peak, 2) << "nothing after the write";
    EXPECT_EQ(summary["cache"]["misses"], 6) << "specular, LUT, irradiance, lights, lobe table, preview";
}

TEST_F(BakeCli, ARepeatedBakeComesFromTheCacheAndNoCacheComputesEverything) {
    ASSERT_EQ(iblkit(small({"bake", "-o", at("first")})).exitCode, 0);
    const auto again = iblkit(small({"bake", "-o", at("again"), "--json"}));
    ASSERT_EQ(again.exitCode, 0) << again.err;
    const auto summary = nlohmann::json::parse(again.out);
    std::vector<std::string> steps;
    for (const auto& step : summary["steps"]) steps.push_back(step["name"]);
    EXPECT_EQ(steps, (std::vector<std::string>{"start", "load", "cache", "write"})) << "no device opened";
    EXPECT_EQ(summary["cache"]["hits"], 6);
    for (const char* file : {"specular.ktx2", "lights.gltf", "lobe_table.ktx2", "preview.png"})
        EXPECT_EQ(readFile(scratch.path() / "first" / file), readFile(scratch.path() / "again" / file)) << file;
    EXPECT_EQ(nlohmann::json::parse(readFile(scratch.path() / "first" / "manifest.json"))["shading"],
              nlohmann::json::parse(readFile(scratch.path() / "again" / "manifest.json"))["shading"])
        << "the lights and the recipe, from the cache";
    const auto uncached = iblkit(small({"bake", "-o", at("uncached"), "--no-cache", "--json"}));
    ASSERT_EQ(uncached.exitCode, 0) << uncached.err;
    EXPECT_EQ(nlohmann::json::parse(uncached.out)["cache"]["hits"], 0);
    EXPECT_EQ(readFile(scratch.path() / "first" / "specular.ktx2"), readFile(scratch.path() / "uncached" / "specular.ktx2"));
    expectFailure(small({"bake", "-o", at("both"), "--no-cache", "--cache", at("c")}), "--cache and --no-cache");
    // A cache inside the output folder was made there during the bake, which then refused to
    // replace a folder with other files, and so did every bake after it.
    for (const auto& inside : {at("inside") + "/cache", at("inside"), at("inside") + "/x/../c"})
        expectFailure(small({"bake", "-o", at("inside"), "--cache", inside}), "is inside the output folder");
}

// The table's count doubles per mip; the manifest says what each mip took, and both kit
// methods that read the source's mips bake.
TEST_F(BakeCli, TheTableAndFilteredMethodsBakeAndRecordTheirCounts) {
    ASSERT_EQ(iblkit(small({"bake", "-o", at("table"), "--method", "table", "--mips", "3"})).exitCode, 0);
    const auto table = nlohmann::json::parse(readFile(scratch.path() / "table" / "manifest.json"))["specular"];
    EXPECT_EQ(table["method"], "table");
    EXPECT_EQ(table["samples_of_mip"], nlohmann::json::parse("[16, 32]")) << "16² down to 4²: mips 1 and 2";
    EXPECT_EQ(table["shader"], "hlsl/PrefilterTableCS.hlsl");
    ASSERT_EQ(iblkit(small({"bake", "-o", at("filtered"), "--method", "filtered"})).exitCode, 0);
    const auto filtered = nlohmann::json::parse(readFile(scratch.path() / "filtered" / "manifest.json"))["specular"];
    EXPECT_EQ(filtered["samples"], 16);
    EXPECT_EQ(filtered["shader"], "hlsl/PrefilterFilteredCS.hlsl");
    expectFailure({"bake", "-o", at("out"), "--method", "table", "--samples", "65536"}, "--samples 65536 is out of range (1 to 65535)");
}

TEST_F(BakeCli, ThePyramidTheMipChainAndTheFastLutMethodsBakeAndRecordTheirCounts) {
    const auto bake = [&](const std::string& folder, std::vector<std::string> settings) {
        std::vector<std::string> arguments{"bake", "-o", at(folder), "--size", "16", "--lut-size", "8",
                                           "--irradiance-size", "4", "--quiet"};
        arguments.insert(arguments.end(), settings.begin(), settings.end());
        const auto result = iblkit(arguments);
        EXPECT_EQ(result.exitCode, 0) << result.err;
        return nlohmann::json::parse(readFile(scratch.path() / folder / "manifest.json"));
    };
    const auto fit = bake("fit", {"--method", "pyramid", "--samples", "2", "--lut-method", "fit", "--lut-samples", "3"});
    EXPECT_EQ(fit["specular"]["method"], "pyramid");
    EXPECT_EQ(fit["specular"]["reads_per_texel"], 2);
    EXPECT_EQ(fit["specular"]["shader"], "hlsl/PrefilterPyramidCS.hlsl");
    // Roughness 0.25, 0.5, 0.75 and 1: the ring from half the lobe's mass past pi/8 (0.5).
    const auto chain = bake("chain", {"--method", "mipchain", "--mips", "5"});
    EXPECT_EQ(chain["specular"]["mips_copied_from_the_source"], nlohmann::json::parse("[1]"));
    EXPECT_EQ(chain["specular"]["mips_from_the_ring"], nlohmann::json::parse("[2, 3, 4]"));
    EXPECT_EQ(chain["specular"]["shader"], "hlsl/PrefilterRingCS.hlsl");
    EXPECT_EQ(fit["brdf_lut"]["method"], "fit");
    EXPECT_EQ(fit["brdf_lut"]["polynomial_degree"], 3);
    EXPECT_EQ(fit["brdf_lut"]["shader"], "hlsl/BrdfLutFitCS.hlsl");
    const auto grid = bake("grid", {"--lut-method", "quadrature-grid", "--lut-samples", "8"});
    EXPECT_EQ(grid["brdf_lut"]["grid_nodes_per_side"], 8);
    EXPECT_EQ(grid["brdf_lut"]["shaders"],
              nlohmann::json::parse(R"(["hlsl/BrdfLutGridCS.hlsl", "hlsl/BrdfLutResampleCS.hlsl"])"));
    expectFailure({"bake", "-o", at("out"), "--lut-method", "fit", "--lut-samples", "10"},
                  "--lut-samples 10 is out of range (1 to 9)");
    expectFailure({"bake", "-o", at("out"), "--method", "pyramid", "--samples", "5"}, "--samples 5 is out of range (1 to 4)");
}

// Every input kind is read as the environment it holds, each bake's manifest naming its kind. A
// uniform panorama (radiance 1: RGBE 128, 128, 128 at exponent 129) gives the furnace's 1 at every
// texel of every specular mip, within 2^-10 (half-float rounding and the convolution's float sums;
// measured: exactly 1). Faces of radiance 1, 2, 4, ... 32 in the order +X, -X, +Y, -Y, +Z, -Z come
// back as mip 0's faces in that order (roughness 0 copies the source), as faces, and again after
// the bake's own KTX2 and DDS cubes are baked in turn: a face read in the wrong place or order is
// caught.
TEST_F(BakeCli, PanoramaFacesAndCubeInputsBake) {
    const auto specular = [&](const std::string& folder, const std::string& kind) {
        const auto manifest = nlohmann::json::parse(readFile(scratch.path() / folder / "manifest.json"));
        EXPECT_EQ(manifest["input"]["kind"], kind) << folder;
        const auto bytes = readFile(scratch.path() / folder / "specular.ktx2");
        const auto texture = image_io::decodeKtx2(std::as_bytes(std::span(bytes.data(), bytes.size())), folder);
        EXPECT_EQ(texture.faces, 6u);
        EXPECT_EQ(texture.width, 16u);
        return image_io::textureValues(texture);
    };
    scratch.write("sky.hdr", radianceHdr(32, 16, 129));
    ASSERT_EQ(iblkit(small({"bake", at("sky.hdr"), "-o", at("from-hdr")})).exitCode, 0);
    const auto uniform = specular("from-hdr", "equirectangular");
    float worst = 0;
    for (size_t i = 0; i < uniform.size(); ++i)
        if (i % 4 != 3) worst = std::max(worst, std::abs(uniform[i] - 1.f));
    EXPECT_LE(worst, 1.f / 1024) << "a texel of the uniform environment's specular is off by " << worst;

    const auto expectFacesInOrder = [&](const std::string& folder, const std::string& kind) {
        const auto values = specular(folder, kind);
        for (uint32_t face = 0; face < 6; ++face) {
            const size_t centre = ((size_t(face) * 16 + 8) * 16 + 8) * 4;
            EXPECT_EQ(values.at(centre), float(1u << face)) << folder << ": face " << face;
        }
    };
    const char* names[] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (int face = 0; face < 6; ++face)
        scratch.write(std::string("faces/") + names[face] + ".hdr", radianceHdr(16, 16, static_cast<unsigned char>(129 + face)));
    const auto faces = iblkit(small({"bake", at("faces"), "-o", at("from-faces"), "--dds"}));
    ASSERT_EQ(faces.exitCode, 0) << faces.err;
    expectFacesInOrder("from-faces", "faces");
    EXPECT_EQ(nlohmann::json::parse(readFile(scratch.path() / "from-faces" / "manifest.json"))["input"]["files"].size(), 6u);
    for (const char* cube : {"from-faces/specular.ktx2", "from-faces/specular.dds"}) {
        const auto folder = std::string("from-") + fs::path(cube).extension().string().substr(1);
        const auto result = iblkit(small({"bake", at(cube), "-o", at(folder)}));
        ASSERT_EQ(result.exitCode, 0) << cube << ": " << result.err;
        expectFacesInOrder(folder, "cube");
    }
}

TEST_F(BakeCli, MissingCorruptAndUnsupportedInputsAreRefused) {
    expectFailure(small({"bake", at("missing.hdr"), "-o", at("out")}), "missing.hdr");
    scratch.write("corrupt.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n\x01\x02");
    expectFailure(small({"bake", at("corrupt.hdr"), "-o", at("out")}), "corrupt.hdr");
    scratch.write("corrupt.exr", std::string("\x76\x2f\x31\x01\x02\x00\x00\x00garbage", 15));
    expectFailure(small({"bake", at("corrupt.exr"), "-o", at("out")}), "corrupt.exr");
    scratch.write("sky.png", "\x89PNG\r\n\x1a\n");
    expectFailure(small({"bake", at("sky.png"), "-o", at("out")}), "unsupported image format");
    scratch.write("faces/px.hdr", radianceHdr(16, 16, 129));
    expectFailure(small({"bake", at("faces"), "-o", at("out")}), "no -X face");
}

// A link to /dev/zero named .hdr had the bake hash an endless file; a FIFO blocked its open.
// Neither is a file: both are refused at once, in one line (the killer stops a regression).
TEST_F(BakeCli, DevicesAndPipesNamedLikeImagesAreRefused) {
    std::filesystem::create_symlink("/dev/zero", at("zero.hdr"));
    std::filesystem::create_symlink("/dev/urandom", at("random.exr"));
    ASSERT_EQ(mkfifo(at("pipe.exr").c_str(), 0600), 0);
    for (const char* input : {"zero.hdr", "random.exr", "pipe.exr"}) {
        const auto result = iblkit(small({"bake", at(input), "-o", at("out")}), 60);
        EXPECT_EQ(result.exitCode, 1) << input << ": " << result.err;
        EXPECT_NE(result.err.find(std::string(input) + "': not a regular file"), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    }
    EXPECT_FALSE(std::filesystem::exists(at("out")));
}

// A file name that is not UTF-8 (Linux names are bytes) ended in a raw JSON exception after the
// bake was written, with a non-zero exit. Its bytes are now written as \xNN in the manifest and
// in --json, and the bake succeeds.
TEST_F(BakeCli, AnInputNameThatIsNotUtf8IsEscapedInTheManifest) {
    const std::string name = "sky\xff\xe0\x80.hdr"; // a lone 0xff, and an overlong start
    scratch.write(name, radianceHdr(16, 8, 129));
    const auto result = iblkit(small({"bake", at(name), "-o", at("out\xfe"), "--json"}));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const auto manifest = nlohmann::json::parse(readFile(scratch.path() / "out\xfe" / "manifest.json"));
    EXPECT_NE(manifest["input"]["files"][0]["path"].get<std::string>().find("sky\\xff\\xe0\\x80.hdr"), std::string::npos)
        << manifest["input"].dump();
    EXPECT_NE(nlohmann::json::parse(result.out)["output"].get<std::string>().find("out\\xfe"), std::string::npos) << result.out;
}

TEST_F(BakeCli, APanoramaThatIsNotTwoToOneIsRefused) {
    scratch.write("wide.hdr", radianceHdr(30, 20, 129));
    expectFailure(small({"bake", at("wide.hdr"), "-o", at("out")}), "30x20");
}

TEST_F(BakeCli, NonFiniteTexelsAreRefusedUnlessSanitized) {
    image_io::FloatImage image{16, 8, 3, std::vector<float>(16 * 8 * 3, 1.f)};
    image.values[(2 * 16 + 5) * 3 + 1] = std::numeric_limits<float>::quiet_NaN();
    image.values[(7 * 16 + 0) * 3] = std::numeric_limits<float>::infinity();
    image_io::writeExr(scratch.path() / "nan.exr", image);
    expectFailure(small({"bake", at("nan.exr"), "-o", at("out")}), "2 NaN/Inf texels (the first at column 5, row 2: nan)");
    const auto result = iblkit(small({"bake", at("nan.exr"), "-o", at("out"), "--sanitize", "--json"}));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_EQ(nlohmann::json::parse(result.out)["sanitized_texels"], 2);
}

// A NaN in a cube file was named by its row across the six stacked faces (row 13 of -Y's row 1);
// now by its face, with the face's own column and row. Two files for one face are ambiguous.
TEST_F(BakeCli, ACubeInputsBadTexelIsNamedByItsFaceAndAFaceGivenTwiceIsRefused) {
    image_io::Texture cube{image_io::PixelFormat::Rgba32Float, 4, 4, 6, 1, {}};
    std::vector<float> texels(6 * 4 * 4 * 4, 1.f);
    texels[((3 * 4 + 1) * 4 + 2) * 4 + 1] = std::numeric_limits<float>::quiet_NaN(); // -Y, row 1, column 2
    const auto bytes = std::as_bytes(std::span(texels));
    cube.levels.emplace_back(bytes.begin(), bytes.end());
    const auto encoded = image_io::encodeKtx2(cube, "test");
    std::ofstream(scratch.path() / "cube.ktx2", std::ios::binary)
        .write(reinterpret_cast<const char*>(encoded.data()), std::streamsize(encoded.size()));
    expectFailure(small({"bake", at("cube.ktx2"), "-o", at("out")}),
                  "'" + at("cube.ktx2") + "' face -Y has 1 NaN/Inf texel (the first at column 2, row 1: nan)");
    for (const char* face : {"px", "nx", "py", "ny", "pz", "nz"})
        scratch.write(std::string("faces/") + face + ".hdr", radianceHdr(16, 16, 129));
    scratch.write("faces/ny.exr", "an exr beside ny.hdr");
    expectFailure(small({"bake", at("faces"), "-o", at("out")}), "has 2 files for the -Y face ('ny.hdr' and 'ny.exr'): keep one");
}

TEST_F(BakeCli, TheDocumentsMethodReproducesItsOutputsFromBeforeTheKitsOwnMethods) {
    // A 32x16 panorama of varied RGBE texels with one bright texel. The values are those the EXR
    // outputs of commit c58b1d3 (the bake before any method of the kit's own existed) decoded to,
    // on lavapipe, for the same input and settings: the document's specular mip 1 and LUT must
    // stay bit for bit what they were. Decoded floats, not the files' bytes: another OpenEXR may
    // compress the same values differently.
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16 +X 32\n";
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 0; x < 32; ++x)
            hdr += std::string{char(64 + (x * 7 + y * 13) % 128), char(64 + (x * 11 + y * 5) % 128),
                               char(64 + (x * 3 + y * 17) % 128), char(x == 20 && y == 5 ? 140 : 129)};
    scratch.write("golden.hdr", hdr);
    const auto result = iblkit({"bake", at("golden.hdr"), "-o", at("out"), "--quiet", "--exr", "--size", "16", "--samples",
                                "64", "--lut-size", "8", "--irradiance-size", "4", "--method", "document",
                                "--lut-method", "document", "--lut-samples", "1024"});
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const auto before = nlohmann::json::parse(readFile("tests/cli/data/document_method_outputs.json"));
    ASSERT_EQ(before.size(), 7u) << "specular mip 1's six faces and the LUT";
    for (const auto& [name, values] : before.items()) {
        const auto image = image_io::readExr(scratch.path() / "out" / name);
        ASSERT_EQ(image.values.size(), values.size()) << name;
        size_t differing = 0;
        for (size_t i = 0; i < values.size(); ++i) differing += image.values[i] != values[i].get<float>();
        EXPECT_EQ(differing, 0u) << name << ": values no longer what the document's method baked";
    }
}

TEST_F(BakeCli, SizesOutOfRangeOrBeyondMemoryAreRefused) {
    expectFailure({"bake", "-o", at("out"), "--size", "100"}, "not a power of two");
    expectFailure({"bake", "-o", at("out"), "--size", "16384", "--quiet"}, "memory");
    expectFailure({"bake", "-o", at("out"), "--lut-format", "rgba8"}, "--lut-format");
    expectFailure({"bake", "-o", at("out"), "--mips", "12", "--size", "64"}, "--mips 12");
    expectFailure({"bake", "-o", at("out"), "--method", "nope"}, "--method nope is not a prefilter method");
    expectFailure({"bake", "-o", at("out"), "--samples", "40000"}, "--samples 40000 is out of range (1 to 2048)");
}

TEST_F(BakeCli, AFolderThatIsNotABakeIsNeverReplaced) {
    scratch.write("mine/notes.txt", "keep me");
    expectFailure(small({"bake", "-o", at("mine")}), "refusing to replace it");
}

TEST_F(BakeCli, AFailedOrKilledBakeLeavesTheEarlierBakeAsItWas) {
    ASSERT_EQ(iblkit(small({"bake", "-o", at("out")})).exitCode, 0);
    const auto good = snapshot(scratch.path() / "out");
    scratch.write("wide.hdr", radianceHdr(30, 20, 129));
    EXPECT_NE(iblkit(small({"bake", at("wide.hdr"), "-o", at("out")})).exitCode, 0);
    EXPECT_EQ(snapshot(scratch.path() / "out"), good);
    // Killed while the prefilter runs (a 256² bake with 4096 samples takes several seconds).
    const auto killed = iblkit({"bake", "-o", at("out"), "--method", "document", "--samples", "4096", "--quiet"}, 2.0);
    EXPECT_EQ(killed.exitCode, 128 + 9) << "the bake finished before it could be killed";
    EXPECT_EQ(snapshot(scratch.path() / "out"), good);
}

// SIGINT and SIGTERM left an empty .iblkit-partial-XXXXXX folder beside the target; now the bake
// removes it and ends as the signal would have.
TEST_F(BakeCli, InterruptedOrTerminatedBakesLeaveNoPartialFolder) {
    for (const int signal : {SIGINT, SIGTERM}) {
        const auto stopped = iblkit({"bake", "-o", at("out"), "--method", "document", "--samples", "4096", "--quiet"}, 2.0, signal);
        EXPECT_EQ(stopped.exitCode, 128 + signal) << "the bake finished before the signal: " << stopped.err;
        EXPECT_EQ(std::distance(std::filesystem::directory_iterator(scratch.path()), std::filesystem::directory_iterator()), 0)
            << "something was left beside the target";
    }
}

} // namespace
} // namespace iblkit::testing
