#pragma once

#include <stdexcept>

namespace iblkit::render {

// A render that cannot be done as asked, in one line.
class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::render
