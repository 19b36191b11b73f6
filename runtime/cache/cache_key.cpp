#include "cache_key.hpp"

#include "sha256.hpp"

#include <span>

namespace iblkit::cache {

CacheKey& CacheKey::add(std::string_view label, std::string_view value) {
    parts_ += std::string(label) + ":" + std::to_string(value.size()) + ":";
    parts_ += value;
    parts_ += ';';
    return *this;
}

CacheKey& CacheKey::add(std::string_view label, uint64_t value) { return add(label, std::to_string(value)); }

CacheKey& CacheKey::add(std::string_view label, const std::vector<bool>& flags) {
    std::string text;
    for (const bool flag : flags) text += flag ? '1' : '0';
    return add(label, text);
}

std::string CacheKey::hex() const { return sha256Hex(std::string_view(parts_)); }

} // namespace iblkit::cache
