#pragma once

#include <cstddef>
#include <vector>

namespace iblkit::image_io {

// Maps the whole pages of [data, data + bytes) in one call (Linux's MADV_POPULATE_WRITE; a no-op
// where the kernel lacks it). A buffer of megabytes first written page by page takes a fault per
// 4 KiB; in a virtual machine each costs microseconds, and mapping them together costs about half
// (a cached bake, whose largest cost is its first touch of fresh buffers, ended 3-5 % sooner in
// whole-process medians).
void populatePages(void* data, size_t bytes);

// `count` elements of `values`, its fresh pages mapped together before they are written.
template <typename T>
void resizePopulated(std::vector<T>& values, size_t count) {
    values.reserve(count);
    populatePages(values.data(), values.capacity() * sizeof(T));
    values.resize(count);
}

} // namespace iblkit::image_io
