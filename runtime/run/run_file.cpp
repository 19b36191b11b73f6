#include "run_file.hpp"

#include "json_fields.hpp"
#include "error_words.hpp"
#include "run_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace iblkit::run {
namespace {

using nlohmann::json;

constexpr std::array kDrawKeys{"vertex", "pixel", "vertex_input", "indices", "draw", "targets", "raster", "viewport"};

constexpr uint64_t kLargest32 = 0xFFFFFFFFu;

class Reader {
public:
    explicit Reader(std::filesystem::path file) : fields_(file), folder_(file.parent_path()) {}

    RunSpec read(const json& root, const std::filesystem::path& file) const {
        fields_.objectOf(root, "the run file", {"shader", "entry", "include", "defines", "image_formats", "enable_16bit_types",
                                                "hlsl_version", "specialization",
                                                "push_constants", "resources", "dispatch", "expect", "save", "comment",
                                                "vertex", "pixel", "vertex_input", "indices", "draw", "targets", "raster",
                                                "viewport", "cross_api"});
        RunSpec spec;
        spec.runFile = file;
        const bool draws = std::any_of(kDrawKeys.begin(), kDrawKeys.end(), [&](const char* key) { return root.contains(key); });
        if (draws && root.contains("dispatch"))
            fields_.fail("the run file", "mixes a dispatch with a draw: give \"dispatch\" or \"vertex\" and \"pixel\", not both");
        if (draws) {
            if (root.contains("entry")) fields_.fail("entry", "a draw takes each stage's entry in \"vertex\" and \"pixel\"");
            spec.graphics = readGraphics(fields_, root, folder_);
            spec.shader = spec.graphics->vertex.shader;
            spec.entry = spec.graphics->vertex.entry;
        } else {
            if (!root.contains("shader")) fields_.fail("the run file", "needs a \"shader\"");
            spec.shader = path(root.at("shader"), "shader");
            if (root.contains("entry")) spec.entry = fields_.text(root.at("entry"), "entry");
        }
        if (root.contains("include"))
            for (const auto& dir : fields_.textArray(root.at("include"), "include")) spec.includeDirs.push_back(folder_ / dir);
        if (root.contains("defines")) spec.defines = fields_.textMap(root.at("defines"), "defines");
        if (root.contains("image_formats")) spec.imageFormats = fields_.textMap(root.at("image_formats"), "image_formats");
        readHlslLanguage(fields_, root, "", spec.enable16BitTypes, spec.hlslVersion);
        if (root.contains("specialization"))
            for (const auto& [name, value] : fields_.object(root.at("specialization"), "specialization").items())
                spec.specialization[name] = fields_.number(value, "specialization." + name);
        if (root.contains("push_constants"))
            for (const auto& [member, value] : fields_.object(root.at("push_constants"), "push_constants").items())
                spec.pushConstants[member] = fields_.numbers(value, "push_constants." + member);
        if (root.contains("resources"))
            for (const auto& [name, object] : fields_.object(root.at("resources"), "resources").items())
                for (auto& each : resourceOrElements(name, object)) spec.resources.push_back(std::move(each));
        if (!draws) readDispatch(root, spec);
        if (root.contains("expect")) {
            const auto& expectations = fields_.array(root.at("expect"), "expect");
            for (size_t index = 0; index < expectations.size(); ++index)
                spec.expectations.push_back(expectation(expectations[index], index));
        }
        if (root.contains("cross_api")) spec.crossApi = tolerance(root.at("cross_api"), "cross_api");
        if (root.contains("save"))
            for (const auto& [name, file] : fields_.object(root.at("save"), "save").items())
                spec.saves[name] = path(file, "save." + name);
        return spec;
    }

private:
    std::filesystem::path path(const json& value, const std::string& where) const {
        return folder_ / fields_.text(value, where);
    }

    void readDispatch(const json& root, RunSpec& spec) const {
        if (!root.contains("dispatch")) fields_.fail("the run file", "needs a \"dispatch\" (a compute run) or \"vertex\" and \"pixel\" (a draw)");
        const auto& dispatch = fields_.objectOf(root.at("dispatch"), "dispatch", {"threads", "groups"});
        if (dispatch.contains("threads") == dispatch.contains("groups"))
            fields_.fail("dispatch", "needs exactly one of \"threads\" and \"groups\"");
        const bool threads = dispatch.contains("threads");
        const std::string where = threads ? "dispatch.threads" : "dispatch.groups";
        auto counts = fields_.wholeArray(dispatch.at(threads ? "threads" : "groups"), where, 1, 3, 0, kLargest32);
        counts.resize(3, 1);
        const std::array<uint32_t, 3> triple{uint32_t(counts[0]), uint32_t(counts[1]), uint32_t(counts[2])};
        (threads ? spec.threads : spec.groups) = triple;
    }

