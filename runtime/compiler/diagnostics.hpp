#pragma once

#include <string>
#include <vector>

namespace iblkit::compiler {

class IncludeResolver;

struct Diagnostics {
    std::vector<std::string> errors;
    std::vector<std::string> warnings;
};

// Turns glslang's info log ("ERROR: file:line: 'token' : text") into
// "file:line:column: error: text" lines, each preceded by its include chain
// ("In file included from parent:line:"). glslang 12 reports no column, so the column is
// that of the quoted token on the reported line (1 when the token is not on it).
Diagnostics parseGlslangLog(const std::string& log, const IncludeResolver& files, const std::string& sourceName);


} // namespace iblkit::compiler
