#pragma once

#include <stdexcept>

namespace iblkit::run {

// A run file that cannot be run: the message names the file, the key and the problem.
class RunError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::run
