#include "hlsl_frontend.hpp"

#include "compile_error.hpp"
#include "diagnostics.hpp"
#include "frontend_refusals.hpp"
#include "glslang_process.hpp"
#include "hlsl_register_resolver.hpp"
#include "bounded_child.hpp"
#include "image_formats.hpp"

#include "include_resolver.hpp"
#include "lowering.hpp"
#include "lowering_error.hpp"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

#include <algorithm>
#include <cctype>

namespace iblkit::compiler {
namespace {

constexpr int kHlslVersion = 100;

EShMessages messagesFor(const CompileOptions& options) {
    const int sixteenBit = options.enable16BitTypes ? int(EShMsgHlslEnable16BitTypes) : 0;
    return static_cast<EShMessages>(EShMsgReadHlsl | EShMsgSpvRules | EShMsgVulkanRules | EShMsgHlslOffsets | sixteenBit);
}

// Lowered text was preprocessed already: its macros are expanded, and their defines must not
// apply twice; the default matrix packing applies either way. Each define replaces a macro
// glslang predefines (VULKAN, for a Vulkan target), as a command line's -D does.
std::string preambleOf(const CompileOptions& options, bool preprocessed) {
    std::string preamble = options.rowMajorByDefault ? "#pragma pack_matrix(row_major)\n" : "";
    if (!preprocessed)
        for (const auto& [name, value] : options.defines)
            preamble += "#undef " + name + "\n#define " + name + " " + value + "\n";
    return preamble;
}

[[noreturn]] void failWith(const std::string& log, const IncludeResolver& files, const std::string& sourceName,
                           const std::string& fallback) {
    if (files.cycle()) throw CompileError(*files.cycle()); // glslang only says it could not include
    // glslang's HLSL frontend cascades after its first error; the first is the real one. Some of
    // its errors have no place ("0:0: 'constructor' : can't convert", then the located one):
    // the first located error says more.
    const auto diagnostics = parseGlslangLog(log, files, sourceName);
    if (diagnostics.errors.empty()) throw CompileError(sourceName + ": error: " + fallback);
    const auto located = std::find_if(diagnostics.errors.begin(), diagnostics.errors.end(),
                                      [](const std::string& error) { return error.rfind("0:0:", 0) != 0; });
    throw CompileError(inKitWords(located != diagnostics.errors.end() ? *located : diagnostics.errors.front()));
}

// One TShader configured the same way for the preprocessing pass and the real parse.
struct ConfiguredShader {
    ConfiguredShader(EShLanguage language, const CompileOptions& options, const std::string& sourceName,
                     const std::string& text, bool preprocessed = false)
        : shader(language), preamble(preambleOf(options, preprocessed)), name(sourceName), source(text.c_str()),
          length(static_cast<int>(text.size())) {
        nameText = name.c_str();
        shader.setStringsWithLengthsAndNames(&source, &length, &nameText, 1);
        shader.setPreamble(preamble.c_str());
        shader.setEntryPoint(options.entryPoint.c_str());
        shader.setSourceEntryPoint(options.entryPoint.c_str());
        shader.setEnvInput(glslang::EShSourceHlsl, language, glslang::EShClientVulkan, kHlslVersion);
        shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
        shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
        shader.setHlslIoMapping(true);
        // Each varying's semantic as a UserSemantic decoration, for system values glslang does not
        // know (spirv_semantic_builtins.hpp); legalization strips the decorations.
        shader.setEnvTargetHlslFunctionality1();
    }

    glslang::TShader shader;
    std::string preamble;
    std::string name;
    const char* source;
    int length;
    const char* nameText = nullptr;
};

std::string preprocess(const CompileOptions& options, const std::string& sourceName, const std::string& text,
                       IncludeResolver& includes) {
    ConfiguredShader configured(EShLangCompute, options, sourceName, text);
    std::string preprocessed;
    if (!configured.shader.preprocess(GetDefaultResources(), kHlslVersion, ENoProfile, false, false, messagesFor(options),
                                      &preprocessed, includes))
        failWith(configured.shader.getInfoLog(), includes, sourceName, "preprocessing failed");
    return preprocessed;
}

// When no definition of the entry point is found, a syntax error in it is the likelier cause,
// and glslang names its place; only when it finds none is the entry point missing.
// The stage given (-S) or deduced; either way the entry point must be defined (glslang alone
// would end in "resource binding failed").
ShaderStage stageOrReportSyntax(const std::string& preprocessed, const CompileOptions& options,
                                const std::string& sourceName, const std::string& text, bool textIsPreprocessed) {
    if (definesEntryPoint(preprocessed, options.entryPoint))
        return options.stage ? *options.stage : deduceStage(preprocessed, options.entryPoint, sourceName);
    IncludeResolver includes(options.includeDirs, &options.virtualFiles);
    includes.addSource(sourceName, text);
    ConfiguredShader configured(EShLangFragment, options, sourceName, text, textIsPreprocessed);
    if (!configured.shader.parse(GetDefaultResources(), kHlslVersion, false, messagesFor(options), includes) &&
        configured.shader.getInfoLog() != std::string() &&
        std::string(configured.shader.getInfoLog()).find("Entry point not found") == std::string::npos)
        failWith(configured.shader.getInfoLog(), includes, sourceName, "compilation failed");
    throw CompileError(sourceName + ": error: entry point '" + options.entryPoint + "' is not defined");
}

// -D names reach glslang as "#define NAME VALUE" in a preamble, whose errors have no place.
void requireMacroNames(const CompileOptions& options, const std::string& sourceName) {
    for (const auto& [name, value] : options.defines) {
        const bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name.front())) &&
                                std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
        if (!identifier)
            throw CompileError(sourceName + ": error: define '" + name + (value.empty() ? "" : "=" + value) +
                               "': '" + name + "' is not a macro name (letters, digits and '_', not starting with a digit)");
    }
}

