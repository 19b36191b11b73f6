#include "reflection.hpp"

#include "compile_error.hpp"
#include "image_formats.hpp"

#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>
#include <optional>
#include <tuple>

namespace iblkit::compiler {
namespace {

using spirv_cross::SPIRType;

std::string scalarName(const SPIRType& type) {
    switch (type.basetype) {
    case SPIRType::Boolean: return "bool";
    case SPIRType::Int: return "int";
    case SPIRType::UInt: return "uint";
    case SPIRType::Half: return "half";
    case SPIRType::Float: return "float";
    case SPIRType::Double: return "double";
    case SPIRType::Int64: return "int64_t";
    case SPIRType::UInt64: return "uint64_t";
    case SPIRType::Short: return "int16_t";
    case SPIRType::UShort: return "uint16_t";
    default: return "unknown";
    }
}

std::string hlslTypeName(const spirv_cross::Compiler& compiler, const SPIRType& type) {
    std::string name;
    if (type.basetype == SPIRType::Struct) {
        name = compiler.get_name(type.self);
    } else {
        name = scalarName(type);
        if (type.columns > 1) name += std::to_string(type.columns) + "x" + std::to_string(type.vecsize);
        else if (type.vecsize > 1) name += std::to_string(type.vecsize);
    }
    // SPIR-V lists array sizes innermost first.
    for (size_t i = type.array.size(); i-- > 0;) name += "[" + std::to_string(type.array[i]) + "]";
    return name;
}

std::vector<BlockMember> membersOf(const spirv_cross::Compiler& compiler, const SPIRType& block) {
    std::vector<BlockMember> members;
    for (uint32_t i = 0; i < block.member_types.size(); ++i) {
        const auto& memberType = compiler.get_type(block.member_types[i]);
        members.push_back({compiler.get_member_name(block.self, i), hlslTypeName(compiler, memberType),
                           compiler.type_struct_member_offset(block, i),
                           static_cast<uint32_t>(compiler.get_declared_struct_member_size(block, i))});
    }
    return members;
}

std::string dimensionName(const SPIRType::ImageType& image) {
    std::string name;
    switch (image.dim) {
    case spv::Dim1D: name = "1d"; break;
    case spv::Dim2D: name = "2d"; break;
    case spv::Dim3D: name = "3d"; break;
    case spv::DimCube: name = "cube"; break;
    case spv::DimBuffer: name = "buffer"; break;
    default: name = "other"; break;
    }
    return image.arrayed ? name + "_array" : name;
}

struct Reflector {
    const spirv_cross::Compiler& compiler;
    const std::vector<ResourceRegister>& registers;
    ShaderReflection& out;

    const ResourceRegister& registerOf(const std::string& name) const {
        for (const auto& assigned : registers)
            if (assigned.name == name) return assigned;
        throw CompileError("error: internal: no register was assigned to resource '" + name + "'");
    }

    ReflectedResource& add(const spirv_cross::Resource& resource, ResourceKind kind) {
        out.resources.push_back({resource.name, kind, registerOf(resource.name), {}, {}, {}, {}, false, 0, {}});
        return out.resources.back();
    }

    void addBuffer(const spirv_cross::Resource& resource, ResourceKind kind) {
        auto& reflected = add(resource, kind);
        const auto& type = compiler.get_type(resource.base_type_id);
        reflected.blockSize = static_cast<uint32_t>(compiler.get_declared_struct_size(type));
        reflected.members = membersOf(compiler, type);
        reflected.readOnly = kind == ResourceKind::StorageBuffer &&
                             compiler.get_buffer_block_flags(resource.id).get(spv::DecorationNonWritable);
    }

