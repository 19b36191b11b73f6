#pragma once

#include "lowering.hpp"
#include "register_binding.hpp"
#include "shader_stage.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::compiler {

enum class OptimizationLevel { None, Performance, Size };

struct CompileOptions {
    std::filesystem::path source;
    // When set, compiled instead of the file's contents; `source` still names it in messages
    // and its folder is where "#include" looks first.
    std::optional<std::string> sourceText;
    std::string entryPoint = "main";
    std::optional<ShaderStage> stage; // deduced from the entry point's attributes when empty
    std::vector<std::filesystem::path> includeDirs;
    // Files served from memory before the disk is asked, by path as an #include forms it
    // ("hlsl/document/Common/PBR.fxh"): shaders built into a program.
    std::map<std::string, std::string> virtualFiles;
    std::map<std::string, std::string> defines; // NAME -> VALUE ("" for a bare -D NAME)
    OptimizationLevel optimization = OptimizationLevel::None;
    bool stripDebugInfo = false;
    // Storage image formats by HLSL resource name, in glslang's spelling ("rg16f", "rgba8", ...).
    std::map<std::string, std::string> imageFormats;
    BindingShifts bindingShifts;
    // Run glslang's front end first in a child process with time and memory limits
    // (bounded_child.hpp), so that a source from a user whose macros expand without bound, or on
    // which glslang crashes, is an error, not a hang or a crash: the command-line tool sets it;
    // the kit's own shaders need no such guard.
    bool boundPreprocessing = false;
    // HLSL 2021 (DXC's default) is lowered to what glslang reads (runtime/lowering/); 2018 is not.
    lowering::HlslVersion hlslVersion = lowering::HlslVersion::Hlsl2021;
    // DXC's -enable-16bit-types: half, min16* and float16_t/int16_t/uint16_t are 16 bits wide.
    // Without it they are 32 bits, as in DXC (min16* with a warning).
    bool enable16BitTypes = false;
    // DXC's and fxc's -Zpr / -Zpc: how a matrix without row_major or column_major is packed
    // (column-major when unset, HLSL's default).
    bool rowMajorByDefault = false;
    // Files an engine's build puts before the source as it compiles it (a prelude of helpers), in
    // order: each is #included first, and the source's own lines keep their numbers.
    std::vector<std::filesystem::path> forceIncludes;
};

} // namespace iblkit::compiler