lowering::LoweredSource lower(const CompileOptions& options, const std::string& sourceName, const std::string& preprocessed) {
    try {
        return lowering::lowerHlsl(preprocessed, sourceName, options.hlslVersion, options.enable16BitTypes, options.entryPoint);
    } catch (const lowering::LoweringError& error) {
        throw CompileError(error.what());
    }
}

// The [[vk::image_format]] attributes in glslang's spelling ("r11g11b10f" is DXC's
// r11f_g11f_b10f, "rgba8snorm" its rgba8_snorm).
std::map<std::string, std::string> attributeImageFormats(const lowering::VulkanAttributes& vulkan, const std::string& sourceName) {
    std::map<std::string, std::string> formats;
    for (const auto& [resource, written] : vulkan.imageFormats) {
        const auto* format = findImageFormatByAttributeName(written);
        if (!format)
            throw CompileError(sourceName + ": error: [[vk::image_format(\"" + written + "\")]] on '" + resource +
                               "' is not a storage image format");
        formats[resource] = std::string(format->glslName);
    }
    return formats;
}

std::map<std::string, ExplicitBinding> attributeBindings(const lowering::VulkanAttributes& vulkan) {
    std::map<std::string, ExplicitBinding> bindings;
    for (const auto& [resource, binding] : vulkan.bindings)
        bindings[resource] = ExplicitBinding{binding.set, binding.binding, binding.place.describe()};
    return bindings;
}

} // namespace

std::string readSource(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw CompileError(path.string() + ": error: no such file");
    if (!std::filesystem::is_regular_file(path, error))
        throw CompileError(path.string() + ": error: not a regular file");
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw CompileError(path.string() + ": error: cannot read the file: " + std::strerror(errno));
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

FrontendResult compileHlsl(const CompileOptions& options) {
    initializeGlslangOnce();
    const std::string sourceName = options.source.string();
    std::string text = asGlslangReadsIt(options.sourceText ? *options.sourceText : readSource(options.source));
    if (!options.forceIncludes.empty()) {
        std::string prelude;
        for (const auto& file : options.forceIncludes) prelude += "#include \"" + file.generic_string() + "\"\n";
        text = prelude + "#line 1\n" + text;
    }
    requireMacroNames(options, sourceName);
    if (options.boundPreprocessing) {
        // The whole front end first in a child with limits: glslang loops on a macro that
        // expands without bound, and crashes on some sources (an unnamed entry-point parameter).
        auto trial = options;
        trial.boundPreprocessing = false;
        trial.sourceText = text;
        runInBoundedChild([&] { return (compileHlsl(trial), std::string()); }, {}, sourceName, "glslang",
                          " on this source (a macro that expands without bound, an #include that never ends, "
                          "or a glslang bug)");
    }
    IncludeResolver preprocessedIncludes(options.includeDirs, &options.virtualFiles);
    preprocessedIncludes.addSource(sourceName, text);
    const auto lowered = lower(options, sourceName, preprocess(options, sourceName, text, preprocessedIncludes));
    // A shader that needs no lowering is parsed from its own text, as it was written.
    const std::string& parsed = lowered.changed ? lowered.text : text;
    const ShaderStage stage = stageOrReportSyntax(lowered.text, options, sourceName, parsed, lowered.changed);
    const EShLanguage language = toGlslang(stage);

    IncludeResolver ownIncludes(options.includeDirs, &options.virtualFiles);
    ownIncludes.addSource(sourceName, text);
    IncludeResolver& includes = lowered.changed ? preprocessedIncludes : ownIncludes;
    ConfiguredShader configured(language, options, sourceName, parsed, lowered.changed);
    if (!configured.shader.parse(GetDefaultResources(), kHlslVersion, false, messagesFor(options), includes))
        failWith(configured.shader.getInfoLog(), includes, sourceName, "compilation failed");

    glslang::TProgram program;
    program.addShader(&configured.shader);
    if (!program.link(messagesFor(options)))
        failWith(program.getInfoLog(), includes, sourceName, "link failed");

    glslang::TIntermediate& intermediate = *program.getIntermediate(language);

    HlslRegisterResolver resolver(intermediate, options.bindingShifts, attributeBindings(lowered.vulkan), sourceName);
    const bool mapped = program.mapIO(&resolver);
    if (resolver.error()) throw CompileError(*resolver.error());
    if (!mapped) failWith(program.getInfoLog(), includes, sourceName, "resource binding failed");

    FrontendResult result{{}, stage, resolver.registers(), includes.includedFiles(), {},
                          attributeImageFormats(lowered.vulkan, sourceName), {}, {}, {}};
    glslang::SpvOptions spvOptions;
    spvOptions.disableOptimizer = true;
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(intermediate, result.spirv, &logger, &spvOptions);
    result.warnings = lowered.warnings;
    result.kitEdits = lowered.edits;
    result.packedMembers = lowered.packedMembers;
    result.bindingShifts = resolver.shifts();
    for (auto& warning : parseGlslangLog(configured.shader.getInfoLog(), includes, sourceName).warnings)
        result.warnings.push_back(std::move(warning));
    const std::string spvMessages = logger.getAllMessages();
    if (!spvMessages.empty()) result.warnings.push_back(sourceName + ": warning: " + spvMessages);
    return result;
}

} // namespace iblkit::compiler
