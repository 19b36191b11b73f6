#pragma once

#include "texture.hpp"

#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace iblkit::image_io {

// A KTX 2.0 file, to the Khronos KTX 2.0 specification: the vkFormat of the texture's format,
// no supercompression, a basic Data Format Descriptor (RGBSDA, BT.709, linear, one FLOAT|SIGNED
// sample per channel), the key/value data {KTXwriter: writer} and `keyValues`, and the levels
// stored smallest first, each aligned to lcm(texel size, 4). `writer` is e.g. "iblkit 0.1.0".
// Throws ImageError when the texture's levels do not match its shape.
std::vector<std::byte> encodeKtx2(const Texture& texture, const std::string& writer,
                                  const std::map<std::string, std::string>& keyValues = {});
// The same file in pieces, to be written one after another without a copy: `head` (the header,
// index, DFD and key/value data), then padding and each level's bytes, views of `texture`'s own
// (which must outlive the pieces).
struct Ktx2Pieces {
    std::vector<std::byte> head;
    std::vector<std::span<const std::byte>> pieces; // head first
};
Ktx2Pieces encodeKtx2Pieces(const Texture& texture, const std::string& writer,
                            const std::map<std::string, std::string>& keyValues = {});

// Reads the four formats of PixelFormat, 2D textures and cubes, not arrays, not 3D, not
// supercompressed. Anything else, and any file whose index is truncated or inconsistent, is an
// ImageError naming `name` and the problem.
Texture decodeKtx2(std::span<const std::byte> bytes, const std::string& name);
// The key/value data of a KTX 2.0 file, values without their terminating NUL.
std::map<std::string, std::string> decodeKtx2KeyValues(std::span<const std::byte> bytes, const std::string& name);

} // namespace iblkit::image_io
