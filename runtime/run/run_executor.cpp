#include "run_executor.hpp"

#include "atomic_output.hpp"
#include "data_file.hpp"
#include "expectation_check.hpp"
#include "gl_error.hpp"
#include "image_save.hpp"
#include "opengl_engine.hpp"
#include "run_error.hpp"
#include "run_plan.hpp"
#include "vulkan_engine.hpp"
#include "vulkan_error.hpp"

#include <fmt/core.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <functional>
#include <map>

namespace iblkit::run {

size_t ImageShape::valueOffset(uint32_t mip, uint32_t layer) const {
    size_t offset = 0;
    for (uint32_t level = 0; level < mip; ++level) offset += size_t(mipWidth(level)) * mipHeight(level) * layers;
    offset += size_t(mipWidth(mip)) * mipHeight(mip) * layer;
    return offset * format->channels;
}

namespace {

// Where value i of a subresource selection lies, for the report.
std::string locate(const ImageShape& image, uint32_t firstMip, uint32_t firstLayer, size_t index, bool oneLayer) {
    const uint32_t channels = image.format->channels;
    size_t texel = index / channels;
    for (uint32_t mip = firstMip; mip < image.mips; ++mip) {
        const size_t perLayer = size_t(image.mipWidth(mip)) * image.mipHeight(mip);
        const size_t layers = oneLayer ? 1 : image.layers;
        if (texel < perLayer * layers) {
            const size_t layer = firstLayer + texel / perLayer, inLayer = texel % perLayer;
            return fmt::format("mip {} layer {} ({}, {}) channel {}", mip, layer, inLayer % image.mipWidth(mip),
                               inLayer / image.mipWidth(mip), index % channels);
        }
        texel -= perLayer * layers;
    }
    return "?";
}

std::string locate(const Readback& data, size_t index) {
    return data.image ? locate(*data.image, 0, 0, index, false) : fmt::format("element {}", index);
}

// A path cannot take the shaders: OpenGL's form is refused or the driver rejects it, the HLSL
// form is refused or does not compile again.
class PathRefusal : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// One API's run of the file: resources made, the dispatch or draw, expectations checked.
class ApiRun {
public:
    ApiRun(const RunSpec& spec, const RunPlan& plan, RunEngine& engine, std::ostream& out, std::string prefix)
        : spec_(spec), plan_(plan), engine_(engine), out_(out), prefix_(std::move(prefix)) {}

    bool run(const RunPrograms& programs) {
        fmt::print(out_, "{}device   {}\n", prefix_, engine_.deviceLine());
        withKey(spec_.graphics ? "vertex" : "shader", [&] {
            try {
                engine_.makeProgram(spec_, programs, plan_.draw ? &*plan_.draw : nullptr);
            } catch (const opengl::GlError& error) {
                throw PathRefusal(spec_.runFile.string() + ": error: " + error.what());
            }
        });
        for (const auto& resource : plan_.resources) withKey("resources." + resource.spec->name, [&] { engine_.makeResource(resource); });
        if (!plan_.pushConstants.empty()) withKey("push_constants", [&] { engine_.setPushConstants(plan_.pushConstants); });
        std::string line;
        try {
            line = engine_.execute(spec_, plan_.draw ? &*plan_.draw : nullptr);
        } catch (const vulkan::VulkanError& error) {
            const std::string what = error.what();
            fail(what.rfind("targets.", 0) == 0 ? what : (spec_.graphics ? "draw: " : "dispatch: ") + what);
        } catch (const vk::SystemError& error) {
            fail((spec_.graphics ? "draw: " : "dispatch: ") + std::string(error.what()));
        } catch (const opengl::GlError& error) {
            fail((spec_.graphics ? "draw: " : "dispatch: ") + std::string(error.what()));
        }
        fmt::print(out_, "{}{}\n", prefix_, line);
        size_t passed = 0;
        for (const auto& expectation : spec_.expectations) passed += check(expectation);
        bool clean = true;
        for (const auto& message : engine_.validationMessages()) {
            fmt::print(out_, "{}FAIL validation: {}\n", prefix_, message);
            clean = false;
        }
        fmt::print(out_, "{}{} of {} expectations passed\n", prefix_, passed, spec_.expectations.size());
        return clean && passed == spec_.expectations.size();
    }

    const Readback& read(const std::string& name) {
        auto found = readbacks_.find(name);
        if (found == readbacks_.end()) {
            Readback data;
            withKey("expect", [&] { data = engine_.read(name); });
            found = readbacks_.emplace(name, std::move(data)).first;
        }
        return found->second;
    }

private:
    [[noreturn]] void fail(const std::string& why) const { throw RunError(spec_.runFile.string() + ": error: " + why); }

