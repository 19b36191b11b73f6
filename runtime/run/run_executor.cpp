#include "run_executor.hpp"

#include "atomic_output.hpp"
#include "block_writer.hpp"
#include "compiler.hpp"
#include "compute_program.hpp"
#include "data_file.hpp"
#include "expectation_check.hpp"
#include "hlsl_frontend.hpp"
#include "spirv_tools.hpp"
#include "run_error.hpp"
#include "vulkan_error.hpp"

#include <fmt/core.h>
#include <fmt/ostream.h>

#include <memory>
#include <variant>

namespace iblkit::run {
namespace {

using Resource = std::variant<std::unique_ptr<vulkan::Buffer>, std::unique_ptr<vulkan::Image>, std::unique_ptr<vulkan::Sampler>>;

struct Program {
    std::vector<uint32_t> spirv;
    compiler::ShaderReflection reflection;
};

Program loadShader(const RunSpec& spec) {
    if (spec.shader.extension() == ".spv") {
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
        return {words, compiler::reflectSpirv(words, spec.entry, spec.shader.string())};
    }
    auto options = compileOptionsOf(spec);
    options.boundPreprocessing = true;
    auto shader = compiler::compileShader(options);
    return {shader.spirv, shader.reflection};
}

class Executor {
public:
    Executor(const RunSpec& spec, const RunOptions& options, std::ostream& out)
        : spec_(spec), out_(out), log_(std::make_shared<vulkan::ValidationLog>()),
          context_({options.device, options.validation, log_, options.timeout, options.onDeviceFailure}) {}

    bool run() {
        const auto program = loadShader(spec_);
        checkNames(program.reflection);
        fmt::print(out_, "shader   {} ({}), workgroup {}x{}x{}\n", spec_.shader.string(), spec_.entry,
                   program.reflection.workgroupSize[0], program.reflection.workgroupSize[1],
                   program.reflection.workgroupSize[2]);
        fmt::print(out_, "device   {}{}\n", context_.deviceInfo().name, context_.validationEnabled() ? ", validation on" : "");
        vulkan::ComputeProgram compute = [&] {
            try {
                return vulkan::ComputeProgram(context_, program.spirv, program.reflection, spec_.specialization);
            } catch (const vulkan::VulkanError& error) {
                throw RunError(spec_.shader.string() + ": error: " + error.what());
            }
        }();
        // The driver's and the runtime's errors name no run file or key: each step adds them.
        for (const auto& resource : spec_.resources)
            withKey("resources." + resource.name, [&] { makeAndBind(resource, compute); });
        if (program.reflection.pushConstantSize > 0)
            withKey("push_constants", [&] {
                compute.setPushConstants(vulkan::packBlock(program.reflection.pushConstantBlock, program.reflection.pushConstants,
                                                           program.reflection.pushConstantSize, spec_.pushConstants));
            });
        vulkan::DispatchTiming timing{};
        withKey("dispatch", [&] {
            timing = spec_.threads ? compute.dispatchThreads(context_, *spec_.threads)
                                   : compute.dispatchGroups(context_, *spec_.groups);
        });
        fmt::print(out_, "dispatch {}x{}x{} groups: {} on the device, {:.3f} ms wall\n", timing.groups[0], timing.groups[1],
                   timing.groups[2],
                   timing.deviceMilliseconds >= 0 ? fmt::format("{:.3f} ms", timing.deviceMilliseconds) : "no timestamps",
                   timing.wallMilliseconds);
        size_t passed = 0;
        for (const auto& expectation : spec_.expectations) passed += check(expectation);
        saveAll();
        bool clean = true;
        for (const auto& message : log_->messages()) {
            fmt::print(out_, "FAIL validation: {}\n", message);
            clean = false;
        }
        fmt::print(out_, "{} of {} expectations passed\n", passed, spec_.expectations.size());
        return clean && passed == spec_.expectations.size();
    }

private:
    [[noreturn]] void fail(const std::string& why) const {
        throw RunError(spec_.runFile.string() + ": error: " + why);
    }

    // Runs a step, turning a VulkanError or a driver's vk::SystemError into "<run file>: error: key: ...".
    template <typename Step>
    void withKey(const std::string& key, Step step) const {
        try {
            step();
        } catch (const vulkan::VulkanError& error) {
            fail(key + ": " + error.what());
        } catch (const vk::SystemError& error) {
            fail(key + ": " + error.what());
        }
    }

