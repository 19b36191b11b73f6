#pragma once

#include "run_engine.hpp"

namespace iblkit::run {

// Runs the GLSL form on OpenGL 4.5 through EGL (llvmpipe on a machine without a GPU), with
// Direct3D's conventions: the clip origin upper left and depth 0 to 1 (glClipControl).
std::unique_ptr<RunEngine> makeOpenGlEngine();

} // namespace iblkit::run
