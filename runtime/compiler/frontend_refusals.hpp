#pragma once

#include <string>

namespace iblkit::compiler {

// glslang's error, in the kit's words first: the construct it refuses and what to write instead,
// at the same file:line:col, with glslang's own message kept after it ("(glslang: ...)"), on
// the same line, so that an error stays one line. `error` is one diagnostic as the kit formats
// it ("In file included from" lines, then "file:line:col: error: message"). A message the kit
// does not know still gets words of its own first.
std::string inKitWords(const std::string& error);

// The validator's refusal of the SPIR-V glslang wrote for a shader ("file: error: the SPIR-V is
// not valid for Vulkan 1.1: ..."), in the kit's words first: the construct that makes glslang
// write it, where the kit knows it, and what to write instead; the validator's message after.
std::string invalidSpirvInKitWords(const std::string& error);

} // namespace iblkit::compiler
