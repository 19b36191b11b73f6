#pragma once

// Helpers the image_io suites share: textures with a distinct value in every channel, byte
// pokes for breaking files on purpose, and the one-line ImageError every refusal must be.
#include "image_error.hpp"
#include "texture.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace iblkit::testing {

// Every value distinct within a level and exactly representable as a half (multiples of 1/4
// below 512), so 16-bit round trips can be compared for equality.
inline image_io::Texture patternedTexture(image_io::PixelFormat format, uint32_t width, uint32_t height, uint32_t faces,
                                          uint32_t mips) {
    std::vector<float> values;
    for (uint32_t mip = 0; mip < mips; ++mip) {
        const size_t count = size_t(std::max(1u, width >> mip)) * std::max(1u, height >> mip) * faces *
                             image_io::channelCount(format);
        for (size_t i = 0; i < count; ++i) values.push_back(float((mip * 7919 + i) % 2039) * 0.25f);
    }
    return image_io::makeTexture(format, width, height, faces, mips, values);
}

inline uint32_t peek32(const std::vector<std::byte>& bytes, size_t offset) {
    uint32_t value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

inline uint64_t peek64(const std::vector<std::byte>& bytes, size_t offset) {
    uint64_t value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

template <typename T>
std::vector<std::byte> poked(std::vector<std::byte> bytes, size_t offset, T value) {
    std::memcpy(bytes.data() + offset, &value, sizeof value);
    return bytes;
}

inline std::vector<std::byte> prefix(const std::vector<std::byte>& bytes, size_t length) {
    return {bytes.begin(), bytes.begin() + std::ptrdiff_t(length)};
}

inline std::vector<std::byte> bytesOf(const std::string& text) {
    const auto* data = reinterpret_cast<const std::byte*>(text.data());
    return {data, data + text.size()};
}

inline std::filesystem::path writeBytes(const std::filesystem::path& path, const std::vector<std::byte>& bytes) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

// The message of the ImageError `action` throws; a test failure when it throws nothing, throws
// something else, or the message is not one line.
template <typename Action>
std::string imageErrorOf(Action&& action) {
    try {
        action();
    } catch (const image_io::ImageError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
        return message;
    } catch (const std::exception& error) {
        ADD_FAILURE() << "expected an ImageError, got: " << error.what();
        return error.what();
    }
    ADD_FAILURE() << "expected an ImageError, nothing was thrown";
    return "";
}

// True when one of the violations mentions `part`.
inline bool mentions(const std::vector<std::string>& violations, const std::string& part) {
    for (const auto& violation : violations)
        if (violation.find(part) != std::string::npos) return true;
    return false;
}

} // namespace iblkit::testing
