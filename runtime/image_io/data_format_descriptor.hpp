#pragma once

#include "texture.hpp"

#include <cstddef>
#include <vector>

namespace iblkit::image_io::ktx2 {

// The Data Format Descriptor of a KTX2 file holding `format`: dfdTotalSize, then one Khronos
// Data Format 1.3 basic descriptor block, exactly as KTX-Software's createDFDUnpacked writes it
// for a little-endian SFLOAT format.
std::vector<std::byte> dataFormatDescriptor(PixelFormat format);

} // namespace iblkit::image_io::ktx2