    // The driver's and the runtime's errors name no run file or key: each step adds them.
    template <typename Step>
    void withKey(const std::string& key, Step step) const {
        try {
            step();
        } catch (const vulkan::VulkanError& error) {
            fail(key + ": " + error.what());
        } catch (const vk::SystemError& error) {
            fail(key + ": " + error.what());
        } catch (const opengl::GlError& error) {
            fail(key + ": " + error.what());
        }
    }

    bool check(const Expectation& expectation) {
        const auto& data = read(expectation.resource);
        std::vector<double> selected = data.values;
        uint32_t firstMip = 0, firstLayer = 0;
        bool oneLayer = false;
        if (data.image && (expectation.mip || expectation.layer)) {
            const auto& shape = *data.image;
            firstMip = expectation.mip.value_or(0);
            const uint32_t lastMip = expectation.mip ? firstMip + 1 : shape.mips;
            if (firstMip >= shape.mips) fail("expect: " + expectation.resource + " has no mip " + std::to_string(firstMip));
            if (expectation.layer && *expectation.layer >= shape.layers)
                fail("expect: " + expectation.resource + " has no layer " + std::to_string(*expectation.layer));
            oneLayer = expectation.layer.has_value();
            firstLayer = expectation.layer.value_or(0);
            selected.clear();
            for (uint32_t mip = firstMip; mip < lastMip; ++mip)
                for (uint32_t layer = 0; layer < shape.layers; ++layer) {
                    if (oneLayer && layer != firstLayer) continue;
                    const size_t begin = shape.valueOffset(mip, layer);
                    const size_t end = layer + 1 < shape.layers ? shape.valueOffset(mip, layer + 1) : shape.valueOffset(mip + 1, 0);
                    selected.insert(selected.end(), data.values.begin() + std::ptrdiff_t(begin), data.values.begin() + std::ptrdiff_t(end));
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
            const auto expected = valuesOf(spec_, expectation.expected, "expect " + expectation.resource, *data.format, selected.size(), channels);
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
        fmt::print(out_, "{}{} {}: {} values {}; {}\n", prefix_, result.passed ? "PASS" : "FAIL", expectation.resource,
                   result.compared, how, detail);
        return result.passed;
    }

    const RunSpec& spec_;
    const RunPlan& plan_;
    RunEngine& engine_;
    std::ostream& out_;
    std::string prefix_;
    std::map<std::string, Readback> readbacks_;
};

// Every save or none: all are written to temporaries first (files::AtomicOutput).
void saveAll(const RunSpec& spec, ApiRun& run, std::ostream& out) {
    files::AtomicOutput output;
    output.protect(inputFiles(spec));
    for (const auto& [name, path] : spec.saves) {
        const auto& data = run.read(name);
        if (isPictureFile(path)) {
            if (!data.image) throw RunError(path.string() + ": error: '" + name + "' is a buffer: save it as .npy");
            const auto& image = *data.image;
            output.add(path, encodePicture(path, *data.format, data.values, image.width, image.height, image.layers, image.mips));
            continue;
        }
        std::vector<size_t> shape{data.values.size()};
        if (data.image && data.image->mips == 1) shape = {data.image->layers, data.image->height, data.image->width, data.image->format->channels};
        output.add(path, encodeValues(path, *data.format, data.values, shape));
    }
    output.commit();
    for (const auto& [name, path] : spec.saves) fmt::print(out, "saved    {} -> {}\n", name, path.string());
}

// What a path's shaders wrote, compared with the first path's: the report names the largest
// difference and where.
bool comparePaths(const RunSpec& spec, const RunPlan& plan, ApiRun& first, ApiRun& other, const std::string& label,
                  const std::string& otherName, std::ostream& out) {
    const Tolerance bound = spec.crossApi.value_or(kDefaultCrossApiTolerance);
    bool passed = true;
    for (const auto& name : plan.written) {
        const auto& a = first.read(name);
        const auto& b = other.read(name);
        if (a.values.size() != b.values.size()) {
            fmt::print(out, "FAIL {} {}: {} values on Vulkan, {} on {}\n", label, name, a.values.size(), b.values.size(), otherName);
            passed = false;
            continue;
        }
        const auto result = compareValues(b.values, a.values, bound, *a.format);
        fmt::print(out, "{} {} {}: {} values, {}{}; largest difference {:.3g} ({} ulp) at {}: vulkan {}, {} {}\n",
                   result.passed ? "PASS" : "FAIL", label, name, result.compared, describeTolerance(bound),
                   result.passed ? "" : fmt::format(", {} outside", result.failed), result.worstAbsolute, result.worstUlp,
                   locate(a, result.worstIndex), result.expected, otherName, result.actual);
        passed = passed && result.passed;
    }
    return passed;
}

// A way to carry out the run file: an engine, and the shaders it runs.
struct RunPath {
    std::string name;  // "vulkan", "hlsl-form", "opengl"
    std::string label; // how its comparison with Vulkan is named
    std::function<std::unique_ptr<RunEngine>()> engine;
    std::function<RunPrograms()> programs;
    bool specializedInSource = false; // the shaders' constants are set before they are compiled
};

std::vector<RunPath> pathsOf(const RunSpec& spec, const RunOptions& options, const RunPrograms& programs) {
    const RunPath vulkan{"vulkan", "", [&] { return makeVulkanEngine(options); }, [&] { return programs; }};
    const RunPath opengl{"opengl", "cross-API", [&] {
                             try {
                                 return makeOpenGlEngine();
                             } catch (const opengl::GlError& error) {
                                 throw RunError(spec.runFile.string() + ": error: OpenGL: " + error.what());
                             }
                         },
                         [&] { return programs; }};
    const RunPath roundTrip{"hlsl-form", "round trip", [&] { return makeVulkanEngine(options); },
                            [&] {
                                try {
                                    return hlslFormPrograms(spec, programs);
                                } catch (const std::exception& error) {
                                    throw PathRefusal(error.what());
                                }
                            },
                            true};
    switch (options.api) {
    case RunApi::Vulkan: return {vulkan};
    case RunApi::OpenGl: return {opengl};
    case RunApi::All: break;
    }
    return {vulkan, roundTrip, opengl};
}

} // namespace

compiler::CompileOptions compileOptionsOf(const RunSpec& spec) {
    compiler::CompileOptions options = spec.compileBase.value_or(compiler::CompileOptions{});
    options.source = spec.shader;
    options.entryPoint = spec.entry;
    options.includeDirs = spec.includeDirs;
    options.defines = spec.defines;
    options.imageFormats = spec.imageFormats;
    options.enable16BitTypes = spec.enable16BitTypes;
    options.hlslVersion = spec.hlslVersion;
    options.virtualFiles = spec.virtualFiles;
    return options;
}

RunSummary executeRunOnPaths(const RunSpec& spec, const RunOptions& options, std::ostream& out) {
    const auto programs = loadPrograms(spec);
    const auto plan = planRun(spec, programs);
    if (spec.graphics)
        fmt::print(out, "shader   {} ({}) and {} ({})\n", spec.graphics->vertex.shader.string(), spec.graphics->vertex.entry,
                   spec.graphics->pixel.shader.string(), spec.graphics->pixel.entry);
    else
        fmt::print(out, "shader   {} ({}), workgroup {}x{}x{}\n", spec.shader.string(), spec.entry, programs.compute->reflection.workgroupSize[0],
                   programs.compute->reflection.workgroupSize[1], programs.compute->reflection.workgroupSize[2]);
    const auto paths = pathsOf(spec, options, programs);
    const bool several = paths.size() > 1;
    RunSummary summary;
    // Each path's engine outlives the comparisons, which read its resources.
    std::vector<std::unique_ptr<RunEngine>> engines;
    std::vector<std::optional<ApiRun>> runs(paths.size());
    std::vector<RunSpec> pathSpecs(paths.size(), spec);
    for (size_t i = 0; i < paths.size(); ++i) {
        const auto& path = paths[i];
        if (path.specializedInSource) pathSpecs[i].specialization.clear();
        PathOutcome outcome{path.name, false, false, ""};
        try {
            const auto pathPrograms = path.programs();
            engines.push_back(path.engine());
            runs[i].emplace(pathSpecs[i], plan, *engines.back(), out, several ? path.name + ": " : "");
            outcome.passed = runs[i]->run(pathPrograms);
            outcome.ran = true;
        } catch (const PathRefusal& refusal) {
            // A form another path cannot take (wave operations in OpenGL, 16-bit types on
            // llvmpipe) is no failure of the run on Vulkan: said, and nothing compared.
            if (!several || i == 0) throw RunError(refusal.what());
            fmt::print(out, "{}: not run: {}\n", path.name, refusal.what());
            outcome.notRun = refusal.what();
            runs[i].reset();
        }
        summary.paths.push_back(outcome);
        if (runs[i] && several) // a single path compares nothing: its values are not read back twice
            for (const auto& name : plan.written) summary.written[path.name][name] = runs[i]->read(name).values;
    }
    summary.pathsAgree = true;
    for (size_t i = 1; i < paths.size(); ++i)
        if (runs[i]) summary.pathsAgree = comparePaths(spec, plan, *runs[0], *runs[i], paths[i].label, paths[i].name, out) && summary.pathsAgree;
    saveAll(spec, *runs[0], out);
    summary.passed = summary.pathsAgree &&
                     std::all_of(summary.paths.begin(), summary.paths.end(), [](const auto& p) { return !p.ran || p.passed; });
    return summary;
}

bool executeRun(const RunSpec& spec, const RunOptions& options, std::ostream& out) {
    return executeRunOnPaths(spec, options, out).passed;
}

} // namespace iblkit::run
