#pragma once

#include "shader_stage.hpp"

#include <glslang/Public/ShaderLang.h>

namespace iblkit::compiler {

// glslang keeps process-wide tables: sets them up on first use and tears them down at exit.
void initializeGlslangOnce();

EShLanguage toGlslang(ShaderStage stage);

} // namespace iblkit::compiler
