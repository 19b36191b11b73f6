#include "sha256.hpp"

#include "cache_error.hpp"
#include "files.hpp"

#include <openssl/evp.h>

#include <cstring>
#include <link.h>
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

std::string sha256Hex(std::span<const std::string_view> parts) {
    Sha256 digest;
    for (const auto part : parts) digest.add(part.data(), part.size());
    return digest.hex();
}

std::string sha256OfFile(const std::filesystem::path& path) {
    Sha256 digest; // a chunk at a time: outputs can be larger than memory wants to hold twice
    image_io::readFileInChunks(path, [&](std::span<const std::byte> chunk) { digest.add(chunk.data(), chunk.size()); });
    return digest.hex();
}

namespace {

// The GNU build id the linker wrote into the program (a hash of its whole contents), read from its
// loaded note segments; "" when it has none.
std::string buildIdOfProgram() {
    std::string id;
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* result) {
            for (int i = 0; i < info->dlpi_phnum; ++i) {
                const auto& header = info->dlpi_phdr[i];
                if (header.p_type != PT_NOTE) continue;
                const auto* at = reinterpret_cast<const unsigned char*>(info->dlpi_addr + header.p_vaddr);
                const auto* end = at + header.p_memsz;
                while (at + sizeof(ElfW(Nhdr)) <= end) {
                    const auto* note = reinterpret_cast<const ElfW(Nhdr)*>(at);
                    const auto* name = at + sizeof(ElfW(Nhdr));
                    const auto* descriptor = name + ((note->n_namesz + 3) & ~3u);
                    if (note->n_type == NT_GNU_BUILD_ID && note->n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0) {
                        *static_cast<std::string*>(result) = sha256Hex(std::as_bytes(std::span(descriptor, note->n_descsz)));
                        return 1;
                    }
                    at = descriptor + ((note->n_descsz + 3) & ~3u);
                }
            }
            return 1; // the first object is the program itself
        },
        &id);
    return id;
}

} // namespace

std::string sha256Hex(std::string_view text) { return sha256Hex(std::as_bytes(std::span(text.data(), text.size()))); }

const std::string& programDigest() {
    // Without a build id, the program file's own bytes (slower: it is read whole).
    static const std::string digest = [] {
        auto id = buildIdOfProgram();
        return id.empty() ? sha256OfFile("/proc/self/exe") : id;
    }();
    return digest;
}

} // namespace iblkit::cache
