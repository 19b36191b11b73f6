#pragma once

#include "register_binding.hpp"
#include "shader_stage.hpp"
#include "spirv_varyings.hpp"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace iblkit::compiler {

enum class ResourceKind { ConstantBuffer, Texture, Sampler, StorageImage, StorageBuffer, TexelBuffer, StorageTexelBuffer };
std::string_view resourceKindName(ResourceKind kind);

struct BlockMember {
    std::string name;
    std::string type; // HLSL spelling: "float", "float4x4", "uint2[4]"
    uint32_t offset;
    uint32_t size;
};

struct ReflectedResource {
    std::string name; // as declared in HLSL (a cbuffer's block name)
    ResourceKind kind;
    ResourceRegister location;
    std::string dimension;   // images: "1d", "2d", "3d", "cube", "buffer", with "_array" when arrayed
    std::string format;      // storage images: "rg16f"; "unknown" when unstated
    std::string vulkanFormat; // "R16G16_SFLOAT"; empty when unknown
    std::string componentType; // images and texel buffers: "float", "int" or "uint"
    bool readOnly = false;   // storage buffers: a StructuredBuffer rather than RWStructuredBuffer
    uint32_t blockSize = 0;  // buffers: the declared size in bytes
    std::vector<BlockMember> members;
};

struct SpecializationConstant {
    std::string name;
    uint32_t constantId;
    std::string type;
    double defaultValue;
};

struct ShaderReflection {
    std::string entryPoint;
    ShaderStage stage;
    std::array<uint32_t, 3> workgroupSize{0, 0, 0};
    bool workgroupSizeFixed = false; // a literal [numthreads] (LocalSize), not specialization constants
    std::vector<ReflectedResource> resources; // in register order: b, t, s, u; space; index
    std::string pushConstantBlock;
    uint32_t pushConstantSize = 0;
    std::vector<BlockMember> pushConstants;
    std::vector<SpecializationConstant> specializationConstants;
    // The entry point's inputs and outputs with their semantics (HLSL compiled here; empty for
    // SPIR-V compiled elsewhere, which keeps no semantics).
    std::vector<Varying> varyings;

    const ReflectedResource* find(const std::string& name) const;
};

// Reads the resources from SPIR-V that still has its names, and joins them to the
// registers the frontend assigned.
ShaderReflection reflectShader(const std::vector<uint32_t>& spirv, const std::vector<ResourceRegister>& registers,
                               const std::string& entryPoint, ShaderStage stage);

// The reflection of a SPIR-V module compiled elsewhere: its resources keep the set and binding
// decorations they have, and, no HLSL being at hand, each binding stands for the register.
ShaderReflection reflectSpirv(const std::vector<uint32_t>& spirv, const std::string& entryPoint,
                              const std::string& sourceName);

nlohmann::json toJson(const ShaderReflection& reflection);
// The inverse of toJson. Throws CompileError naming what is missing or malformed.
ShaderReflection reflectionFromJson(const nlohmann::json& object);

} // namespace iblkit::compiler
