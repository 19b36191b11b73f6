#include "codebase_manifest.hpp"

#include "json_fields.hpp"
#include "porting_error.hpp"
#include "run_error.hpp"
#include "register_binding.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace iblkit::porting {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Manifests are small: a larger file is not one, and is not read whole.
constexpr uintmax_t kLargestManifestBytes = 16u << 20;

struct ProfilePrefix {
    const char* prefix;
    ProfileStage stage;
};
constexpr ProfilePrefix kProfilePrefixes[] = {
    {"vs", ProfileStage::Vertex}, {"ps", ProfileStage::Pixel},         {"cs", ProfileStage::Compute},
    {"gs", ProfileStage::Geometry}, {"hs", ProfileStage::Hull},        {"ds", ProfileStage::Domain},
    {"lib", ProfileStage::RayTracing}, {"ms", ProfileStage::Mesh},     {"as", ProfileStage::Amplification},
};

std::optional<compiler::ShaderStage> kitStage(ProfileStage stage) {
    using compiler::ShaderStage;
    switch (stage) {
    case ProfileStage::Vertex: return ShaderStage::Vertex;
    case ProfileStage::Pixel: return ShaderStage::Fragment;
    case ProfileStage::Compute: return ShaderStage::Compute;
    case ProfileStage::Geometry: return ShaderStage::Geometry;
    case ProfileStage::Hull: return ShaderStage::TessControl;
    case ProfileStage::Domain: return ShaderStage::TessEvaluation;
    default: return std::nullopt;
    }
}

std::vector<std::string> words(const std::string& flag) {
    std::istringstream stream(flag);
    std::vector<std::string> parts;
    for (std::string part; stream >> part;) parts.push_back(part);
    return parts;
}

uint32_t wholeNumber(const std::string& text, const std::string& flag, const std::string& where) {
    uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw PortingError(where + ": '" + flag + "': '" + text + "' is not a whole number");
    return value;
}

// Flags that change nothing the kit compiles: optimization, validation, output and debug
// switches, and the target API's own (the kit always writes SPIR-V for Vulkan 1.1).
bool changesNothing(const std::string& name) {
    static const std::regex kNoEffect(
        R"(-(O[0-4d]|Od|spirv|fspv-.*|fvk-use-.*|fvk-invert-y|fvk-support-nonzero-base-instance|Gis|Gfa|Gfp|Ges|Gec|)"
        R"(all-resources-bound|res-may-alias|WX|W.*|Zi|Zss|Zsb|Qembed_debug|Qstrip_.*|nologo|no-warnings|Vd|)"
        R"(Ni|Vi|Zpr?c?|denorm|ftime-report|Frs|Fre|Fc|Fo|Fh|Fd|Vn|P|Cc|enable-payload-qualifiers|)"
        R"(disable-payload-qualifiers|flegacy-macro-expansion|fcgl|fdiagnostics-.*|D3DCOMPILE_.*|)"
        R"(auto-binding-space|default-linkage|exports|export-shaders-only|force-rootsig-ver|rootsig-define|)"
        R"(HV|enable-16bit-types|strict|no-legacy-cbuf-layout|pack-optimized|pack-prefix-stable|Zpr|Zpc)$)");
    return std::regex_match(name, kNoEffect);
}

} // namespace

std::string_view buildTargetName(BuildTarget target) {
    switch (target) {
    case BuildTarget::D3D11: return "d3d11";
    case BuildTarget::D3D12: return "d3d12";
    case BuildTarget::Vulkan: return "vulkan";
    }
    return "";
}

std::string_view profileStageName(ProfileStage stage) {
    switch (stage) {
    case ProfileStage::Vertex: return "vertex";
    case ProfileStage::Pixel: return "pixel";
    case ProfileStage::Compute: return "compute";
    case ProfileStage::Geometry: return "geometry";
    case ProfileStage::Hull: return "hull";
    case ProfileStage::Domain: return "domain";
    case ProfileStage::RayTracing: return "ray tracing";
    case ProfileStage::Mesh: return "mesh";
    case ProfileStage::Amplification: return "amplification";
    }
    return "";
}

std::optional<ShaderProfile> parseShaderProfile(const std::string& text) {
    static const std::regex kProfile(R"(([a-z]+)_([1-6])_([0-9x]))");
    std::smatch match;
    if (!std::regex_match(text, match, kProfile)) return std::nullopt;
    for (const auto& [prefix, stage] : kProfilePrefixes)
        if (match[1] == prefix)
            return ShaderProfile{text, stage, match[2].str()[0] - '0', match[3] == "x" ? 0 : match[3].str()[0] - '0'};
    return std::nullopt;
}

