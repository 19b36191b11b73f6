#include "run_plan.hpp"

#include "atomic_output.hpp"
#include "block_writer.hpp"
#include "compiler.hpp"
#include "data_file.hpp"
#include "graphics_program.hpp"
#include "hlsl_frontend.hpp"
#include "image_save.hpp"
#include "run_error.hpp"
#include "run_executor.hpp"
#include "spirv_tools.hpp"
#include "vulkan_error.hpp"

#include <algorithm>
#include <cstring>
#include <regex>

namespace iblkit::run {
namespace {

[[noreturn]] void refuse(const RunSpec& spec, const std::string& why) {
    throw RunError(spec.runFile.string() + ": error: " + why);
}

ShaderProgram loadSpirv(const RunSpec& spec) {
    if (!spec.includeDirs.empty() || !spec.defines.empty() || !spec.imageFormats.empty() || spec.enable16BitTypes ||
        spec.hlslVersion != lowering::HlslVersion::Hlsl2021)
        throw RunError(spec.runFile.string() + ": error: \"include\", \"defines\", \"image_formats\", "
                       "\"enable_16bit_types\" and \"hlsl_version\" apply to HLSL shaders, not to " + spec.shader.string());
    const std::string bytes = compiler::readSource(spec.shader);
    if (bytes.size() % 4 != 0 || bytes.size() < 20)
        throw RunError(spec.shader.string() + ": error: not a SPIR-V module (" + std::to_string(bytes.size()) + " bytes)");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    // SPIRV-Cross (the reflection) and the driver trust their input: a damaged module crashes them.
    compiler::validateSpirv(words, spec.shader.string());
    return {words, words, compiler::reflectSpirv(words, spec.entry, spec.shader.string()), spec.shader.string()};
}

ShaderProgram compileStage(const RunSpec& spec, const StageSpec& stage, compiler::ShaderStage kind) {
    auto options = compileOptionsOf(spec);
    options.source = stage.shader;
    options.sourceText = stage.text;
    options.entryPoint = stage.entry;
    options.stage = kind;
    options.boundPreprocessing = true;
    auto shader = compiler::compileShader(options);
    return {shader.spirv, shader.namedSpirv, shader.reflection, stage.shader.string()};
}

} // namespace

RunPrograms loadPrograms(const RunSpec& spec) {
    RunPrograms programs;
    if (!spec.graphics) {
        if (spec.shader.extension() == ".spv") {
            programs.compute = loadSpirv(spec);
        } else {
            auto options = compileOptionsOf(spec);
            options.boundPreprocessing = true;
            auto shader = compiler::compileShader(options);
            programs.compute = ShaderProgram{shader.spirv, shader.namedSpirv, shader.reflection, spec.shader.string()};
        }
        programs.resources = programs.compute->reflection;
        return programs;
    }
    for (const auto* stage : {&spec.graphics->vertex, &spec.graphics->pixel})
        if (stage->shader.extension() == ".spv")
            refuse(spec, "a draw's shaders are HLSL: SPIR-V keeps no semantics to bind vertex_input and targets by (" +
                           stage->shader.string() + ")");
    programs.vertex = compileStage(spec, spec.graphics->vertex, compiler::ShaderStage::Vertex);
    programs.pixel = compileStage(spec, spec.graphics->pixel, compiler::ShaderStage::Fragment);
    try {
        programs.resources = vulkan::mergeStageReflections(programs.vertex->reflection, programs.pixel->reflection);
    } catch (const vulkan::VulkanError& error) {
        refuse(spec, std::string("resources: ") + error.what());
    }
    return programs;
}

namespace {

ShaderProgram throughHlslForm(const RunSpec& spec, const ShaderProgram& program) {
    const auto form = compiler::crossCompile(program.namedSpirv, program.reflection, compiler::CrossTarget::Hlsl, program.sourceName);
    compiler::CompileOptions options;
    options.source = program.sourceName + " (hlsl form)";
    options.sourceText = form.source;
    // The form holds push constants as Direct3D's root constants, a cbuffer without a register;
    // for Vulkan a port marks it [[vk::push_constant]].
    if (program.reflection.pushConstantSize > 0)
        options.sourceText = std::regex_replace(form.source, std::regex(R"(\ncbuffer (\w+)\n)"), "\n[[vk::push_constant]] cbuffer $1\n");
    options.stage = program.reflection.stage;
    options.entryPoint = program.reflection.entryPoint;
    options.enable16BitTypes = spec.enable16BitTypes;
    // The form declares a storage image by its texel type alone, as Direct3D binds it; for Vulkan
    // a port gives the format, as --image-format does.
    for (const auto& resource : program.reflection.resources)
        if (resource.kind == compiler::ResourceKind::StorageImage && resource.format != "unknown" && resource.location.count == 1)
            options.imageFormats[resource.name] = resource.format;
    // Specialization constants are macros in the form, SPIRV-Cross's SPIRV_CROSS_CONSTANT_ID_n.
    for (const auto& constant : program.reflection.specializationConstants)
        if (const auto value = spec.specialization.find(constant.name); value != spec.specialization.end())
            options.defines["SPIRV_CROSS_CONSTANT_ID_" + std::to_string(constant.constantId)] =
                constant.type == "float" ? std::to_string(value->second) + "f"
                : constant.type == "int" ? std::to_string(int64_t(value->second))
                                         : std::to_string(uint64_t(value->second)) + "u";
    auto shader = compiler::compileShader(options);
    return {shader.spirv, shader.namedSpirv, shader.reflection, options.source.string()};
}

} // namespace

RunPrograms hlslFormPrograms(const RunSpec& spec, const RunPrograms& programs) {
    if (spec.shader.extension() == ".spv" && !spec.graphics) throw RunError("a SPIR-V shader has no HLSL source to compare a form with");
    RunPrograms forms;
    if (programs.compute) {
        forms.compute = throughHlslForm(spec, *programs.compute);
        forms.resources = forms.compute->reflection;
        return forms;
    }
    forms.vertex = throughHlslForm(spec, *programs.vertex);
    forms.pixel = throughHlslForm(spec, *programs.pixel);
    forms.resources = vulkan::mergeStageReflections(forms.vertex->reflection, forms.pixel->reflection);
    return forms;
}

const vulkan::TexelFormat& bufferFormat(const ResourceSpec& spec) {
    if (spec.elementType == "uint") return vulkan::texelFormatNamed("R32_UINT");
    if (spec.elementType == "int") return vulkan::texelFormatNamed("R32_SINT");
    return vulkan::texelFormatNamed("R32_SFLOAT");
}

std::vector<std::filesystem::path> inputFiles(const RunSpec& spec) {
    std::vector<std::filesystem::path> inputs{spec.runFile, spec.shader};
    if (spec.graphics) {
        inputs.push_back(spec.graphics->pixel.shader);
        for (const auto& input : spec.graphics->vertexInput)
            if (!input.source.file.empty()) inputs.push_back(input.source.file);
    }
    for (const auto& resource : spec.resources)
        if (!resource.initial.file.empty()) inputs.push_back(resource.initial.file);
    for (const auto& expectation : spec.expectations)
        if (!expectation.expected.file.empty()) inputs.push_back(expectation.expected.file);
    return inputs;
}

// An integer resource's values must be its integers: 2^32 would wrap, 1.5 be cut.
static const std::vector<double>& requireFormatValues(const RunSpec& spec, const std::vector<double>& values,
                                                      const vulkan::TexelFormat& format, const std::string& where) {
    for (size_t i = 0; i < values.size(); ++i)
        if (const auto problem = vulkan::integerValueProblem(format, values[i]); !problem.empty())
            refuse(spec, where + "[" + std::to_string(i) + "]: " + problem);
    return values;
}

std::vector<double> valuesOf(const RunSpec& spec, const ValueSource& source, const std::string& where,
                             const vulkan::TexelFormat& format, size_t count, uint32_t channels) {
    if (!source.file.empty()) return requireFormatValues(spec, readValues(source.file, format, count), format, where + ".file");
    if (!source.values.empty()) {
        if (source.values.size() != count)
            refuse(spec, where + ".values: " + std::to_string(source.values.size()) + " values for " + std::to_string(count));
        return source.values;
    }
    std::vector<double> values(count, 0.0);
    if (!source.fill.empty()) {
        if (source.fill.size() != 1 && source.fill.size() != channels)
            refuse(spec, where + ".fill: " + std::to_string(source.fill.size()) + " numbers for " + std::to_string(channels) + " channels");
        for (size_t i = 0; i < count; ++i) values[i] = source.fill[source.fill.size() == 1 ? 0 : i % channels];
    }
    return values;
}

} // namespace iblkit::run

