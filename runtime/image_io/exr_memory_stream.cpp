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

void ExrMemoryOutput::write(const char c[], int n) {
    if (position_ + uint64_t(n) > bytes_.size()) bytes_.resize(size_t(position_) + size_t(n));
    std::copy(c, c + n, bytes_.begin() + std::ptrdiff_t(position_));
    position_ += uint64_t(n);
}

} // namespace iblkit::image_io