bool CodeBaseConfiguration::refusedStage() const { return !kitStage(profile.stage); }

bool applyCompilerFlag(const std::string& flag, compiler::CompileOptions& options, const std::string& where) {
    const auto parts = words(flag);
    if (parts.empty()) throw PortingError(where + ": an empty flag");
    const std::string& name = parts[0];
    if (name == "-HV") {
        if (parts.size() != 2 || (parts[1] != "2016" && parts[1] != "2017" && parts[1] != "2018" && parts[1] != "2021"))
            throw PortingError(where + ": '" + flag + "': -HV takes 2016, 2017, 2018 or 2021");
        options.hlslVersion = parts[1] == "2021" ? lowering::HlslVersion::Hlsl2021 : lowering::HlslVersion::Hlsl2018;
        return true;
    }
    if (name == "-enable-16bit-types") return options.enable16BitTypes = true;
    if (name == "-Zpr" || name == "-Zpc") {
        options.rowMajorByDefault = name == "-Zpr";
        return true;
    }
    static const std::regex kShift(R"(-fvk-([btsu])-shift)");
    std::smatch match;
    if (std::regex_match(name, match, kShift)) {
        if (parts.size() != 3) throw PortingError(where + ": '" + flag + "': " + name + " takes a shift and a space (or 'all')");
        const auto registerClass = *compiler::registerClassFromLetter(match[1].str()[0]);
        options.bindingShifts.set(registerClass, wholeNumber(parts[1], flag, where));
        return true;
    }
    if (!changesNothing(name)) throw PortingError(where + ": '" + flag + "' is not a DXC or fxc flag the kit knows");
    return false;
}

namespace {

class CodeBaseReader {
public:
    CodeBaseReader(const fs::path& file, const fs::path& folder, CodeBaseFolder kind)
        : file_(file), root_(folder), kind_(kind), fields_(file) {}

    CodeBase read() {
        const json top = parse();
        fields_.objectOf(top, "the manifest", {"name", "repository", "commit", "description", "requires", "target",
                                               "include_dirs", "defines", "flags", "generated_files", "force_includes", "configurations"});
        const auto name = required(top, "name");
        if (kind_ == CodeBaseFolder::HoldsCodeBasesByName) root_ /= name;
        CodeBase codeBase{file_, root_, name, required(top, "repository"), required(top, "commit"),
                          top.contains("description") ? fields_.text(top["description"], "description") : "", {}, {}};
        if (top.contains("requires")) readRequirements(top["requires"], codeBase);
        defaults_ = sharedSettings(top, "");
        // Headers the code base's build writes as it compiles (a macro list, a binding table),
        // by the name they are included by: the build's own, so the manifest holds their text.
        if (top.contains("generated_files")) generatedFiles_ = fields_.textMap(top["generated_files"], "generated_files");
        // Files the build puts before every source (an engine's prelude of helper functions).
        if (top.contains("force_includes"))
            for (const auto& file : fields_.textArray(top["force_includes"], "force_includes"))
                forceIncludes_.push_back(fs::absolute(resolve(file, "force_includes")));
        if (!top.contains("configurations")) fields_.fail("the manifest", "needs \"configurations\"");
        const auto& list = fields_.array(top["configurations"], "configurations");
        std::set<std::string> labels;
        for (size_t i = 0; i < list.size(); ++i) {
            auto configuration = readConfiguration(list[i], "configurations[" + std::to_string(i) + "]");
            if (!labels.insert(configuration.label).second)
                fields_.fail("configurations[" + std::to_string(i) + "]", "'" + configuration.label +
                                                                            "' is another configuration's too: give one a \"name\"");
            codeBase.configurations.push_back(std::move(configuration));
        }
        return codeBase;
    }

private:
    struct Settings {
        BuildTarget target = BuildTarget::D3D12;
        std::vector<std::string> includeDirs;
        std::map<std::string, std::string> defines;
        std::vector<std::string> flags;
    };

    json parse() const {
        std::error_code error;
        if (!fs::is_regular_file(file_, error)) throw PortingError(file_.string() + ": error: no such manifest file");
        if (fs::file_size(file_, error) > kLargestManifestBytes)
            throw PortingError(file_.string() + ": error: larger than 16 MiB: not a code base's manifest");
        std::ifstream stream(file_);
        const json top = json::parse(stream, nullptr, false);
        if (top.is_discarded()) throw PortingError(file_.string() + ": error: not valid JSON");
        return top;
    }

    std::string required(const json& object, const char* key) const {
        if (!object.contains(key)) fields_.fail("the manifest", std::string("needs \"") + key + "\"");
        const auto text = fields_.text(object[key], key);
        if (text.empty()) fields_.fail(key, "is empty");
        return text;
    }

