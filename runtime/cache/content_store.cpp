#include "content_store.hpp"

#include "cache_error.hpp"
#include "sha256.hpp"

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

// The payload of `entry` if it is whole and holds `key`'s value.
std::optional<std::string_view> payloadOf(std::string_view entry, const std::string& key) {
    const auto prefix = keyLine(key);
    const size_t header = prefix.size() + 64 + 1;
    if (entry.size() < header || !entry.starts_with(prefix) || entry[header - 1] != '\n') return std::nullopt;
    const auto payload = entry.substr(header);
    if (entry.substr(prefix.size(), 64) != sha256Hex(payload)) return std::nullopt;
    return payload;
}

std::optional<std::string> readWhole(const fs::path& path) {
    std::error_code error;
    const auto size = fs::file_size(path, error);
    std::ifstream in(path, std::ios::binary);
    if (error || !in) return std::nullopt;
    std::string bytes(size, '\0'); // read once, in place: entries are tens of megabytes at large sizes
    if (!in.read(bytes.data(), std::streamsize(size))) return std::nullopt;
    return bytes;
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
    auto entry = readWhole(path);
    if (!entry) {
        ++counts_.misses;
        return std::nullopt;
    }
    const auto payload = payloadOf(*entry, key);
    if (!payload) {
        std::error_code ignored;
        fs::remove(path, ignored); // damaged, or of the earlier format: computed again and written anew
        if (!entry->starts_with(kEarlierMagic)) ++counts_.corrupt;
        ++counts_.misses;
        return std::nullopt;
    }
    ++counts_.hits;
    entry->erase(0, entry->size() - payload->size());
    return entry;
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