namespace iblkit::run {
namespace {

void checkNames(const RunSpec& spec, const compiler::ShaderReflection& reflection, const std::optional<DrawPlan>& draw) {
    for (const auto& resource : spec.resources) {
        const auto* found = reflection.find(resource.binding);
        if (!found) {
            std::string names;
            for (const auto& r : reflection.resources) names += (names.empty() ? "" : ", ") + r.name;
            refuse(spec, "resources." + resource.binding + ": the shader has no resource of that name (it has: " + names + ")");
        }
        const bool array = resource.name != resource.binding;
        if (array != (found->location.count > 1) || resource.element >= found->location.count)
            refuse(spec, "resources." + resource.binding + ": the shader declares " +
                           (found->location.count > 1 ? "an array of " + std::to_string(found->location.count) + " (give \"elements\")"
                                                      : std::string("one resource, not an array")));
        const auto kind = compiler::resourceKindName(found->kind);
        const std::string& given = resource.kind;
        const bool matches = (given == "buffer" && kind == "buffer") || (given == "cbuffer" && kind == "cbuffer") ||
                             ((given == "image" || given == "cube") && kind == "texture") ||
                             (given == "storage_image" && kind == "storage_image") || (given == "sampler" && kind == "sampler");
        if (!matches) refuse(spec, "resources." + resource.name + ": is a " + given + ", but the shader declares a " + std::string(kind));
    }
    for (const auto& resource : reflection.resources) {
        const auto given = std::count_if(spec.resources.begin(), spec.resources.end(), [&](const auto& r) { return r.binding == resource.name; });
        if (given == 0)
            refuse(spec, "resources: the shader needs '" + resource.name + "' (" + std::string(compiler::resourceKindName(resource.kind)) +
                           "), which the run file does not give");
        if (size_t(given) != resource.location.count)
            refuse(spec, "resources." + resource.name + ": the shader declares an array of " + std::to_string(resource.location.count) +
                           ", the run file gives " + std::to_string(given) + " elements");
    }
    const auto holdsValues = [&](const std::string& name, const std::string& where) {
        if (draw && std::any_of(draw->targets.begin(), draw->targets.end(), [&](const auto& t) { return t.spec->name == name; })) return;
        if (draw && draw->depth && spec.graphics->depth->name == name) return;
        const auto found = std::find_if(spec.resources.begin(), spec.resources.end(), [&](const auto& r) { return r.name == name; });
        if (found == spec.resources.end())
            refuse(spec, where + ": no resource " + (draw ? "or target " : "") + "named '" + name + "'");
        if (found->kind == "sampler") refuse(spec, where + ": '" + name + "' is a sampler: it holds no values");
    };
    for (const auto& expectation : spec.expectations) holdsValues(expectation.resource, "expect");
    for (const auto& [name, path] : spec.saves) holdsValues(name, "save");
    if (!spec.pushConstants.empty() && reflection.pushConstantSize == 0)
        refuse(spec, "push_constants: the shader has no push constants (no [[vk::push_constant]] block)");
    std::vector<std::filesystem::path> saves;
    for (const auto& [name, path] : spec.saves) saves.push_back(path);
    files::requireDistinctOutputs(saves, inputFiles(spec)); // before any device work: nothing is lost
}

const vulkan::TexelFormat* formatOfName(const RunSpec& spec, const std::optional<DrawPlan>& draw, const std::string& name) {
    if (draw) {
        for (const auto& target : draw->targets)
            if (target.spec->name == name) return target.shape.format;
        if (draw->depth && spec.graphics->depth->name == name) return draw->depth->format;
    }
    const auto resource = std::find_if(spec.resources.begin(), spec.resources.end(), [&](const auto& r) { return r.name == name; });
    if (resource == spec.resources.end()) return nullptr;
    if (resource->kind == "buffer") return &bufferFormat(*resource);
    if (resource->kind == "sampler" || resource->kind == "cbuffer") return nullptr;
    try {
        return &vulkan::texelFormatNamed(resource->format);
    } catch (const vulkan::VulkanError&) {
        return nullptr; // named with its key when the image is planned
    }
}

// The values the run file gives an integer resource, and expects of it, must be its integers
// (2^32 would wrap, 1.5 be cut): checked before anything is made. A data file's are checked
// when it is read.
void checkGivenValues(const RunSpec& spec, const std::optional<DrawPlan>& draw) {
    const auto check = [&](const ValueSource& source, const std::string& name, const std::string& where) {
        if (const auto* format = formatOfName(spec, draw, name)) {
            requireFormatValues(spec, source.values, *format, where + ".values");
            requireFormatValues(spec, source.fill, *format, where + ".fill");
        }
    };
    for (const auto& resource : spec.resources) check(resource.initial, resource.name, "resources." + resource.name);
    for (size_t i = 0; i < spec.expectations.size(); ++i)
        check(spec.expectations[i].expected, spec.expectations[i].resource, "expect[" + std::to_string(i) + "]");
}

template <typename Step>
decltype(auto) withKey(const RunSpec& spec, const std::string& key, Step step) {
    try {
        return step();
    } catch (const vulkan::VulkanError& error) {
        refuse(spec, key + ": " + error.what());
    }
}

ResourcePlan planResource(const RunSpec& run, const ResourceSpec& spec, const compiler::ReflectedResource& reflected) {
    ResourcePlan plan{&spec, &reflected, {}, 0, std::nullopt, nullptr};
    const std::string where = "resources." + spec.name;
    if (spec.kind == "cbuffer") {
        plan.bufferSize = std::max(16u, (reflected.blockSize + 15) / 16 * 16);
        auto bytes = withKey(run, where, [&] { return vulkan::packBlock(spec.binding, reflected.members, uint32_t(plan.bufferSize), spec.members); });
        plan.contents = [bytes] { return bytes; };
        plan.format = &vulkan::texelFormatNamed("R32_SFLOAT");
    } else if (spec.kind == "buffer") {
        const auto& format = bufferFormat(spec);
        size_t count = spec.count ? spec.count : spec.sizeBytes / 4;
        if (!count) count = spec.initial.values.size();
        if (!count && !spec.initial.file.empty()) count = readValues(spec.initial.file, format).size();
        if (!count) refuse(run, where + ": give \"count\", \"size_bytes\", \"values\" or \"file\"");
        plan.contents = [&run, &spec, &format, where, count] {
            const auto values = valuesOf(run, spec.initial, where, format, count, 1);
            std::vector<std::byte> bytes(count * 4);
            vulkan::encodeTexels(format, values, bytes);
            return bytes;
        };
        plan.bufferSize = std::max<size_t>(count * 4, reflected.blockSize);
        plan.format = &format;
    } else if (spec.kind != "sampler") {
        const auto& format = withKey(run, where + ".format", [&]() -> const vulkan::TexelFormat& { return vulkan::texelFormatNamed(spec.format); });
        const uint32_t mips = spec.mips ? spec.mips : vulkan::fullMipCount(spec.width, spec.height);
        plan.image = ImageShape{&format, spec.width, spec.height, spec.layers, mips, spec.dimension == "cube"};
        plan.contents = [&run, &spec, &format, where, shape = *plan.image] {
            const auto values = valuesOf(run, spec.initial, where, format, shape.valueCount(), format.channels);
            std::vector<std::byte> bytes(values.size() * format.bytesPerChannel);
            vulkan::encodeTexels(format, values, bytes);
            return bytes;
        };
        plan.format = &format;
    }
    return plan;
}

} // namespace

RunPlan planRun(const RunSpec& spec, const RunPrograms& programs) {
    RunPlan plan;
    if (spec.graphics) plan.draw = planDraw(spec, programs);
    checkNames(spec, programs.resources, plan.draw);
    checkGivenValues(spec, plan.draw);
    for (const auto& [name, path] : spec.saves)
        if (const auto* format = formatOfName(spec, plan.draw, name);
            format && isPictureFile(path) && (format->kind == vulkan::ComponentKind::UInt || format->kind == vulkan::ComponentKind::SInt))
            refuse(spec, "save." + name + ": " + std::string(format->name) + " holds integers, not colours: save it as .npy");
    for (const auto& resource : spec.resources) {
        plan.resources.push_back(planResource(spec, resource, *programs.resources.find(resource.binding)));
        const auto& reflected = *plan.resources.back().reflected;
        if ((resource.kind == "buffer" && !reflected.readOnly) || resource.kind == "storage_image") plan.written.push_back(resource.name);
    }
    if (plan.draw) {
        for (const auto& target : plan.draw->targets) plan.written.push_back(target.spec->name);
        if (plan.draw->depth) plan.written.push_back(spec.graphics->depth->name);
    }
    const auto& reflection = programs.resources;
    if (reflection.pushConstantSize > 0)
        plan.pushConstants = withKey(spec, "push_constants", [&] {
            return vulkan::packBlock(reflection.pushConstantBlock, reflection.pushConstants, reflection.pushConstantSize, spec.pushConstants);
        });
    return plan;
}

} // namespace iblkit::run
