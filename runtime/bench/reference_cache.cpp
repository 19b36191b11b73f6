#include "reference_cache.hpp"

#include "bench_error.hpp"
#include "sha256.hpp"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <unistd.h>

namespace iblkit::bench {
namespace {

namespace fs = std::filesystem;

// "IBLKREF1", the value count, then the doubles in the machine's byte order.
constexpr char kMagic[8] = {'I', 'B', 'L', 'K', 'R', 'E', 'F', '1'};

bool readEntry(const fs::path& path, size_t expected, std::vector<double>& values) {
    std::error_code error;
    if (fs::file_size(path, error) != 16 + expected * sizeof(double) || error) return false;
    std::ifstream in(path, std::ios::binary);
    char magic[8];
    uint64_t count = 0;
    if (!in.read(magic, 8) || std::string_view(magic, 8) != std::string_view(kMagic, 8)) return false;
    if (!in.read(reinterpret_cast<char*>(&count), sizeof count) || count != expected) return false;
    values.resize(count);
    return bool(in.read(reinterpret_cast<char*>(values.data()), std::streamsize(count * sizeof(double))));
}

void writeEntry(const fs::path& path, const std::vector<double>& values) {
    fs::create_directories(path.parent_path());
    const auto temporary = fs::path(path.string() + ".tmp." + std::to_string(getpid()));
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        const uint64_t count = values.size();
        out.write(kMagic, 8);
        out.write(reinterpret_cast<const char*>(&count), sizeof count);
        out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(count * sizeof(double)));
        if (!out) throw BenchError("could not write the reference cache entry " + temporary.string());
    }
    fs::rename(temporary, path);
}

} // namespace

std::string ReferenceCache::key(const std::string& what, std::span<const std::byte> input) {
    std::vector<std::byte> bytes(what.size());
    std::memcpy(bytes.data(), what.data(), what.size());
    bytes.push_back(std::byte{0});
    bytes.insert(bytes.end(), input.begin(), input.end());
    return bake::sha256Hex(bytes);
}

std::vector<double> ReferenceCache::getOrCompute(const std::string& key, size_t count,
                                                 const std::function<std::vector<double>()>& compute, bool* hit) const {
    const auto path = folder_ / "references" / (key + ".bin");
    std::vector<double> values;
    const bool cached = fs::exists(path) && readEntry(path, count, values);
    if (hit) *hit = cached;
    if (cached) return values;
    values = compute();
    if (values.size() != count)
        throw BenchError("internal error: a reference has " + std::to_string(values.size()) + " values, not " +
                         std::to_string(count));
    writeEntry(path, values);
    return values;
}

fs::path ReferenceCache::defaultFolder() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "iblkit";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "iblkit";
    return fs::path("build") / "cache";
}

} // namespace iblkit::bench
