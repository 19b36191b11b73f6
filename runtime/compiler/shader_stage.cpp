#include "shader_stage.hpp"

#include "compile_error.hpp"

#include <array>
#include <regex>
#include <utility>

namespace iblkit::compiler {
namespace {

struct StageNames {
    ShaderStage stage;
    std::string_view shortName;
    std::string_view longName;
    std::string_view hlslName;
};

constexpr std::array kStageNames{
    StageNames{ShaderStage::Vertex, "vert", "vertex", "vertex"},
    StageNames{ShaderStage::TessControl, "tesc", "tesscontrol", "hull"},
    StageNames{ShaderStage::TessEvaluation, "tese", "tessevaluation", "domain"},
    StageNames{ShaderStage::Geometry, "geom", "geometry", "geometry"},
    StageNames{ShaderStage::Fragment, "frag", "fragment", "pixel"},
    StageNames{ShaderStage::Compute, "comp", "compute", "compute"},
};

bool contains(const std::string& text, const char* word) {
    return std::regex_search(text, std::regex(std::string("\\b") + word + "\\b", std::regex::icase));
}

std::optional<ShaderStage> stageFromShaderAttribute(const std::string& attributes, const std::string& entry,
                                                    const std::string& sourceName) {
    std::smatch match;
    if (!std::regex_search(attributes, match, std::regex(R"(\bshader\s*\(\s*\"(\w+)\"\s*\))")))
        return std::nullopt;
    const std::string kind = match[1];
    for (const auto& names : kStageNames)
        if (kind == names.hlslName) return names.stage;
    throw CompileError(sourceName + ": error: entry point '" + entry + "' is a " + kind +
                       " shader, an unsupported stage (supported: vertex, hull, domain, geometry, pixel, compute)");
}

} // namespace

std::string_view stageName(ShaderStage stage) {
    for (const auto& names : kStageNames)
        if (names.stage == stage) return names.longName;
    return "unknown";
}

std::optional<ShaderStage> parseStageName(std::string_view name) {
    for (const auto& names : kStageNames)
        if (name == names.shortName || name == names.longName || name == names.hlslName) return names.stage;
    return std::nullopt;
}

// A definition: optional [attributes], a return type, the name, a parameter list (whose
// parameters may hold one level of parentheses: [[vk::location(2)]]), an optional ": SEMANTIC",
// then the body's brace.
std::regex definitionOf(const std::string& entry) {
    return std::regex("((?:\\[[^\\]]*\\]\\s*)*)\\b[\\w<>,\\s]+?\\s+" + entry +
                      "\\s*\\(((?:[^()]|\\([^()]*\\))*)\\)\\s*(:\\s*\\w+\\s*)?\\{");
}

bool definesEntryPoint(const std::string& source, const std::string& entry) {
    return std::regex_search(source, definitionOf(entry));
}

ShaderStage deduceStage(const std::string& source, const std::string& entry, const std::string& sourceName) {
    std::smatch match;
    if (!std::regex_search(source, match, definitionOf(entry)))
        throw CompileError(sourceName + ": error: entry point '" + entry + "' is not defined");
    const std::string attributes = match[1];
    const std::string signature = std::string(match[2]) + std::string(match[3]);

    if (auto stage = stageFromShaderAttribute(attributes, entry, sourceName)) return *stage;
    // A hull shader has [outputtopology] too, but never [numthreads].
    const bool mesh = (contains(attributes, "outputtopology") && contains(attributes, "numthreads")) ||
                      std::regex_search(signature, std::regex(R"(\bout\s+(vertices|indices|primitives)\b)"));
    const bool amplification = !mesh && contains(attributes, "numthreads") && contains(source, "DispatchMesh");
    if (mesh || amplification)
        throw CompileError(sourceName + ": error: entry point '" + entry + "' is " +
                           (mesh ? "a mesh" : "an amplification") +
                           " shader, an unsupported stage (supported: vertex, hull, domain, geometry, pixel, compute)");
    if (contains(attributes, "numthreads")) return ShaderStage::Compute;
    if (contains(attributes, "maxvertexcount")) return ShaderStage::Geometry;
    if (contains(attributes, "outputcontrolpoints") || contains(attributes, "patchconstantfunc"))
        return ShaderStage::TessControl;
    if (contains(attributes, "domain")) return ShaderStage::TessEvaluation;
    if (contains(signature, "SV_Target\\d*")) return ShaderStage::Fragment;
    if (contains(signature, "SV_Position")) return ShaderStage::Vertex;
    throw CompileError(sourceName + ": error: cannot tell the stage of entry point '" + entry +
                       "' from its attributes or semantics; give it with -S STAGE");
}

} // namespace iblkit::compiler