    void checkNames(const compiler::ShaderReflection& reflection) const {
        for (const auto& resource : spec_.resources) {
            const auto* found = reflection.find(resource.binding);
            if (!found) {
                std::string names;
                for (const auto& r : reflection.resources) names += (names.empty() ? "" : ", ") + r.name;
                fail("resources." + resource.binding + ": the shader has no resource of that name (it has: " + names + ")");
            }
            const bool array = resource.name != resource.binding;
            if (array != (found->location.count > 1) || resource.element >= found->location.count)
                fail("resources." + resource.binding + ": the shader declares " +
                     (found->location.count > 1 ? "an array of " + std::to_string(found->location.count) + " (give \"elements\")"
                                                : std::string("one resource, not an array")));
            const auto kind = compiler::resourceKindName(found->kind);
            const std::string& given = resource.kind;
            const bool matches = (given == "buffer" && kind == "buffer") || (given == "cbuffer" && kind == "cbuffer") ||
                                 ((given == "image" || given == "cube") && kind == "texture") ||
                                 (given == "storage_image" && kind == "storage_image") ||
                                 (given == "sampler" && kind == "sampler");
            if (!matches) fail("resources." + resource.name + ": is a " + given + ", but the shader declares a " + std::string(kind));
        }
        for (const auto& resource : reflection.resources) {
            const auto given = std::count_if(spec_.resources.begin(), spec_.resources.end(),
                                             [&](const auto& r) { return r.binding == resource.name; });
            if (given == 0) fail("resources: the shader needs '" + resource.name + "' (" +
                                 std::string(compiler::resourceKindName(resource.kind)) + "), which the run file does not give");
            if (size_t(given) != resource.location.count)
                fail("resources." + resource.name + ": the shader declares an array of " + std::to_string(resource.location.count) +
                     ", the run file gives " + std::to_string(given) + " elements");
        }
        const auto holdsValues = [&](const std::string& name, const std::string& where) {
            const auto found = std::find_if(spec_.resources.begin(), spec_.resources.end(), [&](const auto& r) { return r.name == name; });
            if (found == spec_.resources.end()) fail(where + ": no resource named '" + name + "'");
            if (found->kind == "sampler") fail(where + ": '" + name + "' is a sampler: it holds no values");
        };
        for (const auto& expectation : spec_.expectations) holdsValues(expectation.resource, "expect");
        for (const auto& [name, path] : spec_.saves) holdsValues(name, "save");
        if (!spec_.pushConstants.empty() && reflection.pushConstantSize == 0)
            fail("push_constants: the shader has no push constants (no [[vk::push_constant]] block)");
        std::vector<std::filesystem::path> saves;
        for (const auto& [name, path] : spec_.saves) saves.push_back(path);
        files::requireDistinctOutputs(saves, inputFiles()); // before any device work: nothing is lost
        checkGivenValues();
    }

    // The values the run file gives an integer resource, and expects of it, must be its integers
    // (2^32 would wrap, 1.5 be cut): checked before anything is made. A data file's are checked
    // when it is read.
    void checkGivenValues() const {
        const auto formatOf = [&](const std::string& name) -> const vulkan::TexelFormat* {
            const auto resource = std::find_if(spec_.resources.begin(), spec_.resources.end(), [&](const auto& r) { return r.name == name; });
            if (resource == spec_.resources.end()) return nullptr;
            if (resource->kind == "buffer") return &bufferFormat(*resource);
            if (resource->kind == "sampler" || resource->kind == "cbuffer") return nullptr;
            try {
                return &vulkan::texelFormatNamed(resource->format);
            } catch (const vulkan::VulkanError&) {
                return nullptr; // named with its key when the image is made
            }
        };
        const auto check = [&](const ValueSource& source, const std::string& name, const std::string& where) {
            if (const auto* format = formatOf(name)) {
                requireFormatValues(source.values, *format, where + ".values");
                requireFormatValues(source.fill, *format, where + ".fill");
            }
        };
        for (const auto& resource : spec_.resources) check(resource.initial, resource.name, "resources." + resource.name);
        for (size_t i = 0; i < spec_.expectations.size(); ++i)
            check(spec_.expectations[i].expected, spec_.expectations[i].resource, "expect[" + std::to_string(i) + "]");
    }

