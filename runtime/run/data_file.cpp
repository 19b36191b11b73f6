#include "data_file.hpp"

#include "half_float.hpp"
#include "run_error.hpp"

#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <type_traits>

namespace iblkit::run {
namespace {

std::string slurp(const std::filesystem::path& path) {
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw RunError(path.string() + ": error: cannot read the data file");
    std::ostringstream bytes;
    bytes << stream.rdbuf();
    return bytes.str();
}

bool isNpy(const std::filesystem::path& path) { return path.extension() == ".npy"; }

struct HalfBits {
    uint16_t bits;
};

template <typename T>
void appendAll(const char* data, size_t count, std::vector<double>& values) {
    for (size_t i = 0; i < count; ++i) {
        T value;
        std::memcpy(&value, data + i * sizeof(T), sizeof(T));
        if constexpr (std::is_same_v<T, HalfBits>) values.push_back(numeric::fromHalfBits(value.bits));
        else values.push_back(static_cast<double>(value));
    }
}

std::vector<double> readNpy(const std::filesystem::path& path) {
    const std::string bytes = slurp(path);
    const auto fail = [&](const std::string& why) -> RunError { return RunError(path.string() + ": error: " + why); };
    if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0) throw fail("not a .npy file");
    const int major = static_cast<unsigned char>(bytes[6]);
    const size_t lengthBytes = major == 1 ? 2 : 4;
    size_t headerLength = 0;
    std::memcpy(&headerLength, bytes.data() + 8, lengthBytes);
    const size_t dataStart = 8 + lengthBytes + headerLength;
    if (dataStart > bytes.size()) throw fail("truncated .npy header");
    const std::string header = bytes.substr(8 + lengthBytes, headerLength);
    std::smatch match;
    if (!std::regex_search(header, match, std::regex(R"('descr':\s*'([<|=]?)([fiu])(\d)')")))
        throw fail("unsupported .npy dtype in header " + header);
    if (std::regex_search(header, std::regex(R"('fortran_order':\s*True)"))) throw fail("Fortran-ordered .npy arrays are not supported");
    const char kind = match[2].str()[0];
    const int size = std::stoi(match[3]);
    const size_t count = (bytes.size() - dataStart) / size;
    if ((bytes.size() - dataStart) % size != 0) throw fail("data is not a whole number of elements");
    const char* data = bytes.data() + dataStart;
    std::vector<double> values;
    values.reserve(count);
    if (kind == 'f' && size == 4) appendAll<float>(data, count, values);
    else if (kind == 'f' && size == 2) appendAll<HalfBits>(data, count, values);
    else if (kind == 'f' && size == 8) appendAll<double>(data, count, values);
    else if (kind == 'i' && size == 4) appendAll<int32_t>(data, count, values);
    else if (kind == 'u' && size == 4) appendAll<uint32_t>(data, count, values);
    else if (kind == 'u' && size == 1) appendAll<uint8_t>(data, count, values);
    else throw fail(std::string("unsupported .npy dtype ") + kind + std::to_string(size));
    return values;
}

// The values as little-endian elements of type T.
template <typename T>
std::string elementBytes(const std::vector<double>& values) {
    std::string bytes(values.size() * sizeof(T), '\0');
    for (size_t i = 0; i < values.size(); ++i) {
        const auto element = static_cast<T>(values[i]);
        std::memcpy(bytes.data() + i * sizeof(T), &element, sizeof(T));
    }
    return bytes;
}

// float32 for float and unorm formats; the integer formats' own uint32 or int32, every value exact.
std::string npyBytes(const std::vector<double>& values, const std::vector<size_t>& shape, const vulkan::TexelFormat& format) {
    const bool unsignedInteger = format.kind == vulkan::ComponentKind::UInt, signedInteger = format.kind == vulkan::ComponentKind::SInt;
    // Python's tuple spelling: "(7,)" for one dimension, "(2, 3)" for more.
    std::string shapeText = "(";
    for (size_t i = 0; i < shape.size(); ++i) shapeText += std::to_string(shape[i]) + (i + 1 < shape.size() ? ", " : "");
    shapeText += shape.size() == 1 ? ",)" : ")";
    const char* type = unsignedInteger ? "<u4" : signedInteger ? "<i4" : "<f4";
    std::string header = std::string("{'descr': '") + type + "', 'fortran_order': False, 'shape': " + shapeText + ", }";
    // The whole preamble is padded with spaces to a multiple of 64 bytes, ending in a newline.
    const size_t preamble = 10 + header.size() + 1;
    header.append((64 - preamble % 64) % 64, ' ');
    header += '\n';
    std::string bytes = "\x93NUMPY\x01";
    bytes += '\0';
    const auto length = static_cast<uint16_t>(header.size());
    bytes.append(reinterpret_cast<const char*>(&length), 2);
    bytes += header;
    bytes += unsignedInteger ? elementBytes<uint32_t>(values) : signedInteger ? elementBytes<int32_t>(values) : elementBytes<float>(values);
    return bytes;
}

} // namespace

std::vector<double> readValues(const std::filesystem::path& path, const vulkan::TexelFormat& format) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw RunError(path.string() + ": error: no such data file");
    if (!std::filesystem::is_regular_file(path, error))
        throw RunError(path.string() + ": error: the data file is not a regular file (a folder, a device or a pipe)");
    if (isNpy(path)) return readNpy(path);
    const std::string bytes = slurp(path);
    if (bytes.size() % format.bytesPerChannel != 0)
        throw RunError(path.string() + ": error: holds " + std::to_string(bytes.size()) + " bytes, not a whole number of " +
                       std::string(format.name) + " components");
    std::vector<double> values(bytes.size() / format.bytesPerChannel);
    vulkan::decodeTexels(format, std::as_bytes(std::span(bytes.data(), bytes.size())), values);
    return values;
}

std::vector<double> readValues(const std::filesystem::path& path, const vulkan::TexelFormat& format, size_t expectedCount) {
    auto values = readValues(path, format);
    if (values.size() != expectedCount)
        throw RunError(path.string() + ": error: holds " + std::to_string(values.size()) + " values, not " +
                       std::to_string(expectedCount));
    return values;
}

std::string encodeValues(const std::filesystem::path& path, const vulkan::TexelFormat& format,
                         const std::vector<double>& values, const std::vector<size_t>& shape) {
    if (isNpy(path)) return npyBytes(values, shape, format);
    std::string bytes(values.size() * format.bytesPerChannel, '\0');
    vulkan::encodeTexels(format, values, std::as_writable_bytes(std::span(bytes.data(), bytes.size())));
    return bytes;
}

} // namespace iblkit::run
