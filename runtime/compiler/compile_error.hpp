#pragma once

#include <stdexcept>
#include <string>

namespace iblkit::compiler {

// Every failure of the compiler: the message is ready to print, one diagnostic per line,
// each "file:line:column: error: text" where a source location is known.
class CompileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::compiler