    // What the run reads: a save must be none of them.
    std::vector<std::filesystem::path> inputFiles() const {
        std::vector<std::filesystem::path> inputs{spec_.runFile, spec_.shader};
        for (const auto& resource : spec_.resources)
            if (!resource.initial.file.empty()) inputs.push_back(resource.initial.file);
        for (const auto& expectation : spec_.expectations)
            if (!expectation.expected.file.empty()) inputs.push_back(expectation.expected.file);
        return inputs;
    }

    // The values of a fill, a list or a file, for a resource or an expectation of `count` values.
    std::vector<double> valuesOf(const ValueSource& source, const std::string& where, const vulkan::TexelFormat& format,
                                 size_t count, uint32_t channels) const {
        if (!source.file.empty()) return requireFormatValues(readValues(source.file, format, count), format, where + ".file");
        if (!source.values.empty()) {
            if (source.values.size() != count)
                fail(where + ".values: " + std::to_string(source.values.size()) + " values for " + std::to_string(count));
            return source.values;
        }
        std::vector<double> values(count, 0.0);
        if (!source.fill.empty()) {
            if (source.fill.size() != 1 && source.fill.size() != channels)
                fail(where + ".fill: " + std::to_string(source.fill.size()) + " numbers for " + std::to_string(channels) +
                     " channels");
            for (size_t i = 0; i < count; ++i) values[i] = source.fill[source.fill.size() == 1 ? 0 : i % channels];
        }
        return values;
    }

    // An integer resource's values must be its integers: 2^32 would wrap, 1.5 be cut.
    const std::vector<double>& requireFormatValues(const std::vector<double>& values, const vulkan::TexelFormat& format,
                                                   const std::string& where) const {
        for (size_t i = 0; i < values.size(); ++i)
            if (const auto problem = vulkan::integerValueProblem(format, values[i]); !problem.empty())
                fail(where + "[" + std::to_string(i) + "]: " + problem);
        return values;
    }

    std::vector<double> initialValues(const ResourceSpec& spec, const vulkan::TexelFormat& format, size_t count,
                                      uint32_t channels) const {
        return valuesOf(spec.initial, "resources." + spec.name, format, count, channels);
    }

    static const vulkan::TexelFormat& bufferFormat(const ResourceSpec& spec) {
        if (spec.elementType == "uint") return vulkan::texelFormatNamed("R32_UINT");
        if (spec.elementType == "int") return vulkan::texelFormatNamed("R32_SINT");
        return vulkan::texelFormatNamed("R32_SFLOAT");
    }

    void makeAndBind(const ResourceSpec& spec, vulkan::ComputeProgram& compute) {
        const auto& reflected = *compute.reflection().find(spec.binding);
        if (spec.kind == "cbuffer") {
            const uint32_t size = std::max(16u, (reflected.blockSize + 15) / 16 * 16);
            auto buffer = std::make_unique<vulkan::Buffer>(context_, size, vk::BufferUsageFlagBits::eUniformBuffer, spec.name);
            buffer->write(vulkan::packBlock(spec.binding, reflected.members, size, spec.members));
            compute.bind(spec.binding, *buffer, spec.element);
            resources_[spec.name] = std::move(buffer);
        } else if (spec.kind == "buffer") {
            const auto& format = bufferFormat(spec);
            size_t count = spec.count ? spec.count : spec.sizeBytes / 4;
            if (!count) count = spec.initial.values.size();
            if (!count && !spec.initial.file.empty()) count = readValues(spec.initial.file, format).size();
            if (!count) fail("resources." + spec.name + ": give \"count\", \"size_bytes\", \"values\" or \"file\"");
            auto buffer = std::make_unique<vulkan::Buffer>(context_, std::max<size_t>(count * 4, reflected.blockSize),
                                                           vk::BufferUsageFlagBits::eStorageBuffer, spec.name);
            const auto values = initialValues(spec, format, count, 1);
            std::vector<std::byte> bytes(count * 4);
            vulkan::encodeTexels(format, values, bytes);
            buffer->write(bytes);
            compute.bind(spec.binding, *buffer, spec.element);
            resources_[spec.name] = std::move(buffer);
        } else if (spec.kind == "sampler") {
            auto sampler = std::make_unique<vulkan::Sampler>(context_, samplerDesc(spec));
            compute.bind(spec.binding, *sampler, spec.element);
            resources_[spec.name] = std::move(sampler);
        } else {
            const auto& format = vulkan::texelFormatNamed(spec.format);
            const uint32_t mips = spec.mips ? spec.mips : vulkan::fullMipCount(spec.width, spec.height);
            auto image = std::make_unique<vulkan::Image>(
                context_, vulkan::ImageDesc{spec.name, &format, spec.width, spec.height, spec.layers, mips,
                                            spec.dimension == "cube", spec.kind == "storage_image"});
            const auto values = initialValues(spec, format, image->valueCount(), format.channels);
            std::vector<std::byte> bytes(values.size() * format.bytesPerChannel);
            vulkan::encodeTexels(format, values, bytes);
            image->uploadBytes(context_, bytes);
            compute.bind(spec.binding, *image, spec.mip, spec.element);
            resources_[spec.name] = std::move(image);
        }
    }

