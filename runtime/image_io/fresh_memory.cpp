#include "fresh_memory.hpp"

#include <sys/mman.h>

#include <cstdint>

namespace iblkit::image_io {

// Debian 12's headers define it; the kernel refuses it before Linux 5.14, and the pages are then
// mapped one by one as before.
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23
#endif

void populatePages(void* data, size_t bytes) {
    constexpr uintptr_t kPage = 4096;
    const auto begin = (reinterpret_cast<uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
    const auto end = (reinterpret_cast<uintptr_t>(data) + bytes) & ~(kPage - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
}

} // namespace iblkit::image_io
