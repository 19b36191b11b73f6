#pragma once

#include "image_error.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace iblkit::image_io {

// KTX2 and DDS are little-endian; so is every machine the kit builds for.
static_assert(std::endian::native == std::endian::little);

// Appends little-endian values to a growing byte vector.
class ByteWriter {
public:
    template <typename T>
    void put(T value) {
        const auto* bytes = reinterpret_cast<const std::byte*>(&value);
        data_.insert(data_.end(), bytes, bytes + sizeof(T));
    }
    void putBytes(std::span<const std::byte> bytes) { data_.insert(data_.end(), bytes.begin(), bytes.end()); }
    void putZeros(size_t count) { data_.insert(data_.end(), count, std::byte{0}); }
    void padTo(size_t alignment) { putZeros((alignment - data_.size() % alignment) % alignment); }
    template <typename T>
    void putAt(size_t offset, T value) { std::memcpy(data_.data() + offset, &value, sizeof(T)); }
    size_t size() const { return data_.size(); }
    std::vector<std::byte> take() { return std::move(data_); }

private:
    std::vector<std::byte> data_;
};

// Reads little-endian values from a file's bytes. A read past the end is an ImageError
// "'name' is truncated: <what> needs N bytes, the file has M".
class ByteReader {
public:
    ByteReader(std::span<const std::byte> bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {}

    template <typename T>
    T get(uint64_t offset, const std::string& what) const {
        require(offset, sizeof(T), what);
        T value;
        std::memcpy(&value, bytes_.data() + offset, sizeof(T));
        return value;
    }
    std::span<const std::byte> slice(uint64_t offset, uint64_t length, const std::string& what) const {
        require(offset, length, what);
        return bytes_.subspan(size_t(offset), size_t(length));
    }
    bool contains(uint64_t offset, uint64_t length) const {
        return offset <= bytes_.size() && length <= bytes_.size() - offset;
    }
    void require(uint64_t offset, uint64_t length, const std::string& what) const {
        if (bytes_.empty()) fail("is empty");
        if (!contains(offset, length)) {
            const std::string needed = offset > UINT64_MAX - length ? "more than 2^64" : std::to_string(offset + length);
            fail("is truncated: " + what + " needs " + needed + " bytes, the file has " +
                 std::to_string(bytes_.size()));
        }
    }
    size_t size() const { return bytes_.size(); }
    // Throws ImageError "'name' <problem>".
    [[noreturn]] void fail(const std::string& problem) const { throw ImageError("'" + name_ + "' " + problem); }

private:
    std::span<const std::byte> bytes_;
    std::string name_;
};

} // namespace iblkit::image_io
