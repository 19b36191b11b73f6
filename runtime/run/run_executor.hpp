#pragma once

#include "compile_options.hpp"
#include "run_file.hpp"

#include <chrono>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace iblkit::run {

enum class RunApi { Vulkan, OpenGl, All };

struct RunOptions {
    // Vulkan from the SPIR-V, OpenGL from the GLSL form, or both, compared with each other.
    RunApi api = RunApi::Vulkan;
    std::string device;      // see vulkan::ContextOptions
    bool validation = false; // any validation message then fails the run
    // How long the dispatch (or any upload or download) may take, and what to do when it does
    // not end in time or the device is lost: see vulkan::ContextOptions.
    std::chrono::milliseconds timeout = std::chrono::seconds(60);
    std::function<void(const std::string& message)> onDeviceFailure = {};
};

// How far another path's results may lie from Vulkan's when the run file does not say: 4 ULP, or
// 1e-6 absolute, which a value interpolated across a primitive needs (llvmpipe's OpenGL and
// lavapipe set interpolation up apart: 3.3e-7 measured on the porting corpus's seeded
// ArrayVaryingLocations draw, 22 ULP of its 0.14). docs/run-files.md gives the measurements.
inline const Tolerance kDefaultCrossApiTolerance{1e-6, std::nullopt, 4.0};

// How the run file's HLSL shader is compiled: its entry point, include folders, defines, image
// formats, 16-bit types and HLSL version.
compiler::CompileOptions compileOptionsOf(const RunSpec& spec);

// Compiles the shaders, makes and fills the resources, dispatches or draws, checks every
// expectation and saves what was asked, printing a line for each step to `out`. With
// RunApi::All it does so on each API and compares what the shaders wrote on one with the
// other (the run file's "cross_api" bound, or kDefaultCrossApiTolerance). Returns true when
// every expectation and comparison passed. Throws RunError, compiler::CompileError or
// vulkan::VulkanError when the run cannot be carried out at all.
bool executeRun(const RunSpec& spec, const RunOptions& options, std::ostream& out);

// How one path carried out the run file: "vulkan" (the SPIR-V), "hlsl-form" (the HLSL form
// compiled again, on Vulkan), "opengl" (the GLSL form).
struct PathOutcome {
    std::string path;
    bool ran = false;    // false: the path could not take the shaders (notRun says why)
    bool passed = false; // every expectation held on it
    std::string notRun;
};

struct RunSummary {
    bool passed = false;     // every expectation on every path that ran, and every comparison
    bool pathsAgree = false; // every path that ran wrote what Vulkan wrote, within the bound
    std::vector<PathOutcome> paths;
    // With several paths (RunApi::All), what each that ran wrote, by path and resource (or target) name.
    std::map<std::string, std::map<std::string, std::vector<double>>> written;
};

// executeRun with what each path did. RunApi::All runs three paths: Vulkan from the SPIR-V,
// Vulkan again from the HLSL form compiled anew, and OpenGL from the GLSL form; the last two are
// compared with the first.
RunSummary executeRunOnPaths(const RunSpec& spec, const RunOptions& options, std::ostream& out);

} // namespace iblkit::run
