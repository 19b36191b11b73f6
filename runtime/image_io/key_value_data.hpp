#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace iblkit::image_io::ktx2 {

// A KTX2 file's key/value data: per entry keyAndValueByteLength, the NUL-terminated key, the
// value as a NUL-terminated UTF-8 string, and zero padding to 4 bytes; entries sorted by the
// bytes of their keys (std::map orders std::string keys as unsigned bytes).
std::vector<std::byte> keyValueData(const std::map<std::string, std::string>& entries);

} // namespace iblkit::image_io::ktx2