    vulkan::SamplerDesc samplerDesc(const ResourceSpec& spec) const {
        vulkan::SamplerDesc desc;
        const auto filter = [&](const std::string& value, const std::string& key) {
            if (value == "nearest") return vk::Filter::eNearest;
            if (value == "linear") return vk::Filter::eLinear;
            fail("resources." + spec.name + "." + key + ": '" + value + "' (nearest, linear)");
        };
        desc.filter = filter(spec.filter, "filter");
        desc.mipmap = filter(spec.mipmap, "mipmap") == vk::Filter::eNearest ? vk::SamplerMipmapMode::eNearest
                                                                             : vk::SamplerMipmapMode::eLinear;
        if (spec.address == "clamp") desc.address = vk::SamplerAddressMode::eClampToEdge;
        else if (spec.address == "repeat") desc.address = vk::SamplerAddressMode::eRepeat;
        else if (spec.address == "mirror") desc.address = vk::SamplerAddressMode::eMirroredRepeat;
        else fail("resources." + spec.name + ".address: '" + spec.address + "' (clamp, repeat, mirror)");
        return desc;
    }

    struct Readback {
        std::vector<double> values;
        const vulkan::TexelFormat* format;
        const vulkan::Image* image; // null for buffers
    };

    Readback readback(const std::string& name) const {
        const auto found = resources_.find(name);
        if (found == resources_.end()) fail("no resource named '" + name + "' to check or save");
        if (const auto* image = std::get_if<std::unique_ptr<vulkan::Image>>(&found->second)) {
            const auto& format = *(*image)->desc().format;
            const auto bytes = (*image)->downloadBytes(context_);
            std::vector<double> values(bytes.size() / format.bytesPerChannel);
            vulkan::decodeTexels(format, bytes, values);
            return {values, &format, image->get()};
        }
        if (const auto* buffer = std::get_if<std::unique_ptr<vulkan::Buffer>>(&found->second)) {
            const auto spec = std::find_if(spec_.resources.begin(), spec_.resources.end(), [&](const auto& r) { return r.name == name; });
            const auto& format = spec->kind == "buffer" ? bufferFormat(*spec) : vulkan::texelFormatNamed("R32_SFLOAT");
            const auto bytes = (*buffer)->read();
            std::vector<double> values(bytes.size() / 4);
            vulkan::decodeTexels(format, bytes, values);
            return {values, &format, nullptr};
        }
        fail("'" + name + "' is a sampler: it holds no values");
    }

    // Where value i of a subresource selection lies, for the report.
    static std::string locate(const vulkan::Image& image, uint32_t firstMip, uint32_t firstLayer, size_t index, bool oneLayer) {
        const uint32_t channels = image.desc().format->channels;
        size_t texel = index / channels;
        for (uint32_t mip = firstMip; mip < image.desc().mips; ++mip) {
            const size_t perLayer = size_t(image.mipWidth(mip)) * image.mipHeight(mip);
            const size_t layers = oneLayer ? 1 : image.desc().layers;
            if (texel < perLayer * layers) {
                const size_t layer = firstLayer + texel / perLayer, inLayer = texel % perLayer;
                return fmt::format("mip {} layer {} ({}, {}) channel {}", mip, layer, inLayer % image.mipWidth(mip),
                                   inLayer / image.mipWidth(mip), index % channels);
            }
            texel -= perLayer * layers;
        }
        return "?";
    }

