#pragma once

#include "json_fields.hpp"
#include "lowering.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::run {

// Where a resource's initial values, or an expectation's expected values, come from.
struct ValueSource {
    std::vector<double> fill;     // repeated over every texel (channels) or element
    std::vector<double> values;   // every value, in order
    std::filesystem::path file;   // raw data in the resource's format, or .npy
    bool given() const { return !fill.empty() || !values.empty() || !file.empty(); }
};

struct ResourceSpec {
    std::string name;    // as expectations name it: "Out", or "Mips[2]" for an element of an array
    std::string binding; // the shader's resource: "Out", "Mips"
    uint32_t element = 0; // within an array of resources ("elements" in the run file)
    std::string kind; // buffer, cbuffer, image, cube, storage_image, sampler
    // images
    std::string format;
    std::string dimension; // 2d, 2d_array, cube
    uint32_t width = 0, height = 0, layers = 1, mips = 1;
    uint32_t mip = 0; // storage images: the mip the shader writes
    // buffers
    std::string elementType = "float"; // float, uint, int
    size_t count = 0;                  // elements
    size_t sizeBytes = 0;
    // cbuffers
    std::map<std::string, std::vector<double>> members;
    // samplers
    std::string filter = "linear", mipmap = "linear", address = "clamp";
    ValueSource initial;
};

struct Tolerance {
    std::optional<double> absolute, relative, ulp;
    bool exact() const { return !absolute && !relative && !ulp; }
};

struct Expectation {
    std::string resource;
    std::optional<uint32_t> mip, layer; // images: compare one mip and/or layer only
    ValueSource expected;
    std::optional<std::array<double, 2>> range; // every value within [min, max]
    Tolerance tolerance;
};

struct RunSpec {
    std::filesystem::path runFile;
    std::filesystem::path shader;
    std::string entry = "main";
    std::vector<std::filesystem::path> includeDirs;
    std::map<std::string, std::string> defines;
    std::map<std::string, std::string> imageFormats;
    bool enable16BitTypes = false; // DXC's -enable-16bit-types
    lowering::HlslVersion hlslVersion = lowering::HlslVersion::Hlsl2021;
    std::map<std::string, double> specialization;
    std::map<std::string, std::vector<double>> pushConstants;
    std::vector<ResourceSpec> resources;
    std::optional<std::array<uint32_t, 3>> threads, groups;
    std::vector<Expectation> expectations;
    std::map<std::string, std::filesystem::path> saves;
};

// Reads a run file (docs/run-files.md); paths in it are relative to the file.
// Throws RunError naming the file, the key and the problem.
// The HLSL language keys of a run file's object (and of the porting corpus's "compile" entries):
// "enable_16bit_types" (true or false) and "hlsl_version" ("2018" or "2021"), each left as it is
// when absent. `prefix` is "" or "key." for messages.
void readHlslLanguage(const JsonFields& fields, const nlohmann::json& object, const std::string& prefix,
                      bool& enable16BitTypes, lowering::HlslVersion& version);

RunSpec readRunFile(const std::filesystem::path& path);
// The same from the file's text; paths in it are relative to `path`'s folder.
RunSpec parseRunFile(const std::string& text, const std::filesystem::path& path);

} // namespace iblkit::run
