#pragma once

#include "json_fields.hpp"
#include "compile_options.hpp"
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

// A draw's shader stage: its file and entry point.
struct StageSpec {
    std::filesystem::path shader;
    std::string entry;
    std::optional<std::string> text; // compiled instead of the file (a stage the kit wrote); `shader` names it
};

// One per-vertex attribute, bound to the vertex shader's input of that semantic.
struct VertexInputSpec {
    std::string semantic; // as the run file writes it: "POSITION", "TEXCOORD0"
    std::string format;   // a vertex format: vertex_format.hpp
    ValueSource source;   // "values" or "file"
};

// A render target, named by the pixel shader's output semantic (SV_Target0 ... SV_Target7).
struct TargetSpec {
    std::string name; // as the run file writes it; expectations and saves use it
    std::string format;
    uint32_t width = 0, height = 0;
    std::array<double, 4> clear{0, 0, 0, 0};
    std::string blend = "none"; // none, alpha, premultiplied, additive
};

struct DepthSpec {
    std::string name = "SV_Depth";
    uint32_t width = 0, height = 0; // the colour targets' size when 0
    double clear = 1.0;
    std::string test = "less"; // never, less, equal, less_equal, greater, not_equal, greater_equal, always
    bool write = true;
};

struct DrawSpec {
    std::optional<uint32_t> vertices; // vertices drawn, or indices when the run file gives "indices"
    uint32_t instances = 1, firstVertex = 0, firstInstance = 0;
    int32_t baseVertex = 0;
    std::string topology = "triangle_list"; // triangle_strip, line_list, line_strip, point_list
};

// What makes a run file a draw rather than a dispatch.
struct GraphicsSpec {
    StageSpec vertex, pixel;
    std::vector<VertexInputSpec> vertexInput;
    std::vector<uint32_t> indices;
    DrawSpec draw;
    std::vector<TargetSpec> targets;
    std::optional<DepthSpec> depth;
    std::string cull = "none";       // none, front, back
    std::string front = "clockwise"; // clockwise or counter_clockwise, as seen in the target
    std::optional<std::array<double, 6>> viewport; // x, y, width, height, min depth, max depth
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
    std::optional<GraphicsSpec> graphics; // a draw; `shader` and `entry` are then the vertex stage's
    std::optional<Tolerance> crossApi;    // how far the APIs may differ, when not the default
    std::map<std::string, std::string> virtualFiles; // files the shaders include, by path, instead of the disk's (a program's own)
    // Where the shaders' compile options start (a build's prelude files, binding shifts), for runs
    // made from a code base's configuration; the keys above are then set on it.
    std::optional<compiler::CompileOptions> compileBase;
};

// Reads a run file (docs/run-files.md); paths in it are relative to the file.
// Throws RunError naming the file, the key and the problem.
// The HLSL language keys of a run file's object (and of the porting corpus's "compile" entries):
// "enable_16bit_types" (true or false) and "hlsl_version" ("2018" or "2021"), each left as it is
// when absent. `prefix` is "" or "key." for messages.
void readHlslLanguage(const JsonFields& fields, const nlohmann::json& object, const std::string& prefix,
                      bool& enable16BitTypes, lowering::HlslVersion& version);

RunSpec readRunFile(const std::filesystem::path& path);
// The keys that make a draw (graphics_run_file.cpp): "vertex", "pixel", "vertex_input", "indices",
// "draw", "targets", "raster" and "viewport".
GraphicsSpec readGraphics(const JsonFields& fields, const nlohmann::json& root, const std::filesystem::path& folder);
// The same from the file's text; paths in it are relative to `path`'s folder.
RunSpec parseRunFile(const std::string& text, const std::filesystem::path& path);

} // namespace iblkit::run
