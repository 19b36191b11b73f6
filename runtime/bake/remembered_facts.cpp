#include "remembered_facts.hpp"

#include "cache_error.hpp"
#include "cache_key.hpp"
#include "content_store.hpp"
#include "sha256.hpp"

#include <nlohmann/json.hpp>

#include <cstdlib>

namespace iblkit::bake {
namespace {

using nlohmann::json;

std::string factsKey(const EnvironmentInput& input) {
    cache::CacheKey key;
    key.add("entry", "input facts").add("program", cache::programDigest());
    key.add("input kind", std::string(inputKindName(input.kind)));
    for (const auto& file : input.files) key.add("input file", file.sha256);
    return key.add("sanitize", uint64_t(input.policy.sanitize)).add("strict", uint64_t(input.policy.strict)).hex();
}

// The choice of device and what the Vulkan loader reads to find the devices it chooses from.
std::string deviceKey(const vulkan::ContextOptions& options) {
    cache::CacheKey key;
    key.add("entry", "device identity").add("program", cache::programDigest()).add("device", options.device);
    for (const char* variable : {"IBLKIT_DEVICE", "VK_ICD_FILENAMES", "VK_DRIVER_FILES", "VK_ADD_DRIVER_FILES"}) {
        const char* value = std::getenv(variable);
        key.add(variable, value ? value : "(unset)");
    }
    return key.hex();
}

// A cache that cannot be written costs the next bake its time: the maps' own entries report why.
void putQuietly(cache::ContentStore& store, const std::string& key, const std::string& payload) {
    try {
        store.put(key, payload);
    } catch (const cache::CacheError&) {
    }
}

template <typename T> std::optional<T> parsed(const std::optional<std::string>& payload, T (*read)(const json&)) {
    if (!payload) return std::nullopt;
    const auto value = json::parse(*payload, nullptr, false);
    if (value.is_discarded() || !value.is_object()) return std::nullopt;
    try {
        return read(value);
    } catch (const json::exception&) {
        return std::nullopt;
    }
}

InputFacts factsFromJson(const json& value) {
    return {value.at("panorama_width").get<uint32_t>(), value.at("panorama_height").get<uint32_t>(),
            value.at("cube_size").get<uint32_t>(), value.at("sanitized_texels").get<size_t>(),
            {value.at("negative_texels").get<size_t>(), value.at("most_negative").get<float>()}};
}

vulkan::DeviceInfo deviceFromJson(const json& value) {
    return {value.at("index").get<uint32_t>(), value.at("name").get<std::string>(), value.at("type").get<std::string>(),
            value.at("driver").get<std::string>(), value.at("api").get<std::string>(), value.at("lavapipe").get<bool>()};
}

} // namespace

std::optional<InputFacts> rememberedFacts(cache::ContentStore& store, const EnvironmentInput& input) {
    if (input.files.empty()) return std::nullopt;
    return parsed(store.peek(factsKey(input)), factsFromJson);
}

void rememberFacts(cache::ContentStore& store, const EnvironmentInput& input) {
    if (input.files.empty()) return;
    const auto facts = factsOf(input);
    putQuietly(store, factsKey(input),
               json({{"panorama_width", facts.panoramaWidth}, {"panorama_height", facts.panoramaHeight},
                     {"cube_size", facts.cubeSize}, {"sanitized_texels", facts.sanitizedTexels},
                     {"negative_texels", facts.negative.count}, {"most_negative", facts.negative.mostNegative}})
                   .dump());
}

std::optional<vulkan::DeviceInfo> rememberedDevice(cache::ContentStore& store, const vulkan::ContextOptions& options) {
    return parsed(store.peek(deviceKey(options)), deviceFromJson);
}

void rememberDevice(cache::ContentStore& store, const vulkan::ContextOptions& options, const vulkan::DeviceInfo& device) {
    putQuietly(store, deviceKey(options),
               json({{"index", device.index}, {"name", device.name}, {"type", device.type}, {"driver", device.driver},
                     {"api", device.apiVersion}, {"lavapipe", device.isLavapipe}})
                   .dump());
}

bool sameIdentity(const vulkan::DeviceInfo& a, const vulkan::DeviceInfo& b) {
    return a.name == b.name && a.driver == b.driver && a.apiVersion == b.apiVersion;
}

} // namespace iblkit::bake