    void readRequirements(const json& value, CodeBase& codeBase) const {
        const auto& list = fields_.array(value, "requires");
        for (size_t i = 0; i < list.size(); ++i) {
            const auto where = "requires[" + std::to_string(i) + "]";
            const auto& entry = fields_.objectOf(list[i], where, {"name", "repository", "commit"});
            for (const char* key : {"name", "repository", "commit"})
                if (!entry.contains(key)) fields_.fail(where, std::string("needs \"") + key + "\"");
            codeBase.requirements.push_back({fields_.text(entry["name"], where + ".name"),
                                             fields_.text(entry["repository"], where + ".repository"),
                                             fields_.text(entry["commit"], where + ".commit")});
        }
        requirements_ = codeBase.requirements;
    }

    Settings sharedSettings(const json& object, const std::string& prefix) const {
        Settings settings = prefix.empty() ? Settings{} : defaults_;
        if (object.contains("target")) {
            const auto name = fields_.oneOf(object["target"], prefix + "target", {"d3d11", "d3d12", "vulkan"});
            settings.target = name == "d3d11" ? BuildTarget::D3D11 : name == "d3d12" ? BuildTarget::D3D12 : BuildTarget::Vulkan;
        }
        if (object.contains("include_dirs"))
            for (auto& dir : fields_.textArray(object["include_dirs"], prefix + "include_dirs")) settings.includeDirs.push_back(dir);
        if (object.contains("defines"))
            for (auto& [name, value] : fields_.textMap(object["defines"], prefix + "defines")) settings.defines[name] = value;
        if (object.contains("flags"))
            for (auto& flag : fields_.textArray(object["flags"], prefix + "flags")) settings.flags.push_back(flag);
        return settings;
    }

    // A manifest path on disk: relative to the root, or "@OTHER/..." to a required code base's.
    fs::path resolve(const std::string& path, const std::string& where) const {
        if (path.empty()) fields_.fail(where, "is empty");
        if (fs::path(path).is_absolute()) fields_.fail(where, "'" + path + "' is absolute: write it relative to the code base");
        if (path[0] != '@') return root_ / path;
        const auto slash = path.find('/');
        const auto other = path.substr(1, slash == std::string::npos ? std::string::npos : slash - 1);
        if (std::none_of(requirements_.begin(), requirements_.end(), [&](const auto& r) { return r.name == other; }))
            fields_.fail(where, "'" + path + "' names '" + other + "', which \"requires\" does not list");
        const fs::path otherRoot = root_.parent_path() / other;
        return slash == std::string::npos ? otherRoot : otherRoot / path.substr(slash + 1);
    }

    CodeBaseConfiguration readConfiguration(const json& value, const std::string& where) const {
        const auto& entry = fields_.objectOf(value, where, {"name", "file", "entry", "profile", "target", "include_dirs",
                                                            "defines", "flags"});
        for (const char* key : {"file", "entry", "profile"})
            if (!entry.contains(key)) fields_.fail(where, std::string("needs \"") + key + "\"");
        CodeBaseConfiguration configuration;
        configuration.file = fields_.text(entry["file"], where + ".file");
        configuration.entry = fields_.text(entry["entry"], where + ".entry");
        const auto profileText = fields_.text(entry["profile"], where + ".profile");
        const auto profile = parseShaderProfile(profileText);
        if (!profile) fields_.fail(where + ".profile", "'" + profileText + "' is not a profile (vs_6_0, ps_5_0, cs_6_2, lib_6_3, ...)");
        configuration.profile = *profile;
        const Settings settings = sharedSettings(entry, where + ".");
        configuration.target = settings.target;
        configuration.label = entry.contains("name") ? fields_.text(entry["name"], where + ".name")
                                                     : fs::path(configuration.file).filename().string() + ":" +
                                                           configuration.entry + ":" + profileText;
        auto& options = configuration.options;
        options.source = resolve(configuration.file, where + ".file");
        options.entryPoint = configuration.entry;
        options.stage = kitStage(profile->stage);
        options.virtualFiles = generatedFiles_;
        options.forceIncludes = forceIncludes_;
        options.boundPreprocessing = false; // each configuration runs in a bounded child of its own
        for (const auto& dir : settings.includeDirs) options.includeDirs.push_back(resolve(dir, where + ".include_dirs"));
        // A bare -D NAME defines NAME as 1 in DXC and fxc, as in C compilers.
        for (const auto& [name, value] : settings.defines) options.defines[name] = value.empty() ? "1" : value;
        // A Direct3D build below Shader Model 6 is fxc's, whose language is HLSL 2018's; DXC's
        // default is HLSL 2021 from its 1.7 on.
        const bool fxc = profile->major < 6 && settings.target != BuildTarget::Vulkan;
        options.hlslVersion = fxc ? lowering::HlslVersion::Hlsl2018 : lowering::HlslVersion::Hlsl2021;
        for (const auto& flag : settings.flags)
            if (!applyCompilerFlag(flag, options, file_.string() + ": " + where + ".flags"))
                configuration.ignoredFlags.push_back(flag);
        return configuration;
    }

