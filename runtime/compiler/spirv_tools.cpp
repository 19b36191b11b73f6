#include "spirv_tools.hpp"

#include "compile_error.hpp"

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

namespace iblkit::compiler {
namespace {

constexpr spv_target_env kEnvironment = SPV_ENV_VULKAN_1_1;
constexpr char kHex[] = "0123456789abcdef";

// The validator quotes the offending instruction on lines of its own, and a damaged module's
// strings hold any byte: one printable line each, so that an error stays one line.
std::string oneLine(const std::string& message) {
    std::string line;
    for (const char c : message) {
        const auto byte = static_cast<unsigned char>(c);
        const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (space && (line.empty() || line.back() == ' ')) continue;
        if (space) line += ' ';
        else if (byte < 0x20 || byte >= 0x7F) line += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
        else line += c;
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    return line;
}

struct MessageCollector {
    std::string text;
    void operator()(spv_message_level_t level, const char*, const spv_position_t& position, const char* message) {
        if (level > SPV_MSG_WARNING) return;
        text += (text.empty() ? "" : "; ") + oneLine(message) + " (word " + std::to_string(position.index) + ")";
    }
};

std::vector<uint32_t> runPasses(spvtools::Optimizer& optimizer, const std::vector<uint32_t>& spirv,
                                const std::string& sourceName, const char* what, bool validateInput = true) {
    MessageCollector messages;
    optimizer.SetMessageConsumer(
        [&](spv_message_level_t level, const char* source, const spv_position_t& position, const char* message) {
            messages(level, source, position, message);
        });
    std::vector<uint32_t> result;
    spvtools::OptimizerOptions options;
    options.set_run_validator(validateInput);
    if (!optimizer.Run(spirv.data(), spirv.size(), &result, options))
        throw CompileError(sourceName + ": error: SPIR-V " + what + " failed: " + messages.text);
    return result;
}

} // namespace

void validateSpirv(const std::vector<uint32_t>& spirv, const std::string& sourceName, SpirvEnvironment environment) {
    const bool vulkan = environment == SpirvEnvironment::Vulkan11;
    spvtools::SpirvTools tools(vulkan ? kEnvironment : SPV_ENV_OPENGL_4_5);
    MessageCollector messages;
    tools.SetMessageConsumer(
        [&](spv_message_level_t level, const char* source, const spv_position_t& position, const char* message) {
            messages(level, source, position, message);
        });
    if (tools.Validate(spirv)) return;
    // glslang keeps an HLSL integer matrix as one, which SPIR-V has no type for.
    if (messages.text.find("Matrix types can only be parameterized with floating-point types") != std::string::npos)
        throw CompileError(sourceName + ": error: an integer matrix (uint4x4, int3x3, ...) has no SPIR-V type for Vulkan, "
                                        "and glslang keeps it as one: hold its rows in vectors (uint4 rows[4]) and "
                                        "convert them row by row (asfloat(rows[i])) (" + messages.text + ")");
    throw CompileError(sourceName + ": error: the SPIR-V is not valid for " + (vulkan ? "Vulkan 1.1" : "OpenGL 4.5") + ": " +
                       messages.text);
}

std::vector<uint32_t> legalizeHlslSpirv(const std::vector<uint32_t>& spirv, const std::string& sourceName) {
    spvtools::Optimizer optimizer(kEnvironment);
    optimizer.RegisterLegalizationPasses();
    optimizer.RegisterPass(spvtools::CreateStripReflectInfoPass()); // hlsl_functionality1's semantics
    // glslang's HLSL output is legal only once legalized (a buffer passed to a function is a
    // pointer of the wrong storage class until inlining removes the call), so, as glslang's own
    // legalization does, the input is not validated; the legalized module is (validateSpirv).
    return runPasses(optimizer, spirv, sourceName, "legalization", false);
}

std::vector<uint32_t> optimizeSpirv(const std::vector<uint32_t>& spirv, OptimizationLevel level,
                                    const std::string& sourceName) {
    if (level == OptimizationLevel::None) return spirv;
    spvtools::Optimizer optimizer(kEnvironment);
    if (level == OptimizationLevel::Performance)
        optimizer.RegisterPerformancePasses();
    else
        optimizer.RegisterSizePasses();
    return runPasses(optimizer, spirv, sourceName, "optimization");
}

std::vector<uint32_t> stripDebugInfo(const std::vector<uint32_t>& spirv, const std::string& sourceName) {
    spvtools::Optimizer optimizer(kEnvironment);
    optimizer.RegisterPass(spvtools::CreateStripDebugInfoPass());
    return runPasses(optimizer, spirv, sourceName, "debug-info stripping");
}

std::string disassembleSpirv(const std::vector<uint32_t>& spirv) {
    spvtools::SpirvTools tools(kEnvironment);
    std::string text;
    tools.Disassemble(spirv, &text, SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES);
    return text;
}

} // namespace iblkit::compiler
