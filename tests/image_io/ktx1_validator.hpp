#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace iblkit::testing {

// Checks a KTX 1.1 file against the Khronos specification, independently of the kit's writer:
// the identifier, the endianness, glType and glTypeSize (GL_HALF_FLOAT 2, GL_FLOAT 4), glFormat
// and glBaseInternalFormat (GL_RGBA, GL_RG) and the sized glInternalFormat they imply, the
// dimensions of a 2D texture or a square cube, the mip count, every key/value pair (its size, a
// NUL-terminated key, its padding), each level's imageSize (one face's bytes for a cube), the
// padding, and the total size. Returns one line per rule broken, each starting with the field it
// is about; none for a conforming file.
std::vector<std::string> validateKtx1(std::span<const std::byte> file);

} // namespace iblkit::testing
