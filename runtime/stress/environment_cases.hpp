#pragma once

#include "suite_environment.hpp"

#include <filesystem>
#include <vector>

namespace iblkit::stress {

// An environment the stress sweep runs every cube kernel on, at a cube size.
struct EnvironmentCase {
    consistency::SuiteEnvironment environment;
    uint32_t size = 16;
};

// Radiance `value` everywhere.
consistency::SuiteEnvironment constantEnvironment(float value);
// Radiance 1 with one texel (at any size) of `value`.
consistency::SuiteEnvironment sunEnvironment(float value);
// An .exr or .hdr panorama as the bake reads it (negative texels clamped), area-averaged onto
// each cube texel and each panorama texel asked for.
consistency::SuiteEnvironment panoramaEnvironment(const std::filesystem::path& path, const std::string& name);

// The cases: black, white, 1e-30, 6e4, suns of 1e3, 1e5 and 1e8, the test environment at 1², 2²
// and 4², and Blender's world HDRIs from `blenderWorlds` unless it is empty. `reduced` keeps
// the test suite's share: no 1e3 or 1e5 sun and no 4².
std::vector<EnvironmentCase> environmentCases(bool reduced, const std::filesystem::path& blenderWorlds);

} // namespace iblkit::stress
