#include "exr_memory_stream.hpp"

#include <Iex.h>

#include <cstring>

namespace iblkit::image_io {

bool ExrMemoryStream::read(char c[], int n) {
    if (n < 0 || position_ > bytes_.size() || size_t(n) > bytes_.size() - position_)
        throw Iex::InputExc("Unexpected end of file.");
    std::memcpy(c, bytes_.data() + position_, size_t(n));
    position_ += uint64_t(n);
    return position_ < bytes_.size();
}

} // namespace iblkit::image_io
