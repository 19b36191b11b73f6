#pragma once

#include <stdexcept>

namespace iblkit::porting {

// A corpus that cannot be read: its manifest, a shader it names, a run file.
struct PortingError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::porting
