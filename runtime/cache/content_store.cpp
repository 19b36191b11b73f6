#include "content_store.hpp"

#include "cache_error.hpp"
#include "sha256.hpp"

#include <algorithm>
#include <atomic>
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

std::string headerOf(const std::string& key, std::string_view payload) { return keyLine(key) + sha256Hex(payload) + '\n'; }

size_t headerSize(const std::string& key) { return keyLine(key).size() + 64 + 1; }

// An entry read in two parts: the header (the key line and the payload's hash) and the payload,
// each straight into its own string, so that a payload of tens of megabytes is neither moved nor
// copied after it is read.
struct Entry {
    std::string header, payload;
};

std::optional<Entry> readEntry(const fs::path& path, const std::string& key) {
    std::error_code error;
    const auto size = fs::file_size(path, error);
    std::ifstream in(path, std::ios::binary);
    if (error || !in) return std::nullopt;
    Entry entry;
    entry.header.resize(std::min<size_t>(size, headerSize(key)));
    entry.payload.resize(size - entry.header.size());
    if (!in.read(entry.header.data(), std::streamsize(entry.header.size())) ||
        !in.read(entry.payload.data(), std::streamsize(entry.payload.size())))
        return std::nullopt;
    return entry;
}

// Whether `entry` is whole and holds `key`'s value.
bool holds(const Entry& entry, const std::string& key) {
    const auto prefix = keyLine(key);
    const auto& header = entry.header;
    if (header.size() != headerSize(key) || !header.starts_with(prefix) || header.back() != '\n') return false;
    return std::string_view(header).substr(prefix.size(), 64) == sha256Hex(entry.payload);
}

// A name no other writer, in this process or another, uses at the same time.
fs::path temporaryBeside(const fs::path& path) {
    static std::atomic<uint64_t> counter{0};
    return fs::path(path.string() + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
}

} // namespace

ContentStore::ContentStore(fs::path folder) : folder_(std::move(folder)) {}

fs::path ContentStore::pathOf(const std::string& key) const { return folder_ / "objects" / key.substr(0, 2) / key; }

std::optional<std::string> ContentStore::get(const std::string& key) {
    const auto path = pathOf(key);
    auto entry = readEntry(path, key);
    if (!entry) {
        ++counts_.misses;
        return std::nullopt;
    }
    if (!holds(*entry, key)) {
        std::error_code ignored;
        fs::remove(path, ignored); // damaged, or of the earlier format: computed again and written anew
        if (!entry->header.starts_with(kEarlierMagic)) ++counts_.corrupt;
        ++counts_.misses;
        return std::nullopt;
    }
    ++counts_.hits;
    return std::move(entry->payload);
}

void ContentStore::put(const std::string& key, std::string_view payload) {
    const auto path = pathOf(key);
    std::error_code error;
    fs::create_directories(path.parent_path(), error);
    if (error) throw CacheError(path.parent_path().string() + ": error: cannot make the cache folder: " + error.message());
    const auto temporary = temporaryBeside(path);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << headerOf(key, payload);
        out.write(payload.data(), std::streamsize(payload.size()));
        if (!out) {
            fs::remove(temporary, error);
            throw CacheError(temporary.string() + ": error: cannot write the cache entry");
        }
    }
    fs::rename(temporary, path, error);
    if (error) {
        fs::remove(temporary, error);
        throw CacheError(path.string() + ": error: cannot put the cache entry in place");
    }
}

fs::path ContentStore::defaultFolder() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "iblkit";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "iblkit";
    return fs::path("build") / "cache";
}

} // namespace iblkit::cache
