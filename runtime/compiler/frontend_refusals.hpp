#pragma once

#include <string>

namespace iblkit::compiler {

// glslang's error, in the kit's words first: the construct it refuses and what to write instead,
// at the same file:line:col, with glslang's own message kept after it ("(glslang: ...)"), on
// the same line, so that an error stays one line. `error` is one diagnostic as the kit formats
// it ("In file included from" lines, then "file:line:col: error: message"). A message the kit
// does not know still gets words of its own first.
std::string inKitWords(const std::string& error);

} // namespace iblkit::compiler
