#include "corpus_manifest.hpp"

#include "json_fields.hpp"
#include "kit_edits.hpp"
#include "porting_error.hpp"
#include "run_error.hpp"
#include "run_executor.hpp"
#include "run_file.hpp"
#include "shader_stage.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>

namespace iblkit::porting {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::map<std::string, FeatureGroup, std::less<>> kGroups{{"sm5", FeatureGroup::ShaderModel5},
                                                               {"sm6", FeatureGroup::ShaderModel6},
                                                               {"hlsl2021", FeatureGroup::Hlsl2021},
                                                               {"vulkan", FeatureGroup::VulkanAttributes}};

compiler::CrossTarget crossTargetNamed(const run::JsonFields& fields, const json& value, const std::string& where) {
    const auto name = fields.text(value, where);
    for (const auto target : compiler::kCrossTargets)
        if (compiler::crossTargetName(target) == name) return target;
    fields.fail(where, "'" + name + "' is not a form (glsl, essl, msl, hlsl, vulkan-glsl, vulkan-essl)");
}

class ManifestReader {
public:
    explicit ManifestReader(const fs::path& folder) : folder_(folder), file_(folder / "corpus.json"), fields_(file_) {}

    CorpusManifest read() {
        std::ifstream stream(file_);
        if (!stream) throw PortingError(file_.string() + ": error: cannot read the corpus manifest");
        const json root = json::parse(stream, nullptr, false);
        if (root.is_discarded()) throw PortingError(file_.string() + ": error: not valid JSON");
        fields_.objectOf(root, "the manifest", {"comment", "features", "compile"});
        const json compile = root.contains("compile") ? fields_.object(root.at("compile"), "compile") : json::object();
        CorpusManifest manifest{folder_, {}, {}};
        if (!root.contains("features")) fields_.fail("the manifest", "needs \"features\"");
        const auto& features = fields_.array(root.at("features"), "features");
        for (size_t i = 0; i < features.size(); ++i) {
            manifest.features.push_back(feature(features[i], i));
            const auto& id = manifest.features.back().id;
            if (std::count_if(manifest.features.begin(), manifest.features.end(), [&](const auto& f) { return f.id == id; }) > 1)
                fields_.fail("features[" + std::to_string(i) + "].id", "'" + id + "' is another feature's id too");
        }
        for (const auto& feature : manifest.features)
            if (std::none_of(manifest.shaders.begin(), manifest.shaders.end(), [&](const auto& s) { return s.name == feature.shader; }))
                manifest.shaders.push_back(shader(feature.shader, compile));
        for (const auto& [name, options] : compile.items())
            if (std::none_of(manifest.features.begin(), manifest.features.end(), [&](const auto& f) { return f.shader == name; }))
                fields_.fail("compile." + name, "names a shader no feature uses");
        return manifest;
    }

private:
    CorpusFeature feature(const json& value, size_t index) const {
        const std::string where = "features[" + std::to_string(index) + "]";
        fields_.objectOf(value, where, {"id", "group", "feature", "shader", "kit", "refused_forms", "unread_forms",
                                           "error", "warning"});
        for (const char* key : {"id", "group", "feature", "shader"})
            if (!value.contains(key)) fields_.fail(where, std::string("needs \"") + key + "\"");
        CorpusFeature feature;
        feature.id = fields_.text(value.at("id"), where + ".id");
        feature.group = kGroups.find(fields_.oneOf(value.at("group"), where + ".group", {"sm5", "sm6", "hlsl2021", "vulkan"}))->second;
        feature.description = fields_.text(value.at("feature"), where + ".feature");
        feature.shader = fields_.text(value.at("shader"), where + ".shader");
        if (value.contains("kit")) feature.kitEdits = fields_.textArray(value.at("kit"), where + ".kit");
        for (const auto& edit : feature.kitEdits)
            if (compiler::describeKitEdit(edit).empty()) fields_.fail(where + ".kit", "'" + edit + "' is not one of the kit's edits");
        if (value.contains("refused_forms"))
            for (const auto& form : fields_.array(value.at("refused_forms"), where + ".refused_forms"))
                feature.refusedForms.insert(crossTargetNamed(fields_, form, where + ".refused_forms"));
        if (value.contains("unread_forms"))
            for (const auto& form : fields_.array(value.at("unread_forms"), where + ".unread_forms"))
                feature.unreadForms.insert(crossTargetNamed(fields_, form, where + ".unread_forms"));
        if (value.contains("error")) feature.error = fields_.text(value.at("error"), where + ".error");
        if (value.contains("warning")) feature.warning = fields_.text(value.at("warning"), where + ".warning");
        if (!fs::is_regular_file(folder_ / feature.shader)) fields_.fail(where + ".shader", "no such file: " + feature.shader);
        const bool expectsOutcomes = !feature.kitEdits.empty() || !feature.refusedForms.empty() || !feature.unreadForms.empty() ||
                                     !feature.warning.empty();
        if (!feature.error.empty() && expectsOutcomes)
            fields_.fail(where, "a refused feature (\"error\") has no edits, forms or warnings to show");
        return feature;
    }

    CorpusShader shader(const std::string& name, const json& compile) const {
        CorpusShader shader{name, {}, {}};
        std::error_code error;
        const fs::path source = folder_ / name;
        const fs::path runFile = fs::path(source).replace_extension(".run.json");
        if (fs::exists(runFile)) {
            if (compile.contains(name)) fields_.fail("compile." + name, "a shader with a run file is compiled as its run file says");
            shader.runFile = runFile;
            shader.options = run::compileOptionsOf(run::readRunFile(runFile));
            if (!fs::equivalent(shader.options.source, source, error))
                fields_.fail(runFile.filename().string(), "runs " + shader.options.source.string() + ", not " + name);
            return shader;
        }
        shader.options.source = source;
        if (!compile.contains(name)) return shader;
        const std::string where = "compile." + name;
        const auto& options = fields_.objectOf(compile.at(name), where, {"entry", "stage", "enable_16bit_types", "hlsl_version"});
        if (options.contains("entry")) shader.options.entryPoint = fields_.text(options.at("entry"), where + ".entry");
        if (options.contains("stage")) {
            shader.options.stage = compiler::parseStageName(fields_.text(options.at("stage"), where + ".stage"));
            if (!shader.options.stage) fields_.fail(where + ".stage", "is not a stage (vert, frag, comp, ...)");
        }
        run::readHlslLanguage(fields_, options, where + ".", shader.options.enable16BitTypes, shader.options.hlslVersion);
        return shader;
    }

    fs::path folder_, file_;
    run::JsonFields fields_;
};

} // namespace

std::string_view groupTitle(FeatureGroup group) {
    switch (group) {
    case FeatureGroup::ShaderModel5: return "Shader Model 5.x";
    case FeatureGroup::ShaderModel6: return "Shader Model 6.x";
    case FeatureGroup::Hlsl2021: return "HLSL 2021";
    case FeatureGroup::VulkanAttributes: return "Vulkan attributes";
    }
    return "";
}

CorpusManifest readCorpusManifest(const fs::path& folder) {
    try {
        return ManifestReader(folder).read();
    } catch (const run::RunError& error) {
        throw PortingError(error.what());
    }
}

} // namespace iblkit::porting
