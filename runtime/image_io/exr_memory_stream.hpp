#pragma once

#include <ImfIO.h>

#include <cstddef>
#include <span>
#include <string>

namespace iblkit::image_io {

// An EXR file's bytes as an Imf::IStream, so the file is opened once, by readFileBytes, and a
// missing file gets the system's reason.
class ExrMemoryStream : public Imf::IStream {
public:
    ExrMemoryStream(std::span<const std::byte> bytes, const char* name) : Imf::IStream(name), bytes_(bytes) {}

    bool read(char c[], int n) override;
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override { position_ = position; }

private:
    std::span<const std::byte> bytes_;
    uint64_t position_ = 0;
};

// The other way: an EXR file written into memory, for outputs that are committed all at once.
class ExrMemoryOutput : public Imf::OStream {
public:
    explicit ExrMemoryOutput(const char* name) : Imf::OStream(name) {}

    void write(const char c[], int n) override;
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = position; }
    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
    uint64_t position_ = 0;
};

} // namespace iblkit::image_io