    bool check(const Expectation& expectation) const {
        auto data = readback(expectation.resource);
        std::vector<double> selected = data.values;
        uint32_t firstMip = 0, firstLayer = 0;
        bool oneLayer = false;
        if (data.image && (expectation.mip || expectation.layer)) {
            const auto& desc = data.image->desc();
            firstMip = expectation.mip.value_or(0);
            const uint32_t lastMip = expectation.mip ? firstMip + 1 : desc.mips;
            if (firstMip >= desc.mips) fail("expect: " + expectation.resource + " has no mip " + std::to_string(firstMip));
            if (expectation.layer && *expectation.layer >= desc.layers)
                fail("expect: " + expectation.resource + " has no layer " + std::to_string(*expectation.layer));
            oneLayer = expectation.layer.has_value();
            firstLayer = expectation.layer.value_or(0);
            selected.clear();
            for (uint32_t mip = firstMip; mip < lastMip; ++mip)
                for (uint32_t layer = 0; layer < desc.layers; ++layer) {
                    if (oneLayer && layer != firstLayer) continue;
                    const size_t begin = data.image->valueOffset(mip, layer);
                    const size_t end = layer + 1 < desc.layers ? data.image->valueOffset(mip, layer + 1)
                                                               : data.image->valueOffset(mip + 1, 0);
                    selected.insert(selected.end(), data.values.begin() + begin, data.values.begin() + end);
                }
        } else if (!data.image && (expectation.mip || expectation.layer)) {
            fail("expect: " + expectation.resource + " is a buffer: it has no mips or layers");
        }

        CheckResult result;
        std::string how;
        if (expectation.range) {
            result = checkRange(selected, (*expectation.range)[0], (*expectation.range)[1]);
            how = fmt::format("within [{}, {}]", (*expectation.range)[0], (*expectation.range)[1]);
        } else {
            const uint32_t channels = data.image ? data.format->channels : 1;
            const auto expected = valuesOf(expectation.expected, "expect " + expectation.resource, *data.format,
                                           selected.size(), channels);
            result = compareValues(selected, expected, expectation.tolerance, *data.format);
            how = describeTolerance(expectation.tolerance);
        }
        const std::string where = data.image ? locate(*data.image, firstMip, firstLayer, result.worstIndex, oneLayer)
                                             : fmt::format("element {}", result.worstIndex);
        std::string detail;
        if (expectation.range)
            detail = result.passed ? fmt::format("seen [{}, {}]", result.minimum, result.maximum)
                                   : fmt::format("{} outside, first worst {} at {}", result.failed, result.actual, where);
        else
            detail = fmt::format("{}worst at {}: expected {}, got {} (error {:.3g}, {} ulp)",
                                 result.passed ? "" : fmt::format("{} outside, ", result.failed), where, result.expected,
                                 result.actual, result.worstAbsolute, result.worstUlp);
        fmt::print(out_, "{} {}: {} values {}; {}\n", result.passed ? "PASS" : "FAIL", expectation.resource,
                   result.compared, how, detail);
        return result.passed;
    }

    // Every save or none: all are written to temporaries first (files::AtomicOutput).
    void saveAll() const {
        files::AtomicOutput output;
        output.protect(inputFiles());
        for (const auto& [name, path] : spec_.saves) {
            const auto data = readback(name);
            std::vector<size_t> shape{data.values.size()};
            if (data.image && data.image->desc().mips == 1) {
                const auto& desc = data.image->desc();
                shape = {desc.layers, desc.height, desc.width, desc.format->channels};
            }
            output.add(path, encodeValues(path, *data.format, data.values, shape));
        }
        output.commit();
        for (const auto& [name, path] : spec_.saves) fmt::print(out_, "saved    {} -> {}\n", name, path.string());
    }

    const RunSpec& spec_;
    std::ostream& out_;
    std::shared_ptr<vulkan::ValidationLog> log_;
    vulkan::VulkanContext context_;
    std::map<std::string, Resource> resources_;
};

} // namespace

compiler::CompileOptions compileOptionsOf(const RunSpec& spec) {
    compiler::CompileOptions options;
    options.source = spec.shader;
    options.entryPoint = spec.entry;
    options.includeDirs = spec.includeDirs;
    options.defines = spec.defines;
    options.imageFormats = spec.imageFormats;
    options.enable16BitTypes = spec.enable16BitTypes;
    options.hlslVersion = spec.hlslVersion;
    return options;
}

bool executeRun(const RunSpec& spec, const RunOptions& options, std::ostream& out) {
    return Executor(spec, options, out).run();
}

} // namespace iblkit::run
