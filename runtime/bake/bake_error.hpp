#pragma once

#include <stdexcept>

namespace iblkit::bake {

// A bake that cannot be done: the one-line message names the input or setting and the problem.
class BakeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::bake
