#include "reference_cache.hpp"

#include "bench_error.hpp"
#include "cache_key.hpp"
#include "content_store.hpp"

#include <cstring>

namespace iblkit::bench {
namespace {

namespace fs = std::filesystem;

std::string payloadOf(const std::vector<double>& values) {
    return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
}

} // namespace

std::string ReferenceCache::key(const std::string& what, std::span<const std::byte> input) {
    const auto bytes = std::string_view(reinterpret_cast<const char*>(input.data()), input.size());
    return cache::CacheKey().add("reference", what).add("input", bytes).hex();
}

std::vector<double> ReferenceCache::getOrCompute(const std::string& key, size_t count,
                                                 const std::function<std::vector<double>()>& compute, bool* hit) const {
    cache::ContentStore store(folder_);
    const auto entry = store.get(key);
    const bool cached = entry && entry->size() == count * sizeof(double);
    if (hit) *hit = cached;
    if (cached) {
        std::vector<double> values(count);
        std::memcpy(values.data(), entry->data(), entry->size());
        return values;
    }
    auto values = compute();
    if (values.size() != count)
        throw BenchError("internal error: a reference has " + std::to_string(values.size()) + " values, not " +
                         std::to_string(count));
    store.put(key, payloadOf(values));
    return values;
}

fs::path ReferenceCache::defaultFolder() { return cache::ContentStore::defaultFolder(); }

} // namespace iblkit::bench
