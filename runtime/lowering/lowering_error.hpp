#pragma once

#include <stdexcept>
#include <string>

namespace iblkit::lowering {

// "file:line:col: error: <construct>: <why>", one line.
class LoweringError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::lowering
