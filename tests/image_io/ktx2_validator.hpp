#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace iblkit::testing {

// Checks a KTX 2.0 file without supercompression against the Khronos KTX 2.0 specification,
// written from the specification alone and sharing nothing with the kit's writer: the
// identifier; the header against the vkFormat (R16G16B16A16_SFLOAT, R32G32B32A32_SFLOAT,
// R16G16_SFLOAT, R32G32_SFLOAT); the index; the basic Data Format Descriptor; the key/value data
// (with a KTXwriter); and the levels (sizes, smallest first, aligned, padded with zeros, the file
// ending with level 0). Returns one line per rule broken, each starting with the field it is
// about; none for a conforming file.
std::vector<std::string> validateKtx2(std::span<const std::byte> file);

} // namespace iblkit::testing
