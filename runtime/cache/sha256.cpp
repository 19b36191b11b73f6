#include "sha256.hpp"

#include "cache_error.hpp"
#include "files.hpp"

#include <openssl/evp.h>

#include <memory>

namespace iblkit::cache {
namespace {

class Sha256 {
public:
    Sha256() : context_(EVP_MD_CTX_new(), EVP_MD_CTX_free) {
        if (!context_ || EVP_DigestInit_ex(context_.get(), EVP_sha256(), nullptr) != 1)
            throw CacheError("OpenSSL could not start a SHA-256 digest");
    }
    void add(const void* data, size_t size) { EVP_DigestUpdate(context_.get(), data, size); }
    std::string hex() {
        std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
        unsigned int length = 0;
        EVP_DigestFinal_ex(context_.get(), digest.data(), &length);
        static constexpr char kDigits[] = "0123456789abcdef";
        std::string text;
        for (unsigned int i = 0; i < length; ++i) text += {kDigits[digest[i] >> 4], kDigits[digest[i] & 15]};
        return text;
    }

private:
    std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context_;
};

} // namespace

std::string sha256Hex(std::span<const std::byte> bytes) {
    Sha256 digest;
    digest.add(bytes.data(), bytes.size());
    return digest.hex();
}

std::string sha256OfFile(const std::filesystem::path& path) {
    Sha256 digest; // a chunk at a time: outputs can be larger than memory wants to hold twice
    image_io::readFileInChunks(path, [&](std::span<const std::byte> chunk) { digest.add(chunk.data(), chunk.size()); });
    return digest.hex();
}

} // namespace iblkit::cache
