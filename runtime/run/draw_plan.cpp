#include "run_plan.hpp"

#include "run_error.hpp"
#include "spirv_varyings.hpp"
#include "vulkan_error.hpp"

#include <algorithm>

namespace iblkit::run {
namespace {

[[noreturn]] void refuseDraw(const RunSpec& spec, const std::string& why) {
    throw RunError(spec.runFile.string() + ": error: " + why);
}

std::string typeName(const compiler::Varying& varying) {
    return varying.componentType + (varying.components > 1 ? std::to_string(varying.components) : "");
}

std::string listOf(const std::vector<const compiler::Varying*>& varyings) {
    std::string names;
    for (const auto* varying : varyings) names += (names.empty() ? "" : ", ") + varying->semantic + " (" + typeName(*varying) + ")";
    return names.empty() ? "none" : names;
}

bool kindsMatch(const std::string& componentType, vulkan::ComponentKind kind) {
    using K = vulkan::ComponentKind;
    if (componentType == "float") return kind == K::Float || kind == K::UNorm;
    return (componentType == "uint" && kind == K::UInt) || (componentType == "int" && kind == K::SInt);
}

std::string kindName(vulkan::ComponentKind kind) {
    using K = vulkan::ComponentKind;
    return kind == K::UInt ? "uint" : kind == K::SInt ? "int" : "float";
}

} // namespace

std::vector<compiler::Varying> inputSlots(const compiler::ShaderReflection& vertex) {
    std::vector<compiler::Varying> slots;
    for (const auto& varying : vertex.varyings) {
        if (!varying.input || !varying.builtIn.empty()) continue;
        const size_t digits = varying.semantic.find_last_not_of("0123456789") + 1;
        const std::string name = varying.semantic.substr(0, digits);
        const uint32_t index = digits < varying.semantic.size() ? uint32_t(std::stoul(varying.semantic.substr(digits))) : 0;
        for (uint32_t row = 0; row < varying.locations; ++row) {
            auto slot = varying;
            slot.locations = 1;
            slot.location = varying.location + int32_t(row);
            slot.semantic = varying.locations > 1 ? name + std::to_string(index + row) : varying.semantic;
            slots.push_back(std::move(slot));
        }
    }
    return slots;
}

namespace {

// The vertex shader's inputs other than system values, each bound to a vertex_input entry.
std::vector<AttributePlan> planAttributes(const RunSpec& spec, const compiler::ShaderReflection& vertex, uint32_t& vertexCount) {
    const auto slots = inputSlots(vertex);
    std::vector<const compiler::Varying*> inputs;
    for (const auto& slot : slots) inputs.push_back(&slot);
    std::vector<AttributePlan> plans;
    for (const auto& given : spec.graphics->vertexInput) {
        const std::string where = "vertex_input." + given.semantic;
        const auto semantic = compiler::canonicalSemantic(given.semantic);
        const auto input = std::find_if(inputs.begin(), inputs.end(), [&](const auto* v) { return v->semantic == semantic; });
        if (input == inputs.end())
            refuseDraw(spec, where + ": the vertex shader has no input of that semantic (it reads: " + listOf(inputs) + ")");
        const auto& format = *findVertexFormat(given.format);
        if (!kindsMatch((*input)->componentType, format.kind))
            refuseDraw(spec, where + ".format: the shader reads " + typeName(**input) + ", the format gives " + kindName(format.kind) + "s");
        const auto& component = format.componentFormat();
        std::vector<double> values = given.source.values;
        if (!given.source.file.empty()) values = readValues(given.source.file, component);
        for (size_t i = 0; i < values.size(); ++i)
            if (const auto problem = vulkan::integerValueProblem(component, values[i]); !problem.empty())
                refuseDraw(spec, where + ".values[" + std::to_string(i) + "]: " + problem);
        if (values.empty() || values.size() % format.components != 0)
            refuseDraw(spec, where + ": " + std::to_string(values.size()) + " values are not whole vertices of " +
                           std::to_string(format.components) + " components");
        const auto count = uint32_t(values.size() / format.components);
        if (!plans.empty() && count != vertexCount)
            refuseDraw(spec, where + ": " + std::to_string(count) + " vertices, where " + plans[0].semantic + " has " + std::to_string(vertexCount));
        vertexCount = count;
        AttributePlan plan{given.semantic, uint32_t((*input)->location), &format, std::vector<std::byte>(values.size() * format.bytesPerComponent)};
        vulkan::encodeTexels(component, values, plan.bytes);
        plans.push_back(std::move(plan));
    }
    for (const auto* input : inputs)
        if (std::none_of(plans.begin(), plans.end(), [&](const auto& p) { return compiler::canonicalSemantic(p.semantic) == input->semantic; }))
            refuseDraw(spec, "vertex_input: the vertex shader reads " + input->semantic + " (" + typeName(*input) +
                           "), which vertex_input does not give");
    return plans;
}

const vulkan::TexelFormat& targetFormat(const RunSpec& spec, const std::string& name, const std::string& format) {
    try {
        return vulkan::texelFormatNamed(format);
    } catch (const vulkan::VulkanError& error) {
        refuseDraw(spec, "targets." + name + ".format: " + error.what());
    }
}

void planTargets(const RunSpec& spec, const compiler::ShaderReflection& pixel, DrawPlan& plan) {
    std::vector<const compiler::Varying*> outputs;
    for (const auto& varying : pixel.varyings)
        if (!varying.input && varying.builtIn.empty()) outputs.push_back(&varying);
    const auto& graphics = *spec.graphics;
    for (const auto& target : graphics.targets) {
        const std::string where = "targets." + target.name;
        const auto semantic = compiler::canonicalSemantic(target.name);
        const auto output = std::find_if(outputs.begin(), outputs.end(), [&](const auto* v) { return v->semantic == semantic; });
        if (output == outputs.end())
            refuseDraw(spec, where + ": the pixel shader has no output of that semantic (it writes: " + listOf(outputs) + ")");
        const auto& format = targetFormat(spec, target.name, target.format);
        if (format.depth()) refuseDraw(spec, where + ".format: a depth format is SV_Depth's");
        if (!kindsMatch((*output)->componentType, format.kind))
            refuseDraw(spec, where + ".format: the shader writes " + typeName(**output) + ", " + std::string(format.name) + " holds " +
                           kindName(format.kind) + "s");
        plan.targets.push_back({&target, uint32_t((*output)->location), ImageShape{&format, target.width, target.height, 1, 1, false}});
    }
    for (const auto* output : outputs)
        if (std::none_of(plan.targets.begin(), plan.targets.end(), [&](const auto& t) { return compiler::canonicalSemantic(t.spec->name) == output->semantic; }))
            refuseDraw(spec, "targets: the pixel shader writes " + output->semantic + " (" + typeName(*output) + "), which targets does not give");
    for (const auto& target : plan.targets)
        if (target.shape.width != plan.targets[0].shape.width || target.shape.height != plan.targets[0].shape.height)
            refuseDraw(spec, "targets." + target.spec->name + ".size: every target of a draw has one size");
    if (graphics.depth) {
        auto depth = ImageShape{&vulkan::texelFormatNamed("D32_SFLOAT"), graphics.depth->width, graphics.depth->height, 1, 1, false};
        if (!plan.targets.empty() && depth.width == 0) {
            depth.width = plan.targets[0].shape.width;
            depth.height = plan.targets[0].shape.height;
        }
        if (depth.width == 0) refuseDraw(spec, "targets." + graphics.depth->name + ": needs a \"size\" when there is no colour target");
        if (!plan.targets.empty() && (depth.width != plan.targets[0].shape.width || depth.height != plan.targets[0].shape.height))
            refuseDraw(spec, "targets." + graphics.depth->name + ".size: every target of a draw has one size");
        plan.depth = depth;
    }
}

} // namespace

DrawPlan planDraw(const RunSpec& spec, const RunPrograms& programs) {
    const auto& graphics = *spec.graphics;
    DrawPlan plan;
    plan.spec = &graphics;
    uint32_t vertexCount = 0;
    plan.attributes = planAttributes(spec, programs.vertex->reflection, vertexCount);
    planTargets(spec, programs.pixel->reflection, plan);
    const auto& draw = graphics.draw;
    if (!graphics.indices.empty()) {
        const uint64_t first = draw.firstVertex, drawn = draw.vertices.value_or(uint32_t(graphics.indices.size() - std::min<size_t>(first, graphics.indices.size())));
        if (first + drawn > graphics.indices.size() || drawn == 0)
            refuseDraw(spec, "draw: indices " + std::to_string(first) + " to " + std::to_string(first + drawn) + " of " +
                           std::to_string(graphics.indices.size()) + " given");
        plan.count = uint32_t(drawn);
        if (!plan.attributes.empty())
            for (size_t i = first; i < first + drawn; ++i) {
                const int64_t vertex = int64_t(graphics.indices[i]) + draw.baseVertex;
                if (vertex < 0 || vertex >= int64_t(vertexCount))
                    refuseDraw(spec, "indices[" + std::to_string(i) + "]: vertex " + std::to_string(vertex) + " of " + std::to_string(vertexCount));
            }
    } else {
        if (!draw.vertices && plan.attributes.empty())
            refuseDraw(spec, "draw: give \"vertices\" when no vertex_input tells how many (a shader that makes them from SV_VertexID)");
        plan.count = draw.vertices.value_or(vertexCount > draw.firstVertex ? vertexCount - draw.firstVertex : 0);
        if (!plan.attributes.empty() && (uint64_t(draw.firstVertex) + plan.count > vertexCount || plan.count == 0))
            refuseDraw(spec, "draw: vertices " + std::to_string(draw.firstVertex) + " to " + std::to_string(uint64_t(draw.firstVertex) + plan.count) +
                           " of the " + std::to_string(vertexCount) + " vertex_input gives");
    }
    return plan;
}

} // namespace iblkit::run
