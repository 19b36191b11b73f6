#include "run_file.hpp"

#include "run_error.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <sstream>

namespace iblkit::run {
namespace {

using nlohmann::json;

// The value under key, or an empty object or array when absent (never a temporary to iterate).
const json& memberOr(const json& object, const char* key, const json& empty) {
    return object.contains(key) ? object.at(key) : empty;
}
const json kNoObject = json::object();
const json kNoArray = json::array();

class Reader {
public:
    explicit Reader(std::filesystem::path file) : file_(std::move(file)), folder_(file_.parent_path()) {}

    [[noreturn]] void fail(const std::string& where, const std::string& why) const {
        throw RunError(file_.string() + ": error: " + where + ": " + why);
    }

    std::filesystem::path path(const json& value) const { return folder_ / value.get<std::string>(); }

    void allowOnly(const json& object, const std::string& where, std::initializer_list<const char*> keys) const {
        if (!object.is_object()) fail(where, "must be an object");
        const std::set<std::string> allowed(keys.begin(), keys.end());
        for (const auto& [key, value] : object.items())
            if (!allowed.count(key)) fail(where, "unknown key '" + key + "'");
    }

    static std::vector<double> numbers(const json& value) {
        if (value.is_number()) return {value.get<double>()};
        return value.get<std::vector<double>>();
    }

    std::array<uint32_t, 3> triple(const json& value, const std::string& where) const {
        auto list = value.get<std::vector<int64_t>>();
        if (list.empty() || list.size() > 3) fail(where, "takes 1 to 3 numbers");
        list.resize(3, 1);
        std::array<uint32_t, 3> out{};
        for (int i = 0; i < 3; ++i) {
            if (list[i] < 0) fail(where, "negative size");
            out[i] = static_cast<uint32_t>(list[i]);
        }
        return out;
    }

    ValueSource source(const json& object) const {
        ValueSource source;
        if (object.contains("fill")) source.fill = numbers(object.at("fill"));
        if (object.contains("values")) source.values = object.at("values").get<std::vector<double>>();
        if (object.contains("file")) source.file = path(object.at("file"));
        return source;
    }

    ResourceSpec resource(const std::string& name, const json& object) const {
        const std::string where = "resources." + name;
        if (!object.is_object() || !object.contains("kind")) fail(where, "needs a \"kind\"");
        ResourceSpec spec;
        spec.name = name;
        spec.kind = object.at("kind").get<std::string>();
        if (spec.kind == "buffer") {
            allowOnly(object, where, {"kind", "type", "count", "size_bytes", "fill", "values", "file"});
            spec.elementType = object.value("type", "float");
            spec.count = object.value("count", size_t(0));
            spec.sizeBytes = object.value("size_bytes", size_t(0));
        } else if (spec.kind == "cbuffer") {
            allowOnly(object, where, {"kind", "members"});
            for (const auto& [member, value] : memberOr(object, "members", kNoObject).items())
                spec.members[member] = numbers(value);
        } else if (spec.kind == "image" || spec.kind == "cube" || spec.kind == "storage_image") {
            allowOnly(object, where, {"kind", "dim", "format", "size", "layers", "mips", "mip", "fill", "values", "file"});
            spec.format = object.value("format", "");
            if (spec.format.empty()) fail(where, "needs a \"format\"");
            spec.dimension = spec.kind == "cube" ? "cube" : object.value("dim", "2d");
            if (spec.dimension != "2d" && spec.dimension != "2d_array" && spec.dimension != "cube")
                fail(where, "unknown dim '" + spec.dimension + "' (2d, 2d_array, cube)");
            if (!object.contains("size")) fail(where, "needs a \"size\"");
            const auto size = triple(object.at("size"), where + ".size");
            spec.width = size[0];
            spec.height = object.at("size").size() > 1 ? size[1] : size[0];
            spec.layers = spec.dimension == "cube" ? 6 : object.value("layers", 1u);
            if (object.contains("mips") && object.at("mips").is_string()) {
                if (object.at("mips") != "full") fail(where + ".mips", "a number or \"full\"");
                spec.mips = 0; // the full chain, worked out when the size is known
            } else {
                spec.mips = object.value("mips", 1u);
            }
            spec.mip = object.value("mip", 0u);
        } else if (spec.kind == "sampler") {
            allowOnly(object, where, {"kind", "filter", "mipmap", "address"});
            spec.filter = object.value("filter", "linear");
            spec.mipmap = object.value("mipmap", "linear");
            spec.address = object.value("address", "clamp");
        } else {
            fail(where, "unknown kind '" + spec.kind + "' (buffer, cbuffer, image, cube, storage_image, sampler)");
        }
        spec.initial = source(object);
        return spec;
    }

