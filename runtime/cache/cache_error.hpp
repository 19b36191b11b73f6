#pragma once

#include <stdexcept>

namespace iblkit::cache {

// The cache folder cannot be made or written, or a digest cannot be taken.
struct CacheError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::cache
