#include "kernels/compiled_kernel_cache.hpp"

#include "cache_error.hpp"
#include "cache_key.hpp"
#include "compiler.hpp"
#include "content_store.hpp"
#include "sha256.hpp"

#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

namespace iblkit::kernels {
namespace {

using nlohmann::json;

thread_local CompiledKernelCache* cacheInUse = nullptr;

std::string keyOf(const compiler::CompileOptions& options) {
    cache::CacheKey key;
    key.add("entry", "compiled kernel").add("program", cache::programDigest());
    key.add("source", options.source.generic_string()).add("text", *options.sourceText);
    key.add("entry point", options.entryPoint).add("stage", options.stage ? compiler::stageName(*options.stage) : "");
    for (const auto& folder : options.includeDirs) key.add("include folder", folder.generic_string());
    for (const auto& [name, value] : options.defines) key.add("define", name).add("value", value);
    for (const auto& [name, format] : options.imageFormats) key.add("image", name).add("format", format);
    for (const uint32_t shift : options.bindingShifts.shift) key.add("shift", shift);
    key.add("optimization", uint64_t(options.optimization)).add("strip", options.stripDebugInfo);
    key.add("hlsl", uint64_t(options.hlslVersion)).add("16-bit types", options.enable16BitTypes);
    return key.hex();
}

// An included file as the compiler would read it now: served from memory first, then the disk.
std::optional<std::string> includedText(const compiler::CompileOptions& options, const std::string& name) {
    if (const auto found = options.virtualFiles.find(name); found != options.virtualFiles.end()) return found->second;
    std::ifstream in(name, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

bool includesUnchanged(const compiler::CompileOptions& options, const json& includes) {
    for (const auto& include : includes) {
        const auto text = includedText(options, include.at(0));
        if (!text || cache::sha256Hex(*text) != include.at(1)) return false;
    }
    return true;
}

std::string payloadOf(const compiler::CompileOptions& options, const compiler::CompiledShader& shader) {
    json includes = json::array();
    for (const auto& name : shader.includedFiles)
        if (const auto text = includedText(options, name)) includes.push_back({name, cache::sha256Hex(*text)});
    const auto* words = reinterpret_cast<const uint8_t*>(shader.spirv.data());
    const json payload = {{"includes", std::move(includes)},
                          {"spirv", json::binary({words, words + shader.spirv.size() * 4})},
                          {"reflection", compiler::toJson(shader.reflection)}};
    const auto bytes = json::to_cbor(payload);
    return {bytes.begin(), bytes.end()};
}

std::vector<uint32_t> wordsOf(const json::binary_t& bytes) {
    if (bytes.size() % 4 != 0 || bytes.empty()) throw std::invalid_argument("SPIR-V is not whole words");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    return words;
}

} // namespace

CompiledKernelCache::CompiledKernelCache(const std::filesystem::path& folder, cache::ContentStore::Access access)
    : store_(std::make_unique<cache::ContentStore>(folder, access)) {}

CompiledKernelCache::~CompiledKernelCache() = default;

std::optional<KernelProgram> CompiledKernelCache::find(const compiler::CompileOptions& options) {
    if (!options.sourceText) return std::nullopt;
    const auto key = keyOf(options);
    const std::lock_guard lock(mutex_);
    const size_t damagedBefore = store_->counts().corrupt;
    const auto payload = store_->get(key);
    counts_.damaged += store_->counts().corrupt - damagedBefore;
    try {
        if (payload) {
            const auto entry = json::from_cbor(*payload);
            if (!includesUnchanged(options, entry.at("includes"))) {
                ++counts_.stale;
            } else {
                KernelProgram program{wordsOf(entry.at("spirv").get_binary()), compiler::reflectionFromJson(entry.at("reflection"))};
                ++counts_.hits;
                return program;
            }
        }
    } catch (const std::exception&) {
        ++counts_.damaged; // its checksum held, yet it does not parse: written by another program
    }
    ++counts_.misses;
    return std::nullopt;
}

void CompiledKernelCache::keep(const compiler::CompileOptions& options, const compiler::CompiledShader& shader) {
    if (!options.sourceText) return;
    const auto key = keyOf(options);
    const auto payload = payloadOf(options, shader);
    const std::lock_guard lock(mutex_);
    try {
        store_->put(key, payload);
    } catch (const cache::CacheError&) {
        ++counts_.unwritable;
    }
}

CompiledKernelCache::Counts CompiledKernelCache::counts() const {
    const std::lock_guard lock(mutex_);
    return counts_;
}

UseCompiledKernelCache::UseCompiledKernelCache(CompiledKernelCache* cache) : previous_(std::exchange(cacheInUse, cache)) {}

UseCompiledKernelCache::~UseCompiledKernelCache() { cacheInUse = previous_; }

CompiledKernelCache* compiledKernelCacheInUse() { return cacheInUse; }

} // namespace iblkit::kernels
