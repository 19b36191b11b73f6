#pragma once

#include "environment_input.hpp"
#include "context_options.hpp"

#include <optional>
#include <string>

namespace iblkit::cache {
class ContentStore;
}

namespace iblkit::bake {

// Two small cache entries that let a bake whose maps are all cached skip its two slowest steps.
//
// The input's facts (InputFacts), kept by its files' hashes and the input policy: with them the
// files are hashed but not decoded (about 60 ms of a cached bake of a 1024x512 EXR).
std::optional<InputFacts> rememberedFacts(cache::ContentStore& store, const EnvironmentInput& input);
void rememberFacts(cache::ContentStore& store, const EnvironmentInput& input);

// The device the last bake with the same device choice ran on. A Vulkan instance takes about
// 0.1 s on lavapipe (its driver loads LLVM): a bake reads its cache entries under the remembered
// device's keys while the real device is found, and uses them only if the two are the same
// (baked_outputs.cpp). A wrong memory costs time, never a wrong entry.
std::optional<vulkan::DeviceInfo> rememberedDevice(cache::ContentStore& store, const vulkan::ContextOptions& options);
void rememberDevice(cache::ContentStore& store, const vulkan::ContextOptions& options, const vulkan::DeviceInfo& device);

// Whether the cache keys of two devices are the same (bake_cache.cpp's commonKey).
bool sameIdentity(const vulkan::DeviceInfo& a, const vulkan::DeviceInfo& b);

} // namespace iblkit::bake
