#include "run_file.hpp"

#include "spirv_varyings.hpp"
#include "vertex_format.hpp"

#include <set>

namespace iblkit::run {
namespace {

using nlohmann::json;

constexpr uint64_t kLargestCount = 0xFFFFFFFFu;

class GraphicsReader {
public:
    GraphicsReader(const JsonFields& fields, std::filesystem::path folder) : fields_(fields), folder_(std::move(folder)) {}

    GraphicsSpec read(const json& root) const {
        GraphicsSpec spec;
        for (const char* key : {"vertex", "pixel"})
            if (!root.contains(key)) fields_.fail("the run file", std::string("a draw needs \"vertex\" and \"pixel\": \"") + key + "\" is missing");
        spec.vertex = stage(root, "vertex");
        spec.pixel = stage(root, "pixel");
        if (root.contains("vertex_input"))
            for (const auto& [semantic, object] : fields_.object(root.at("vertex_input"), "vertex_input").items())
                spec.vertexInput.push_back(vertexInput(semantic, object));
        if (root.contains("indices"))
            for (const auto index : fields_.wholeArray(root.at("indices"), "indices", 1, kLargestCount, 0, kLargestCount))
                spec.indices.push_back(uint32_t(index));
        if (root.contains("draw")) spec.draw = draw(root.at("draw"));
        if (!root.contains("targets")) fields_.fail("the run file", "a draw needs \"targets\"");
        readTargets(root.at("targets"), spec);
        if (root.contains("raster")) {
            const auto& raster = fields_.objectOf(root.at("raster"), "raster", {"cull", "front"});
            if (raster.contains("cull")) spec.cull = fields_.oneOf(raster.at("cull"), "raster.cull", {"none", "front", "back"});
            if (raster.contains("front"))
                spec.front = fields_.oneOf(raster.at("front"), "raster.front", {"clockwise", "counter_clockwise"});
        }
        if (root.contains("viewport")) spec.viewport = viewport(root.at("viewport"));
        return spec;
    }

private:
    StageSpec stage(const json& root, const char* key) const {
        const std::string where = key;
        const auto& object = fields_.objectOf(root.at(key), where, {"shader", "entry"});
        StageSpec stage;
        if (!object.contains("shader") && !root.contains("shader"))
            fields_.fail(where, "needs a \"shader\" (or the run file one for both stages)");
        stage.shader = folder_ / fields_.text(object.contains("shader") ? object.at("shader") : root.at("shader"),
                                              object.contains("shader") ? where + ".shader" : "shader");
        if (!object.contains("entry")) fields_.fail(where, "needs an \"entry\"");
        stage.entry = fields_.text(object.at("entry"), where + ".entry");
        return stage;
    }

    VertexInputSpec vertexInput(const std::string& semantic, const json& value) const {
        const std::string where = "vertex_input." + semantic;
        const auto& object = fields_.objectOf(value, where, {"format", "values", "file"});
        VertexInputSpec input;
        input.semantic = semantic;
        if (!object.contains("format")) fields_.fail(where, "needs a \"format\" (" + vertexFormatNames() + ")");
        input.format = fields_.text(object.at("format"), where + ".format");
        if (!findVertexFormat(input.format))
            fields_.fail(where + ".format", "'" + input.format + "' is not a vertex format (" + vertexFormatNames() + ")");
        if (object.contains("values") == object.contains("file")) fields_.fail(where, "needs one of \"values\" and \"file\"");
        if (object.contains("values")) input.source.values = fields_.numberArray(object.at("values"), where + ".values");
        else input.source.file = folder_ / fields_.text(object.at("file"), where + ".file");
        return input;
    }

    DrawSpec draw(const json& value) const {
        const auto& object = fields_.objectOf(value, "draw", {"vertices", "instances", "first_vertex", "first_instance",
                                                               "base_vertex", "topology"});
        DrawSpec draw;
        if (object.contains("vertices")) draw.vertices = uint32_t(fields_.whole(object.at("vertices"), "draw.vertices", 1, kLargestCount));
        if (object.contains("instances")) draw.instances = uint32_t(fields_.whole(object.at("instances"), "draw.instances", 1, kLargestCount));
        if (object.contains("first_vertex"))
            draw.firstVertex = uint32_t(fields_.whole(object.at("first_vertex"), "draw.first_vertex", 0, kLargestCount));
        if (object.contains("first_instance"))
            draw.firstInstance = uint32_t(fields_.whole(object.at("first_instance"), "draw.first_instance", 0, kLargestCount));
        if (object.contains("base_vertex")) {
            const double base = fields_.number(object.at("base_vertex"), "draw.base_vertex");
            if (base != std::floor(base) || std::abs(base) > 0x7FFFFFFF) fields_.fail("draw.base_vertex", "a 32-bit integer");
            draw.baseVertex = int32_t(base);
        }
        if (object.contains("topology"))
            draw.topology = fields_.oneOf(object.at("topology"), "draw.topology",
                                          {"triangle_list", "triangle_strip", "line_list", "line_strip", "point_list"});
        return draw;
    }

