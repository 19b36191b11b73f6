#pragma once

#include "compile_options.hpp"
#include "run_file.hpp"

#include <chrono>
#include <functional>
#include <ostream>
#include <string>

namespace iblkit::run {

struct RunOptions {
    std::string device;      // see vulkan::ContextOptions
    bool validation = false; // any validation message then fails the run
    // How long the dispatch (or any upload or download) may take, and what to do when it does
    // not end in time or the device is lost: see vulkan::ContextOptions.
    std::chrono::milliseconds timeout = std::chrono::seconds(60);
    std::function<void(const std::string& message)> onDeviceFailure = {};
};

// How the run file's HLSL shader is compiled: its entry point, include folders, defines, image
// formats, 16-bit types and HLSL version.
compiler::CompileOptions compileOptionsOf(const RunSpec& spec);

// Compiles the shader, makes and fills the resources, dispatches, checks every expectation
// and saves what was asked, printing a line for each step to `out`. Returns true when every
// expectation passed. Throws RunError, compiler::CompileError or vulkan::VulkanError when the
// run cannot be carried out at all.
bool executeRun(const RunSpec& spec, const RunOptions& options, std::ostream& out);

} // namespace iblkit::run