    Expectation expectation(const json& object, size_t index) const {
        const std::string where = "expect[" + std::to_string(index) + "]";
        allowOnly(object, where, {"resource", "mip", "layer", "fill", "values", "file", "range", "tolerance"});
        if (!object.contains("resource")) fail(where, "needs a \"resource\"");
        Expectation expectation;
        expectation.resource = object.at("resource").get<std::string>();
        if (object.contains("mip")) expectation.mip = object.at("mip").get<uint32_t>();
        if (object.contains("layer")) expectation.layer = object.at("layer").get<uint32_t>();
        expectation.expected = source(object);
        if (object.contains("range")) {
            const auto range = object.at("range").get<std::vector<double>>();
            if (range.size() != 2 || range[0] > range[1]) fail(where + ".range", "takes [min, max]");
            expectation.range = std::array<double, 2>{range[0], range[1]};
        }
        if (expectation.expected.given() == expectation.range.has_value())
            fail(where, "needs exactly one of \"fill\", \"values\", \"file\" or \"range\"");
        if (object.contains("tolerance")) {
            const auto& tolerance = object.at("tolerance");
            allowOnly(tolerance, where + ".tolerance", {"abs", "rel", "ulp"});
            if (tolerance.contains("abs")) expectation.tolerance.absolute = tolerance.at("abs").get<double>();
            if (tolerance.contains("rel")) expectation.tolerance.relative = tolerance.at("rel").get<double>();
            if (tolerance.contains("ulp")) expectation.tolerance.ulp = tolerance.at("ulp").get<double>();
        }
        return expectation;
    }

    RunSpec read(const json& root) const {
        allowOnly(root, "the run file", {"shader", "entry", "include", "defines", "image_formats", "specialization",
                                         "push_constants", "resources", "dispatch", "expect", "save", "comment"});
        RunSpec spec;
        spec.runFile = file_;
        if (!root.contains("shader")) fail("the run file", "needs a \"shader\"");
        spec.shader = path(root.at("shader"));
        spec.entry = root.value("entry", "main");
        for (const auto& dir : memberOr(root, "include", kNoArray)) spec.includeDirs.push_back(path(dir));
        spec.defines = root.value("defines", std::map<std::string, std::string>{});
        spec.imageFormats = root.value("image_formats", std::map<std::string, std::string>{});
        spec.specialization = root.value("specialization", std::map<std::string, double>{});
        for (const auto& [member, value] : memberOr(root, "push_constants", kNoObject).items())
            spec.pushConstants[member] = numbers(value);
        for (const auto& [name, object] : memberOr(root, "resources", kNoObject).items())
            spec.resources.push_back(resource(name, object));
        if (!root.contains("dispatch")) fail("the run file", "needs a \"dispatch\"");
        const auto& dispatch = root.at("dispatch");
        allowOnly(dispatch, "dispatch", {"threads", "groups"});
        if (dispatch.contains("threads") == dispatch.contains("groups"))
            fail("dispatch", "needs exactly one of \"threads\" and \"groups\"");
        if (dispatch.contains("threads")) spec.threads = triple(dispatch.at("threads"), "dispatch.threads");
        else spec.groups = triple(dispatch.at("groups"), "dispatch.groups");
        size_t index = 0;
        for (const auto& object : memberOr(root, "expect", kNoArray)) spec.expectations.push_back(expectation(object, index++));
        for (const auto& [name, file] : memberOr(root, "save", kNoObject).items()) spec.saves[name] = path(file);
        return spec;
    }

private:
    std::filesystem::path file_;
    std::filesystem::path folder_;
};

} // namespace

RunSpec readRunFile(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
        throw RunError(path.string() + ": error: the run file is not a regular file (a folder, a device or a pipe)");
    std::ifstream stream(path);
    if (!stream) throw RunError(path.string() + ": error: cannot read the run file");
    std::ostringstream text;
    text << stream.rdbuf();
    const Reader reader(path);
    try {
        return reader.read(json::parse(text.str()));
    } catch (const json::parse_error& error) {
        throw RunError(path.string() + ": error: not valid JSON: " + error.what());
    } catch (const json::exception& error) {
        throw RunError(path.string() + ": error: " + error.what());
    }
}

} // namespace iblkit::run
