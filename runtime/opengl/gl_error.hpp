#pragma once

#include <stdexcept>

namespace iblkit::opengl {

// Every failure of the OpenGL runner, one line ready to print.
class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::opengl