    void addImage(const spirv_cross::Resource& resource, bool storage) {
        const auto& type = compiler.get_type(resource.type_id);
        const bool buffer = type.image.dim == spv::DimBuffer;
        const ResourceKind kind = storage ? (buffer ? ResourceKind::StorageTexelBuffer : ResourceKind::StorageImage)
                                          : (buffer ? ResourceKind::TexelBuffer : ResourceKind::Texture);
        auto& reflected = add(resource, kind);
        reflected.dimension = dimensionName(type.image);
        const auto* format = findImageFormat(type.image.format);
        reflected.format = format ? std::string(format->glslName) : "unknown";
        reflected.vulkanFormat = format ? std::string(format->vulkanName) : "";
        reflected.componentType = scalarName(compiler.get_type(type.image.type));
    }
};

uint32_t registerOrder(const ReflectedResource& resource) {
    return static_cast<uint32_t>(resource.location.registerClass);
}

} // namespace

std::string_view resourceKindName(ResourceKind kind) {
    switch (kind) {
    case ResourceKind::ConstantBuffer: return "cbuffer";
    case ResourceKind::Texture: return "texture";
    case ResourceKind::Sampler: return "sampler";
    case ResourceKind::StorageImage: return "storage_image";
    case ResourceKind::StorageBuffer: return "buffer";
    case ResourceKind::TexelBuffer: return "texel_buffer";
    case ResourceKind::StorageTexelBuffer: return "storage_texel_buffer";
    }
    return "unknown";
}

const ReflectedResource* ShaderReflection::find(const std::string& name) const {
    for (const auto& resource : resources)
        if (resource.name == name) return &resource;
    return nullptr;
}

ShaderReflection reflectShader(const std::vector<uint32_t>& spirv, const std::vector<ResourceRegister>& registers,
                               const std::string& entryPoint, ShaderStage stage) {
    spirv_cross::Compiler compiler(spirv);
    // A module may hold several entry points: reflect the one asked for (its resources, its
    // workgroup size).
    for (const auto& entry : compiler.get_entry_points_and_stages())
        if (entry.name == entryPoint) compiler.set_entry_point(entry.name, entry.execution_model);
    ShaderReflection out;
    out.entryPoint = entryPoint;
    out.stage = stage;
    Reflector reflector{compiler, registers, out};
    const auto resources = compiler.get_shader_resources(compiler.get_active_interface_variables());
    for (const auto& resource : resources.uniform_buffers) reflector.addBuffer(resource, ResourceKind::ConstantBuffer);
    for (const auto& resource : resources.storage_buffers) reflector.addBuffer(resource, ResourceKind::StorageBuffer);
    for (const auto& resource : resources.separate_images) reflector.addImage(resource, false);
    for (const auto& resource : resources.storage_images) reflector.addImage(resource, true);
    for (const auto& resource : resources.separate_samplers) reflector.add(resource, ResourceKind::Sampler);
    std::sort(out.resources.begin(), out.resources.end(), [](const auto& a, const auto& b) {
        return std::tuple(registerOrder(a), a.location.space, a.location.registerIndex) <
               std::tuple(registerOrder(b), b.location.space, b.location.registerIndex);
    });

    for (const auto& block : resources.push_constant_buffers) {
        const auto& type = compiler.get_type(block.base_type_id);
        // A `[[vk::push_constant]] cbuffer` is anonymous: its name is the block type's.
        out.pushConstantBlock = block.name.empty() ? compiler.get_name(block.base_type_id) : block.name;
        out.pushConstantSize = static_cast<uint32_t>(compiler.get_declared_struct_size(type));
        out.pushConstants = membersOf(compiler, type);
    }
    for (const auto& constant : compiler.get_specialization_constants()) {
        const auto& value = compiler.get_constant(constant.id);
        const auto& type = compiler.get_type(value.constant_type);
        const double defaultValue = type.basetype == SPIRType::Float ? value.scalar_f32()
                                    : type.basetype == SPIRType::Int ? value.scalar_i32()
                                                                     : value.scalar();
        out.specializationConstants.push_back(
            {compiler.get_name(constant.id), constant.constant_id, hlslTypeName(compiler, type), defaultValue});
    }
    if (stage == ShaderStage::Compute) {
        const auto& modes = compiler.get_execution_mode_bitset();
        out.workgroupSizeFixed = modes.get(spv::ExecutionModeLocalSize);
        if (out.workgroupSizeFixed)
            for (uint32_t axis = 0; axis < 3; ++axis)
                out.workgroupSize[axis] = compiler.get_execution_mode_argument(spv::ExecutionModeLocalSize, axis);
    }
    return out;
}

ShaderReflection reflectSpirv(const std::vector<uint32_t>& spirv, const std::string& entryPoint,
                              const std::string& sourceName) {
    std::optional<ShaderStage> stage;
    std::vector<ResourceRegister> registers;
    try {
        spirv_cross::Compiler compiler(spirv);
        for (const auto& entry : compiler.get_entry_points_and_stages())
            if (entry.name == entryPoint) {
                compiler.set_entry_point(entry.name, entry.execution_model);
                if (entry.execution_model == spv::ExecutionModelGLCompute) stage = ShaderStage::Compute;
                else if (entry.execution_model == spv::ExecutionModelVertex) stage = ShaderStage::Vertex;
                else if (entry.execution_model == spv::ExecutionModelFragment) stage = ShaderStage::Fragment;
            }
        if (!stage) throw CompileError(sourceName + ": error: no compute, vertex or fragment entry point '" + entryPoint + "'");
        const auto resources = compiler.get_shader_resources(compiler.get_active_interface_variables());
        const auto add = [&](const auto& list, RegisterClass registerClass) {
            for (const auto& resource : list) {
                const uint32_t set = compiler.get_decoration(resource.id, spv::DecorationDescriptorSet);
                const uint32_t binding = compiler.get_decoration(resource.id, spv::DecorationBinding);
                registers.push_back({resource.name, registerClass, binding, 1, set, true, set, binding});
            }
        };
        add(resources.uniform_buffers, RegisterClass::ConstantBuffer);
        add(resources.storage_buffers, RegisterClass::UnorderedAccess);
        add(resources.separate_images, RegisterClass::ShaderResource);
        add(resources.storage_images, RegisterClass::UnorderedAccess);
        add(resources.separate_samplers, RegisterClass::Sampler);
    } catch (const spirv_cross::CompilerError& error) {
        throw CompileError(sourceName + ": error: not a SPIR-V module iblkit can read: " + error.what());
    }
    return reflectShader(spirv, registers, entryPoint, *stage);
}

} // namespace iblkit::compiler
