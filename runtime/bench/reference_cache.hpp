#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace iblkit::bench {

// Converged references are slow, so each is kept in the content store (runtime/cache/) under the
// SHA-256 of everything it depends on.
class ReferenceCache {
public:
    explicit ReferenceCache(std::filesystem::path folder) : folder_(std::move(folder)) {}

    // The key: what the reference is ("prefilter v1"), its parameters and its input's bytes.
    static std::string key(const std::string& what, std::span<const std::byte> input);

    // The cached values of `key`, or compute() stored under it; an entry that does not hold
    // exactly `count` values is computed again. `hit` tells which it was.
    std::vector<double> getOrCompute(const std::string& key, size_t count,
                                     const std::function<std::vector<double>()>& compute, bool* hit = nullptr) const;

    // The default folder: $XDG_CACHE_HOME/iblkit, else ~/.cache/iblkit, else build/cache.
    static std::filesystem::path defaultFolder();

private:
    std::filesystem::path folder_;
};

} // namespace iblkit::bench
