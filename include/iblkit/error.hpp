#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace iblkit {

// What went wrong, for a caller that reacts differently to each: fix the request, fix the shader,
// try another device. The message (what()) is the one the command line prints: one line, naming
// the file or setting and the problem (for a shader that does not compile, a line per diagnostic).
enum class ErrorKind {
    BadInput,      // refused before any work: a setting out of range, a file that cannot be read or is
                   // not what it should be, an output folder the bake may not replace
    CompileFailed, // the HLSL does not compile (what() holds the compiler's diagnostics, one a line)
    RunFailed,     // the run file was read, but the run cannot be carried out as it asks (a resource,
                   // a dispatch, a data file: the message names the key)
    BakeFailed,    // the bake began but could not finish: memory, a value the 16-bit files cannot hold
                   // with `strict`, a file that could not be written
    DeviceFailed,  // the Vulkan runtime refused or failed: no device (or none that matches the
                   // selector), no validation layer; in a bake, an allocation or a lost device
};

// "bad input", "compile failed", ... for messages and logs.
std::string_view errorKindName(ErrorKind kind);

// Every function of the library throws this and nothing else (beside std::bad_alloc).
class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message);
    // Defined in the library, so that one copy of its type information exists and a catch in a
    // program matches what the shared library throws.
    ~Error() override;

    ErrorKind kind() const noexcept { return kind_; }

private:
    ErrorKind kind_;
};

} // namespace iblkit
