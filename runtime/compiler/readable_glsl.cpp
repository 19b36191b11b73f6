#include "readable_glsl.hpp"

#include "compile_error.hpp"
#include "glsl_frontend.hpp"

#include <spirv_cross/spirv_glsl.hpp>

#include <regex>
#include <sstream>

namespace iblkit::compiler {
namespace {

// glslang's reader's message on the form, or "" when it reads it.
std::string readBackError(const std::string& source, ShaderStage stage, bool vulkanSemantics, const std::string& name) {
    try {
        if (vulkanSemantics) compileVulkanGlsl(source, stage, name);
        else compileOpenGlGlsl(source, stage, name);
        return "";
    } catch (const CompileError& error) {
        return error.what();
    }
}

// "Possible extensions include: GL_EXT_geometry_shader GL_OES_geometry_shader": the first one.
std::vector<std::string> namedExtensions(const std::string& message) {
    static const std::regex kExtension(R"(extensions? include:?\s*(GL_[A-Za-z0-9_]+))");
    std::smatch match;
    if (std::regex_search(message, match, kExtension)) return {match[1].str()};
    static const std::regex kRequires(R"(requires? (?:extension )?\"?(GL_[A-Za-z0-9_]+))");
    if (std::regex_search(message, match, kRequires)) return {match[1].str()};
    return {};
}

// The line of glslang's message that says what, without its "ERROR: file:line: " prefix.
std::string whatItSays(const std::string& message) {
    std::istringstream lines(message);
    for (std::string line; std::getline(lines, line);) {
        const auto at = line.find("ERROR: ");
        if (at == std::string::npos) continue;
        line = line.substr(at + 7);
        static const std::regex kPlace(R"(^.*?:\d+: )");
        return std::regex_replace(line, kPlace, "", std::regex_constants::format_first_only);
    }
    return message.substr(0, message.find('\n'));
}

std::string compiledAt(spirv_cross::CompilerGLSL& compiler, uint32_t version) {
    auto options = compiler.get_common_options();
    options.version = version;
    compiler.set_common_options(options);
    return compiler.compile();
}

} // namespace

ReadableGlsl readableGlsl(spirv_cross::CompilerGLSL& compiler, ShaderStage stage, bool es, bool vulkanSemantics,
                          const std::string& formName, const std::string& sourceName) {
    const std::string readerName = sourceName + " (" + formName + " form)";
    std::string error;
    ReadableGlsl form;
    for (const uint32_t version : es ? std::vector<uint32_t>{310, 320} : std::vector<uint32_t>{450}) {
        form.version = version;
        form.source = compiledAt(compiler, version);
        error = readBackError(form.source, stage, vulkanSemantics, readerName);
        if (error.empty()) return form;
    }
    // Each extension glslang names, one at a time, while it names a new one.
    for (auto extensions = namedExtensions(error); !extensions.empty(); extensions = namedExtensions(error)) {
        if (std::find(form.extensions.begin(), form.extensions.end(), extensions[0]) != form.extensions.end()) break;
        form.extensions.push_back(extensions[0]);
        compiler.require_extension(extensions[0]);
        form.source = compiler.compile();
        error = readBackError(form.source, stage, vulkanSemantics, readerName);
        if (error.empty()) return form;
    }
    const std::string versions = es ? "ESSL 3.10 or 3.20" : "GLSL 4.50";
    throw CompileError(sourceName + ": error: " + formName + " cannot express the shader: glslang, its reference compiler, " +
                       "does not read the form at " + versions + (form.extensions.empty() ? "" : " with the extensions it names") +
                       " (" + whatItSays(error) + "), so it is not written\n" + error);
}

} // namespace iblkit::compiler
