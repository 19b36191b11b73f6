#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>

namespace iblkit::cache {

// A file mapped read-only, unmapped when the object goes. Reading a large cache entry in place
// saves a copy into fresh memory, whose first touch is the slow part of reading it. The store
// replaces entries by renaming, never by writing into them, so a mapped entry never changes
// under its reader.
class MappedFile {
public:
    // None when the file cannot be opened or mapped, or is not a regular file.
    static std::optional<MappedFile> open(const std::filesystem::path& path);
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&& other) noexcept;
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    ~MappedFile();

    std::string_view bytes() const { return address_ ? std::string_view(static_cast<const char*>(address_), size_) : std::string_view(); }

private:
    MappedFile(void* address, size_t size) : address_(address), size_(size) {}
    void* address_ = nullptr;
    size_t size_ = 0;
};

} // namespace iblkit::cache