    fs::path file_, root_;
    CodeBaseFolder kind_;
    run::JsonFields fields_;
    Settings defaults_;
    std::map<std::string, std::string> generatedFiles_;
    std::vector<fs::path> forceIncludes_;
    mutable std::vector<CodeBaseRequirement> requirements_;
};

} // namespace

namespace {

// "-DNAME=V", "-D NAME", "-I DIR", "-IDIR", or a flag with the arguments that follow it.
void applyListArguments(const std::vector<std::string>& parts, const fs::path& folder, CodeBaseConfiguration& configuration,
                        const std::string& where) {
    auto& options = configuration.options;
    for (size_t i = 3; i < parts.size(); ++i) {
        std::string part = parts[i];
        const bool define = part.rfind("-D", 0) == 0, include = part.rfind("-I", 0) == 0;
        if (define || include) {
            std::string value = part.substr(2);
            if (value.empty()) {
                if (i + 1 >= parts.size()) throw PortingError(where + ": '" + part + "' needs a value");
                value = parts[++i];
            }
            if (include) options.includeDirs.push_back(folder / value);
            else {
                const auto equals = value.find('=');
                options.defines[value.substr(0, equals)] = equals == std::string::npos ? "1" : value.substr(equals + 1);
            }
            continue;
        }
        // A flag's arguments are the words that follow it up to the next flag.
        while (i + 1 < parts.size() && parts[i + 1][0] != '-') part += " " + parts[++i];
        if (!applyCompilerFlag(part, options, where)) configuration.ignoredFlags.push_back(part);
    }
}

} // namespace

CodeBase readEntryList(const fs::path& listFile, const fs::path& folder) {
    std::ifstream stream(listFile);
    if (!stream) throw PortingError(listFile.string() + ": error: cannot read the list of entries");
    CodeBase codeBase{listFile, folder, folder.filename().string(), "", "", "", {}, {}};
    if (codeBase.name.empty()) codeBase.name = fs::absolute(folder).parent_path().filename().string();
    std::set<std::string> labels;
    std::string line;
    for (size_t number = 1; std::getline(stream, line); ++number) {
        const auto where = listFile.string() + ":" + std::to_string(number);
        const auto parts = words(line.substr(0, line.find('#')));
        if (parts.empty()) continue;
        if (parts.size() < 3) throw PortingError(where + ": error: a line is FILE ENTRY PROFILE [-D NAME=VALUE] [-I DIR] [flags]");
        const auto profile = parseShaderProfile(parts[2]);
        if (!profile) throw PortingError(where + ": error: '" + parts[2] + "' is not a profile (vs_6_0, ps_5_0, cs_6_2, ...)");
        CodeBaseConfiguration configuration;
        configuration.file = parts[0];
        configuration.entry = parts[1];
        configuration.profile = *profile;
        configuration.label = parts[0] + ":" + parts[1] + ":" + parts[2];
        if (!labels.insert(configuration.label).second) configuration.label += "#" + std::to_string(number);
        configuration.options.source = folder / parts[0];
        configuration.options.entryPoint = parts[1];
        configuration.options.stage = kitStage(profile->stage);
        configuration.options.hlslVersion = profile->major < 6 ? lowering::HlslVersion::Hlsl2018 : lowering::HlslVersion::Hlsl2021;
        applyListArguments(parts, folder, configuration, where + ": error");
        configuration.target = std::count(configuration.ignoredFlags.begin(), configuration.ignoredFlags.end(), "-spirv")
                                   ? BuildTarget::Vulkan
                                   : BuildTarget::D3D12;
        codeBase.configurations.push_back(std::move(configuration));
    }
    if (codeBase.configurations.empty()) throw PortingError(listFile.string() + ": error: lists no entries");
    return codeBase;
}

CodeBase readCodeBaseManifest(const fs::path& manifestFile, const fs::path& folder, CodeBaseFolder kind) {
    try {
        return CodeBaseReader(manifestFile, folder, kind).read();
    } catch (const run::RunError& error) { // JsonFields' words, naming the file and the key
        throw PortingError(error.what());
    }
}

} // namespace iblkit::porting
