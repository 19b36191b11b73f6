#pragma once

#include "compile_options.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::porting {

// Where a configuration's shaders are built for: Direct3D (DXIL or DXBC) or Vulkan (DXC -spirv).
enum class BuildTarget { D3D11, D3D12, Vulkan };
std::string_view buildTargetName(BuildTarget target); // "d3d11", "d3d12", "vulkan"

// The stage a DXC/fxc profile names, including the ones the kit refuses as whole stages.
enum class ProfileStage { Vertex, Pixel, Compute, Geometry, Hull, Domain, RayTracing, Mesh, Amplification };
std::string_view profileStageName(ProfileStage stage); // "vertex", "pixel", ..., "ray tracing"

// A DXC/fxc target profile, "ps_6_0" or "lib_6_3".
struct ShaderProfile {
    std::string text;
    ProfileStage stage = ProfileStage::Compute;
    int major = 5, minor = 0;
};
// nullopt when `text` is not a profile.
std::optional<ShaderProfile> parseShaderProfile(const std::string& text);

// One shader as a code base's own build compiles it: its file, entry, profile, defines, include
// folders and compiler flags, turned into the kit's compile options. Flags the kit has no use for
// (optimization levels, validation switches) are kept in `ignoredFlags` for the report.
struct CodeBaseConfiguration {
    std::string label; // unique within the code base: "ToneMapping.fx:main:ps_6_0" unless named
    std::string file;  // as the manifest writes it
    std::string entry;
    ShaderProfile profile;
    BuildTarget target = BuildTarget::D3D12;
    compiler::CompileOptions options;
    std::vector<std::string> ignoredFlags;
    // Whole stages the kit refuses (ray tracing, mesh, amplification): counted apart.
    bool refusedStage() const;
};

struct CodeBaseRequirement {
    std::string name, repository, commit;
};

// A code base's manifest (docs/porting-real-code.md): where it comes from and each configuration
// its build compiles.
struct CodeBase {
    std::filesystem::path manifestFile;
    std::filesystem::path root; // where its files are on disk
    std::string name, repository, commit, description;
    std::vector<CodeBaseRequirement> requirements;
    std::vector<CodeBaseConfiguration> configurations;
};

// Whether a folder is the code base itself (--source) or holds code bases in folders of their
// names (--sources).
enum class CodeBaseFolder { IsTheCodeBase, HoldsCodeBasesByName };

// Reads a code base's manifest. Paths are relative to its root (`folder`, or `folder`/NAME); one
// that starts with "@OTHER/" to OTHER's root, the folder named OTHER beside it. Throws
// PortingError naming the file and key.
CodeBase readCodeBaseManifest(const std::filesystem::path& manifestFile, const std::filesystem::path& folder,
                              CodeBaseFolder kind = CodeBaseFolder::IsTheCodeBase);

// A folder and a list of its shaders, one a line: "FILE ENTRY PROFILE [-D NAME[=VALUE]] [-I DIR]
// [flags...]", '#' starting a comment, paths relative to `folder`: a code base without a manifest.
// Throws PortingError naming the list's line.
CodeBase readEntryList(const std::filesystem::path& listFile, const std::filesystem::path& folder);

// DXC's and fxc's flags as the kit takes them: -HV, -enable-16bit-types, -fvk-{b,t,s,u}-shift,
// -Zpr/-Zpc (the default matrix packing). Returns false for a flag that changes nothing the kit
// compiles (an optimization level, -spirv, validation switches). Throws PortingError for a flag
// whose argument is wrong.
bool applyCompilerFlag(const std::string& flag, compiler::CompileOptions& options, const std::string& where);

} // namespace iblkit::porting