    // At most one of fill, values and file.
    ValueSource source(const json& object, const std::string& where) const {
        ValueSource source;
        if (int(object.contains("fill")) + int(object.contains("values")) + int(object.contains("file")) > 1)
            fields_.fail(where, "takes one of \"fill\", \"values\" and \"file\", not several");
        if (object.contains("fill")) source.fill = fields_.numbers(object.at("fill"), where + ".fill");
        if (object.contains("values")) source.values = fields_.numberArray(object.at("values"), where + ".values");
        if (object.contains("file")) source.file = path(object.at("file"), where + ".file");
        return source;
    }

    void readBuffer(const json& object, const std::string& where, ResourceSpec& spec) const {
        fields_.objectOf(object, where, {"kind", "type", "count", "size_bytes", "fill", "values", "file"});
        if (object.contains("type")) spec.elementType = fields_.oneOf(object.at("type"), where + ".type", {"float", "uint", "int"});
        if (object.contains("count") && object.contains("size_bytes"))
            fields_.fail(where, "takes \"count\" or \"size_bytes\", not both");
        if (object.contains("count")) spec.count = fields_.whole(object.at("count"), where + ".count", 1, kLargest32);
        if (object.contains("size_bytes"))
            spec.sizeBytes = fields_.whole(object.at("size_bytes"), where + ".size_bytes", 4, kLargest32);
    }

    void readImage(const json& object, const std::string& where, ResourceSpec& spec) const {
        fields_.objectOf(object, where, {"kind", "dim", "format", "size", "layers", "mips", "mip", "fill", "values", "file"});
        if (!object.contains("format")) fields_.fail(where, "needs a \"format\"");
        spec.format = fields_.text(object.at("format"), where + ".format");
        if (spec.format.empty()) fields_.fail(where + ".format", "must not be empty");
        spec.dimension = spec.kind == "cube" ? "cube" : "2d";
        if (object.contains("dim")) spec.dimension = fields_.oneOf(object.at("dim"), where + ".dim", {"2d", "2d_array", "cube"});
        if (!object.contains("size")) fields_.fail(where, "needs a \"size\"");
        const auto size = fields_.wholeArray(object.at("size"), where + ".size", 1, 2, 1, kLargest32);
        spec.width = uint32_t(size[0]);
        spec.height = uint32_t(size.size() > 1 ? size[1] : size[0]);
        spec.layers = spec.dimension == "cube" ? 6 : 1;
        if (object.contains("layers") && spec.dimension != "cube")
            spec.layers = uint32_t(fields_.whole(object.at("layers"), where + ".layers", 1, kLargest32));
        if (object.contains("mips") && object.at("mips").is_string()) {
            if (object.at("mips") != "full") fields_.fail(where + ".mips", "a number or \"full\"");
            spec.mips = 0; // the full chain, worked out when the size is known
        } else if (object.contains("mips")) {
            spec.mips = uint32_t(fields_.whole(object.at("mips"), where + ".mips", 1, 32));
        }
        if (object.contains("mip")) spec.mip = uint32_t(fields_.whole(object.at("mip"), where + ".mip", 0, 31));
    }

    // A resource, or an array of them: {"kind": K, "elements": [{...}, ...]}, each element a
    // resource of kind K named "NAME[i]".
    std::vector<ResourceSpec> resourceOrElements(const std::string& name, const json& object) const {
        const std::string where = "resources." + name;
        if (!object.is_object() || !object.contains("elements")) {
            auto spec = resource(name, object);
            spec.binding = name;
            return {std::move(spec)};
        }
        fields_.objectOf(object, where, {"kind", "elements"});
        if (!object.contains("kind")) fields_.fail(where, "needs a \"kind\"");
        const auto& elements = fields_.array(object.at("elements"), where + ".elements");
        if (elements.empty()) fields_.fail(where + ".elements", "is empty");
        std::vector<ResourceSpec> specs;
        for (size_t i = 0; i < elements.size(); ++i) {
            const std::string elementName = name + "[" + std::to_string(i) + "]";
            json element = fields_.object(elements[i], where + ".elements[" + std::to_string(i) + "]");
            if (element.contains("kind")) fields_.fail(where + ".elements[" + std::to_string(i) + "]", "takes its kind from the array");
            element["kind"] = object.at("kind");
            auto spec = resource(elementName, element);
            spec.binding = name;
            spec.element = uint32_t(i);
            specs.push_back(std::move(spec));
        }
        return specs;
    }