    std::pair<uint32_t, uint32_t> size(const json& object, const std::string& where) const {
        const auto size = fields_.wholeArray(object.at("size"), where + ".size", 1, 2, 1, 16384);
        return {uint32_t(size[0]), uint32_t(size.size() > 1 ? size[1] : size[0])};
    }

    void readTargets(const json& value, GraphicsSpec& spec) const {
        std::set<std::string> semantics;
        for (const auto& [name, object] : fields_.object(value, "targets").items()) {
            const std::string where = "targets." + name;
            const std::string semantic = compiler::canonicalSemantic(name);
            if (!semantics.insert(semantic).second) fields_.fail(where, "names the same target as another key");
            if (semantic == "SV_DEPTH") {
                spec.depth = depth(name, object);
                continue;
            }
            if (semantic.rfind("SV_TARGET", 0) != 0 || semantic.size() != 10 || semantic[9] < '0' || semantic[9] > '7')
                fields_.fail(where, "a target is SV_Target0 to SV_Target7, or SV_Depth");
            spec.targets.push_back(target(name, object));
        }
        if (spec.targets.empty() && !spec.depth) fields_.fail("targets", "is empty");
    }

    TargetSpec target(const std::string& name, const json& value) const {
        const std::string where = "targets." + name;
        const auto& object = fields_.objectOf(value, where, {"format", "size", "clear", "blend"});
        TargetSpec target;
        target.name = name;
        if (!object.contains("format")) fields_.fail(where, "needs a \"format\"");
        target.format = fields_.text(object.at("format"), where + ".format");
        if (!object.contains("size")) fields_.fail(where, "needs a \"size\"");
        std::tie(target.width, target.height) = size(object, where);
        if (object.contains("clear")) {
            const auto clear = fields_.numbers(object.at("clear"), where + ".clear");
            if (clear.size() != 1 && clear.size() != 4) fields_.fail(where + ".clear", "one number or four");
            for (size_t i = 0; i < 4; ++i) target.clear[i] = clear[clear.size() == 1 ? 0 : i];
        }
        if (object.contains("blend"))
            target.blend = fields_.oneOf(object.at("blend"), where + ".blend", {"none", "alpha", "premultiplied", "additive"});
        return target;
    }

    DepthSpec depth(const std::string& name, const json& value) const {
        const std::string where = "targets." + name;
        const auto& object = fields_.objectOf(value, where, {"format", "size", "clear", "test", "write"});
        DepthSpec depth;
        depth.name = name;
        if (object.contains("format")) fields_.oneOf(object.at("format"), where + ".format", {"d32f", "D32_SFLOAT"});
        if (object.contains("size")) std::tie(depth.width, depth.height) = size(object, where);
        if (object.contains("clear")) {
            depth.clear = fields_.number(object.at("clear"), where + ".clear");
            if (depth.clear < 0 || depth.clear > 1) fields_.fail(where + ".clear", "depth runs from 0 to 1");
        }
        if (object.contains("test"))
            depth.test = fields_.oneOf(object.at("test"), where + ".test",
                                       {"never", "less", "equal", "less_equal", "greater", "not_equal", "greater_equal", "always"});
        if (object.contains("write")) depth.write = fields_.flag(object.at("write"), where + ".write");
        return depth;
    }

    std::array<double, 6> viewport(const json& value) const {
        const auto numbers = fields_.numberArray(value, "viewport");
        if (numbers.size() != 4 && numbers.size() != 6) fields_.fail("viewport", "takes [x, y, width, height] or [x, y, width, height, min depth, max depth]");
        std::array<double, 6> viewport{0, 0, 0, 0, 0, 1};
        std::copy(numbers.begin(), numbers.end(), viewport.begin());
        if (viewport[2] <= 0 || viewport[3] <= 0) fields_.fail("viewport", "width and height must be positive");
        if (viewport[4] < 0 || viewport[5] > 1 || viewport[4] > viewport[5]) fields_.fail("viewport", "depths run from 0 to 1, min first");
        return viewport;
    }

    const JsonFields& fields_;
    std::filesystem::path folder_;
};

} // namespace

GraphicsSpec readGraphics(const JsonFields& fields, const nlohmann::json& root, const std::filesystem::path& folder) {
    return GraphicsReader(fields, folder).read(root);
}

} // namespace iblkit::run
