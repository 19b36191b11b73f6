#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit::cache {

// The name of a cache entry: the SHA-256 of every labelled part it depends on. Each part is
// written with its label and its length, so no two different lists of parts collide by
// concatenation ("ab" + "c" is not "a" + "bc").
class CacheKey {
public:
    CacheKey& add(std::string_view label, std::string_view value);
    CacheKey& add(std::string_view label, uint64_t value);
    CacheKey& add(std::string_view label, const std::vector<bool>& flags);
    std::string hex() const; // 64 hex digits

private:
    std::string parts_;
};

} // namespace iblkit::cache
