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

constexpr std::string_view kMagic = "IBLKCAS1"; // then the payload's SHA-256 in hex, a newline, the payload
constexpr size_t kHeader = 8 + 64 + 1;

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
    const bool whole = entry->size() >= kHeader && std::string_view(*entry).substr(0, 8) == kMagic && (*entry)[72] == '\n';
    if (!whole || entry->compare(8, 64, sha256Hex(std::string_view(*entry).substr(kHeader))) != 0) {
        std::error_code ignored;
        fs::remove(path, ignored); // damaged: computed again and written anew
        ++counts_.corrupt;
        ++counts_.misses;
        return std::nullopt;
    }
    ++counts_.hits;
    entry->erase(0, kHeader);
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
        out << kMagic << sha256Hex(payload) << '\n';
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
