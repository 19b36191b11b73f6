#include "bench_environments.hpp"

#include "bake.hpp"
#include "bench_error.hpp"
#include "shell_command.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <cstdlib>
#include <unistd.h>

namespace iblkit::bench {
bool isBlenderWorld(const std::string& name) {
    return std::find(std::begin(kBlenderWorlds), std::end(kBlenderWorlds), name) != std::end(kBlenderWorlds);
}

namespace {

namespace fs = std::filesystem;

bake::EnvironmentInput constantCube(uint32_t size, float radiance) {
    bake::EnvironmentInput input;
    input.kind = bake::InputKind::Cube;
    input.cubeSize = size;
    input.cubeTexels.assign(size_t(6) * size * size * 4, radiance);
    for (size_t texel = 0; texel < input.cubeTexels.size() / 4; ++texel) input.cubeTexels[texel * 4 + 3] = 1.f;
    return input;
}

// One texel of 1e4 on a background of 1, away from the faces' centres and edges so that no
// prefiltered texel direction passes exactly through it.
bake::EnvironmentInput sunCube(uint32_t size) {
    auto input = constantCube(size, 1.f);
    const uint32_t face = 4, row = size * 3 / 8, column = size * 5 / 8;
    float* sun = &input.cubeTexels[((size_t(face) * size + row) * size + column) * 4];
    std::fill(sun, sun + 3, 1e4f);
    return input;
}

// A file's name in tables and plot names: its stem in letters, digits, - and _ ("summary" is
// the summary plot's).
std::string tableName(const fs::path& path) {
    std::string name = path.stem().string();
    if (name.empty()) name = path.parent_path().filename().string(); // a folder given as "faces/"
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    return name.empty() || name == "summary" ? "file_" + name : name;
}

BenchEnvironment resolveOne(const std::string& name, uint32_t size, const fs::path& cacheDir) {
    if (name == "sky") return {name, bake::loadEnvironment(std::nullopt, {})};
    if (name == "furnace") return {name, constantCube(size, 1.f)};
    if (name == "sun") return {name, sunCube(size)};
    if (isBlenderWorld(name)) return {name, bake::loadEnvironment(blenderWorlds(cacheDir) / (name + ".exr"), {})};
    requireEnvironmentName(name);
    return {tableName(name), bake::loadEnvironment(fs::path(name), {})};
}

} // namespace

void requireEnvironmentName(const std::string& name) {
    if (name == "sky" || name == "furnace" || name == "sun" || name == "blender" || isBlenderWorld(name) || fs::exists(name))
        return;
    throw BenchError(fmt::format("no environment '{}': not a file, nor sky, furnace, sun, blender or one of "
                                 "blender's worlds (city, courtyard, forest, ...)", name));
}

std::optional<fs::path> bakeInputOf(const std::string& name, const fs::path& cacheDir) {
    if (name == "sky") return fs::path();
    if (isBlenderWorld(name)) return blenderWorlds(cacheDir) / (name + ".exr");
    if (std::error_code error; fs::exists(name, error)) return fs::path(name);
    return std::nullopt;
}

fs::path blenderWorlds(const fs::path& cacheDir) {
    const fs::path worlds = cacheDir / "blender-data" / "world";
    if (fs::exists(worlds / "sunset.exr")) return worlds;
    const fs::path download = cacheDir / fmt::format("blender-data.download.{}", getpid());
    fs::remove_all(download);
    fs::create_directories(download);
    // The download folder goes, whether the fetch succeeds or not.
    const std::unique_ptr<const fs::path, void (*)(const fs::path*)> cleanup(&download, [](const fs::path* folder) {
        std::error_code ignored;
        fs::remove_all(*folder, ignored);
    });
    fmt::print(stderr, "fetching Debian's blender-data package for its world HDRIs into {}\n", cacheDir.string());
    runShell("cd " + shellQuoted(download) + " && apt-get download -q blender-data >&2", "download blender-data");
    const std::string member = "./usr/share/blender/datafiles/studiolights/world";
    runShell("dpkg-deb --fsys-tarfile " + shellQuoted(download) + "/blender-data_*.deb | tar -x -C " + shellQuoted(download) +
                 " " + member,
             "unpack blender-data's world HDRIs");
    fs::create_directories(worlds.parent_path());
    fs::remove_all(worlds);
    fs::rename(download / member, worlds); // whole or not at all
    return worlds;
}

std::vector<BenchEnvironment> resolveEnvironments(const std::vector<std::string>& names, uint32_t size,
                                                  const fs::path& cacheDir) {
    std::vector<BenchEnvironment> environments;
    for (const auto& name : names) {
        if (name == "blender") {
            for (const auto* world : kBlenderWorlds) environments.push_back(resolveOne(world, size, cacheDir));
            continue;
        }
        environments.push_back(resolveOne(name, size, cacheDir));
    }
    return environments;
}

} // namespace iblkit::bench
