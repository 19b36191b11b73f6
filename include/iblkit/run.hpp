#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace iblkit {

// Where a run file runs: Vulkan from the SPIR-V, OpenGL from the GLSL form (through EGL), or
// both, each API's results compared with the other's.
enum class RunApi { Vulkan, OpenGl, All };

struct RunRequest {
    std::filesystem::path runFile; // the JSON run file (docs/run-files.md); its paths are relative to it
    RunApi api = RunApi::Vulkan;
    std::string device;            // a device index or part of its name; empty: $IBLKIT_DEVICE, else lavapipe
    bool validation = false;       // the Vulkan validation layer on: any message it gives fails the run
    // How long the dispatch (or an upload or a download) may take.
    std::chrono::milliseconds timeout = std::chrono::seconds(60);
    // Called with the message when the dispatch times out or the device is lost. The device may
    // still be running the shader, so nothing made for the run can be freed safely: a program may
    // end here (the command line does). Otherwise the run throws Error, and the device is not to
    // be used again by this process.
    std::function<void(const std::string& message)> onDeviceFailure;
    // Where each line of the report also goes as the run makes it (nothing when null), for a
    // caller that shows progress; RunResult::report holds it all the same.
    std::ostream* reportStream = nullptr;
};

struct RunResult {
    bool passed = false; // every expectation of the run file held, on every API, and the APIs agreed
    std::string report;  // a line for each step and each expectation, as `iblkit run` prints it
};

// Compiles the run file's shaders, makes and fills its resources, dispatches or draws, checks every
// expectation and saves what it asks. An expectation that fails is a result (passed false), not an
// error. Throws Error: BadInput for a run file that cannot be read, CompileFailed for its shader,
// RunFailed when the run cannot be carried out as the file asks, DeviceFailed.
RunResult executeRunFile(const RunRequest& request);

} // namespace iblkit
