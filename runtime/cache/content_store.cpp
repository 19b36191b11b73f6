#include "content_store.hpp"

#include "cache_error.hpp"
#include "left_behind.hpp"
#include "mapped_file.hpp"
#include "sha256.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <span>
#include <unistd.h>

namespace iblkit::cache {
namespace {

namespace fs = std::filesystem;

// Then the entry's key and a newline, the payload's SHA-256 in hex and a newline, the payload. The
// key inside the entry makes one copied or renamed to another key's path damaged, not another's
// value.
constexpr std::string_view kMagic = "IBLKCAS2";
// Entries of the first format, which carried no key: misses, replaced, not damaged.
constexpr std::string_view kEarlierMagic = "IBLKCAS1";

std::string keyLine(const std::string& key) { return std::string(kMagic) + key + '\n'; }

size_t headerSize(const std::string& key) { return keyLine(key).size() + 64 + 1; }

// Whether `entry` is whole and holds `key`'s value: its key line, then the payload's hash.
bool holds(std::string_view entry, const std::string& key) {
    const auto prefix = keyLine(key);
    const size_t header = headerSize(key);
    if (entry.size() < header || !entry.starts_with(prefix) || entry[header - 1] != '\n') return false;
    return entry.substr(prefix.size(), 64) == sha256Hex(entry.substr(header));
}

// A file beside `path` that no other writer uses: made by mkstemp (O_EXCL), so not by another
// process on this machine nor, on a shared folder, on another machine (whose process ids overlap
// this one's). Its name holds the writer's host and process id, so that one a killed writer left
// can be told from one a live writer is still filling.
fs::path temporaryBeside(const fs::path& path) {
    std::string name = path.string() + ".tmp-" + files::writerTag() + "-XXXXXX";
    const int descriptor = mkstemp(name.data());
    if (descriptor < 0) throw CacheError(path.parent_path().string() + ": error: cannot make a cache entry there: " +
                                         std::generic_category().message(errno));
    close(descriptor);
    return name;
}

} // namespace

ContentStore::ContentStore(fs::path folder, Access access) : folder_(std::move(folder)), access_(access) {}

fs::path ContentStore::pathOf(const std::string& key) const { return folder_ / "objects" / key.substr(0, 2) / key; }

std::optional<std::string> ContentStore::get(const std::string& key) {
    const auto entry = read(key, counts_);
    return entry ? std::optional<std::string>(entry->payload()) : std::nullopt;
}

std::optional<ContentStore::Payload> ContentStore::getInPlace(const std::string& key) { return read(key, counts_); }

std::optional<std::string> ContentStore::peek(const std::string& key) {
    Counts uncounted;
    const auto entry = read(key, uncounted);
    return entry ? std::optional<std::string>(entry->payload()) : std::nullopt;
}

std::optional<ContentStore::Payload> ContentStore::read(const std::string& key, Counts& counts) {
    const auto path = pathOf(key);
    auto file = MappedFile::open(path);
    if (!file) {
        ++counts.misses;
        return std::nullopt;
    }
    if (!holds(file->bytes(), key)) {
        std::error_code ignored;
        if (access_ == Access::ReadWrite) fs::remove(path, ignored); // damaged, or of the earlier format: computed again and written anew
        if (!file->bytes().starts_with(kEarlierMagic)) ++counts.corrupt;
        ++counts.misses;
        return std::nullopt;
    }
    ++counts.hits;
    return Payload(std::move(*file), headerSize(key));
}

void ContentStore::put(const std::string& key, std::string_view payload) { put(key, std::span(&payload, 1)); }

void ContentStore::put(const std::string& key, std::span<const std::string_view> payload) {
    const auto path = pathOf(key);
    if (access_ == Access::ReadOnly) throw CacheError(folder_.string() + ": error: the store is read-only");
    std::error_code error;
    fs::create_directories(path.parent_path(), error);
    if (error) throw CacheError(path.parent_path().string() + ": error: cannot make the cache folder: " + error.message());
    const auto temporary = temporaryBeside(path);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << keyLine(key) << sha256Hex(payload) << '\n';
        for (const auto part : payload) out.write(part.data(), std::streamsize(part.size()));
        out.close(); // a full disk may first show when the last bytes are written
        if (out.fail()) {
            const int why = errno;
            fs::remove(temporary, error);
            throw CacheError(temporary.string() + ": error: cannot write the cache entry: " + std::generic_category().message(why));
        }
    }
    fs::rename(temporary, path, error);
    if (error) {
        fs::remove(temporary, error);
        throw CacheError(path.string() + ": error: cannot put the cache entry in place: " + error.message());
    }
    files::removeLeftBehind(path.parent_path(), ".tmp-"); // what killed writers left in this folder
}

fs::path ContentStore::defaultFolder() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "iblkit";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "iblkit";
    return fs::path("build") / "cache";
}

} // namespace iblkit::cache
