#pragma once

#include <stdexcept>

namespace iblkit::image_io {

// An image or texture that cannot be read or written. Every message is one line naming the
// file and the problem, e.g. "'sky.hdr' is not a Radiance HDR image: ...".
class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::image_io
