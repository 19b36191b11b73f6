#pragma once

#include "environment_input.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::bench {

// The file `iblkit bake` reads for a bench environment: an empty path for the built-in sky; none
// for an environment that exists only inside the bench (sun, furnace).
std::optional<std::filesystem::path> bakeInputOf(const std::string& name, const std::filesystem::path& cacheDir);

// An environment the bench measures on: a name for the tables and the input the bake reads.
struct BenchEnvironment {
    std::string name;
    bake::EnvironmentInput input;
};

// The synthetic environments, by name: "sky" (the bake's built-in sky), "furnace" (radiance 1
// everywhere: every method must return exactly 1), "sun" (radiance 1 with one texel of 1e4).
// The eight world HDRIs of Debian's blender-data package (CC0) by their names ("forest", ...),
// or all of them as "blender". Anything else is a path the bake can read.
inline constexpr const char* kBlenderWorlds[] = {"city", "courtyard", "forest", "interior",
                                                 "night", "studio", "sunrise", "sunset"};

// Whether `name` is one of kBlenderWorlds.
bool isBlenderWorld(const std::string& name);

// Resolves names into environments for a cube of `size`. Blender's HDRIs are fetched with
// `apt-get download blender-data` into `cacheDir` the first time they are asked for.
// Throws BenchError (or the bake's errors for a bad file), naming the environment.
std::vector<BenchEnvironment> resolveEnvironments(const std::vector<std::string>& names, uint32_t size,
                                                  const std::filesystem::path& cacheDir);

// Throws BenchError naming `name` unless resolveEnvironments knows it (or it is a file).
void requireEnvironmentName(const std::string& name);

// The folder that holds blender-data's world HDRIs under `cacheDir`, fetched when missing.
std::filesystem::path blenderWorlds(const std::filesystem::path& cacheDir);

} // namespace iblkit::bench
