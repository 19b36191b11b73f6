#pragma once

#include <cstdint>
#include <vector>

namespace iblkit::compiler {

// Rewrites the format operand of every storage-image type (OpTypeImage, Sampled = 2) that
// has format `from`. Used for ESSL's stand-in formats, on a copy of the module.
void replaceStorageImageFormat(std::vector<uint32_t>& spirv, unsigned from, unsigned to);

} // namespace iblkit::compiler
