#include "suite_run.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace iblkit::consistency {
namespace {

bool withinBounds(const ErrorStats& vsFloat, const ErrorStats& vsDouble, const Bounds& bounds) {
    return vsFloat.nonFinite == 0 && vsFloat.maxAbsolute <= bounds.maxVsFloat && vsFloat.rms <= bounds.rmsVsFloat &&
           vsDouble.maxAbsolute <= bounds.maxVsDouble && vsDouble.rms <= bounds.rmsVsDouble;
}

// Over the first three of every four values only: an alpha of 1 (or the harmonics' solid angle)
// is no measure of the output's radiance, and would hide errors in a dim environment's.
bool isColour(size_t index) { return index % 4 != 3; }

double largestColour(const std::vector<double>& values) {
    double largest = 0;
    for (size_t i = 0; i < values.size(); ++i)
        if (isColour(i) && std::isfinite(values[i])) largest = std::max(largest, std::abs(values[i]));
    return largest;
}

// The largest error of the colour values over the largest of them (the absolute error where
// they are all 0).
template <typename T>
double colourError(const std::vector<T>& values, const std::vector<double>& reference) {
    const double scale = largestColour(reference);
    double largest = 0;
    for (size_t i = 0; i < std::min(values.size(), reference.size()); ++i)
        if (isColour(i)) largest = std::max(largest, std::abs(double(values[i]) - reference[i]));
    return scale > 0 ? largest / scale : largest;
}

void addPathRows(SuiteRun& run, const OutputSpec& spec, const References& references, const PathRun& vulkanRun,
                 const OpenGlRun& openGlRun, bool skipPathA) {
    const auto add = [&](std::string path, const std::vector<float>& gpu) { addJudgedRow(run, spec, std::move(path), gpu, references); };
    for (const auto path : kVulkanPaths)
        if (!skipPathA || path != ShaderPath::Glslang)
            add(std::string(pathName(path)), vulkanRun(run.program(spec.kernel, path)));
    add(std::string(openGlPathName()), openGlRun(run.openGl(spec.kernel)));
}

} // namespace

void addJudgedRow(SuiteRun& run, const OutputSpec& spec, std::string path, const std::vector<float>& gpu, const References& references) {
    const auto vsFloat = measureError(gpu, references.inFloat);
    const auto vsDouble = measureError(gpu, references.inDouble);
    auto knownIssue = knownDivergence(spec.kernel, path);
    run.rows.push_back({spec.kernel, std::move(path), spec.output, vsFloat, vsDouble, spec.bounds, false,
                        withinBounds(vsFloat, vsDouble, spec.bounds), std::move(knownIssue), colourError(gpu, references.inDouble)});
}

const compiler::CompileOptions& SuiteRun::shader(const std::string& kernel) const {
    const auto found = options.shaders.find(kernel);
    if (found == options.shaders.end()) throw std::out_of_range("the suite's options have no shader " + kernel);
    return found->second;
}

const PathProgram& SuiteRun::program(const std::string& kernel, ShaderPath path) {
    const auto key = std::pair(kernel, path);
    if (!programs_.contains(key)) programs_.emplace(key, compileForPath(path, shader(kernel)));
    return programs_.at(key);
}

const OpenGlForm& SuiteRun::openGl(const std::string& kernel) {
    if (!openGlForms_.contains(kernel)) openGlForms_.emplace(kernel, openGlForm(shader(kernel)));
    return openGlForms_.at(kernel);
}

void addOutput(SuiteRun& run, const OutputSpec& spec, const std::function<References()>& makeReferences,
               const PathRun& vulkanRun, const OpenGlRun& openGlRun) {
    if (!run.runs(spec.kernel)) return;
    const auto references = makeReferences();
    run.rows.push_back({spec.kernel, "f. C++ reference, float", spec.output, {},
                        measureError(references.inFloat, references.inDouble), spec.bounds, true, true, {},
                        colourError(references.inFloat, references.inDouble)});
    addPathRows(run, spec, references, vulkanRun, openGlRun, false);
}

void addOutputAgainstPathA(SuiteRun& run, const OutputSpec& spec, const PathRun& vulkanRun, const OpenGlRun& openGlRun) {
    if (!run.runs(spec.kernel)) return;
    References pathA;
    pathA.inFloat = vulkanRun(run.program(spec.kernel, ShaderPath::Glslang));
    pathA.inDouble.assign(pathA.inFloat.begin(), pathA.inFloat.end());
    run.rows.push_back({spec.kernel, std::string(pathName(ShaderPath::Glslang)) + ", the reference (no C++ reference)",
                        spec.output, {}, {}, spec.bounds, true, true});
    addPathRows(run, spec, pathA, vulkanRun, openGlRun, true);
}

} // namespace iblkit::consistency