    ResourceSpec resource(const std::string& name, const json& object) const {
        const std::string where = "resources." + name;
        fields_.object(object, where);
        if (!object.contains("kind")) fields_.fail(where, "needs a \"kind\"");
        ResourceSpec spec;
        spec.name = name;
        spec.kind = fields_.oneOf(object.at("kind"), where + ".kind", {"buffer", "cbuffer", "image", "cube", "storage_image", "sampler"});
        if (spec.kind == "buffer") {
            readBuffer(object, where, spec);
        } else if (spec.kind == "cbuffer") {
            fields_.objectOf(object, where, {"kind", "members"});
            if (object.contains("members"))
                for (const auto& [member, value] : fields_.object(object.at("members"), where + ".members").items())
                    spec.members[member] = fields_.numbers(value, where + ".members." + member);
        } else if (spec.kind == "sampler") {
            fields_.objectOf(object, where, {"kind", "filter", "mipmap", "address"});
            if (object.contains("filter")) spec.filter = fields_.oneOf(object.at("filter"), where + ".filter", {"nearest", "linear"});
            if (object.contains("mipmap")) spec.mipmap = fields_.oneOf(object.at("mipmap"), where + ".mipmap", {"nearest", "linear"});
            if (object.contains("address"))
                spec.address = fields_.oneOf(object.at("address"), where + ".address", {"clamp", "repeat", "mirror"});
        } else {
            readImage(object, where, spec);
        }
        spec.initial = source(object, where);
        return spec;
    }

    Expectation expectation(const json& object, size_t index) const {
        const std::string where = "expect[" + std::to_string(index) + "]";
        fields_.objectOf(object, where, {"resource", "mip", "layer", "fill", "values", "file", "range", "tolerance"});
        if (!object.contains("resource")) fields_.fail(where, "needs a \"resource\"");
        Expectation expectation;
        expectation.resource = fields_.text(object.at("resource"), where + ".resource");
        if (object.contains("mip")) expectation.mip = uint32_t(fields_.whole(object.at("mip"), where + ".mip", 0, 31));
        if (object.contains("layer"))
            expectation.layer = uint32_t(fields_.whole(object.at("layer"), where + ".layer", 0, kLargest32));
        expectation.expected = source(object, where);
        if (object.contains("range")) {
            const auto range = fields_.numberArray(object.at("range"), where + ".range");
            if (range.size() != 2 || range[0] > range[1]) fields_.fail(where + ".range", "takes [min, max]");
            expectation.range = std::array<double, 2>{range[0], range[1]};
        }
        if (expectation.expected.given() == expectation.range.has_value())
            fields_.fail(where, "needs exactly one of \"fill\", \"values\", \"file\" or \"range\"");
        if (object.contains("tolerance")) expectation.tolerance = tolerance(object.at("tolerance"), where + ".tolerance");
        return expectation;
    }

    Tolerance tolerance(const json& value, const std::string& where) const {
        const auto& object = fields_.objectOf(value, where, {"abs", "rel", "ulp"});
        const auto bound = [&](const char* key) { return fields_.nonNegative(object.at(key), where + "." + key); };
        Tolerance tolerance;
        if (object.contains("abs")) tolerance.absolute = bound("abs");
        if (object.contains("rel")) tolerance.relative = bound("rel");
        if (object.contains("ulp")) tolerance.ulp = bound("ulp");
        return tolerance;
    }

    JsonFields fields_;
    std::filesystem::path folder_;
};

} // namespace

void readHlslLanguage(const JsonFields& fields, const nlohmann::json& object, const std::string& prefix,
                      bool& enable16BitTypes, lowering::HlslVersion& version) {
    if (object.contains("enable_16bit_types"))
        enable16BitTypes = fields.flag(object.at("enable_16bit_types"), prefix + "enable_16bit_types");
    if (object.contains("hlsl_version"))
        version = fields.oneOf(object.at("hlsl_version"), prefix + "hlsl_version", {"2018", "2021"}) == "2018"
                      ? lowering::HlslVersion::Hlsl2018
                      : lowering::HlslVersion::Hlsl2021;
}

RunSpec readRunFile(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
        throw RunError(path.string() + ": error: the run file is not a regular file (a folder, a device or a pipe)");
    std::ifstream stream(path);
    if (!stream) throw RunError(path.string() + ": error: cannot read the run file");
    std::ostringstream text;
    text << stream.rdbuf();
    return parseRunFile(text.str(), path);
}

RunSpec parseRunFile(const std::string& text, const std::filesystem::path& path) {
    const Reader reader(path);
    try {
        return reader.read(json::parse(text), path);
    } catch (const json::exception& error) {
        throw RunError(path.string() + ": error: " + files::jsonErrorInWords(error));
    }
}

} // namespace iblkit::run
