#include "cross_compile.hpp"

#include "compile_error.hpp"
#include "hlsl_form_registers.hpp"
#include "hlsl_matrix_loads.hpp"
#include "image_formats.hpp"
#include "readable_glsl.hpp"
#include "spirv_module.hpp"

#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>
#include <spirv_cross/spirv_msl.hpp>

#include <algorithm>
#include <map>
#include <set>

namespace iblkit::compiler {
namespace {

spv::ExecutionModel executionModelOf(ShaderStage stage) {
    switch (stage) {
    case ShaderStage::Vertex: return spv::ExecutionModelVertex;
    case ShaderStage::TessControl: return spv::ExecutionModelTessellationControl;
    case ShaderStage::TessEvaluation: return spv::ExecutionModelTessellationEvaluation;
    case ShaderStage::Geometry: return spv::ExecutionModelGeometry;
    case ShaderStage::Fragment: return spv::ExecutionModelFragment;
    case ShaderStage::Compute: return spv::ExecutionModelGLCompute;
    }
    return spv::ExecutionModelGLCompute;
}

// Variable ids by the HLSL name reflection uses (the block name for buffers).
std::map<std::string, spirv_cross::VariableID> variablesByName(const spirv_cross::Compiler& compiler) {
    std::map<std::string, spirv_cross::VariableID> ids;
    const auto resources = compiler.get_shader_resources();
    for (const auto* list : {&resources.uniform_buffers, &resources.storage_buffers, &resources.separate_images,
                             &resources.storage_images, &resources.separate_samplers})
        for (const auto& resource : *list) ids[resource.name] = resource.id;
    return ids;
}

// ESSL 3.10 lacks two-channel and 16-bit float storage formats among others: such images are
// declared with a four-channel stand-in of the same component type (docs/bindings.md).
struct StandIn {
    std::string original; // the image's own format
    std::string declared; // the ESSL format declared for it
};

std::map<std::string, StandIn> esslStandIns(std::vector<uint32_t>& spirv, const ShaderReflection& reflection,
                                                const std::string& sourceName) {
    std::map<std::string, StandIn> adaptedFrom;
    for (const auto& resource : reflection.resources) {
        if (resource.kind != ResourceKind::StorageImage && resource.kind != ResourceKind::StorageTexelBuffer) continue;
        if (isEssl310Format(resource.format)) continue;
        const auto* format = findImageFormatByGlslName(resource.format);
        if (!format || format->esslStandIn.empty())
            throw CompileError(sourceName + ": error: ESSL 3.10 cannot declare storage image '" + resource.name +
                               "' of format " + resource.format + ", and no ESSL format can stand in for it");
        const auto* standIn = findImageFormatByGlslName(format->esslStandIn);
        SpirvModule module(spirv);
        module.replaceStorageImageFormat(format->spirvFormat, standIn->spirvFormat);
        spirv = module.words();
        adaptedFrom[resource.name] = {resource.format, std::string(format->esslStandIn)};
    }
    return adaptedFrom;
}

// ESSL 3.10 reads and writes one storage image only in r32f, r32i or r32ui; any other format
// must be readonly or writeonly (decorateStorageImageAccess states which).
void requireEsslImageAccess(const spirv_cross::CompilerGLSL& compiler, const ShaderReflection& reflection,
                            const std::string& sourceName, bool vulkan) {
    const auto ids = variablesByName(compiler);
    for (const auto& resource : reflection.resources) {
        if (resource.kind != ResourceKind::StorageImage || resource.format == "r32f" || resource.format == "r32i" ||
            resource.format == "r32ui")
            continue;
        const auto& decorations = compiler.get_decoration_bitset(ids.at(resource.name));
        if (decorations.get(spv::DecorationNonReadable) || decorations.get(spv::DecorationNonWritable)) continue;
        throw CompileError(sourceName + ": error: " + (vulkan ? "vulkan-essl" : "essl") +
                           " cannot express the shader: storage image '" + resource.name + "' (" + resource.format +
                           ") is both read and written, which ESSL 3.10 allows only in r32f, r32i and r32ui: write the " +
                           (vulkan ? "--vulkan-glsl" : "--glsl or --vulkan-glsl") + " form, or give it one of those formats");
    }
}

// GLSL allows a matrix layout qualifier on a block's members only, so SPIRV-Cross writes a struct
// inside a buffer with one layout for all of its matrices: a struct holding both (an HLSL
// row_major member beside a column-major one) would be read wrongly. Refused by name.
void requireOneMatrixLayoutPerStruct(const std::vector<uint32_t>& spirv, const std::string& sourceName, std::string_view form) {
    const SpirvModule module(spirv);
    std::set<uint32_t> blocks;
    std::map<uint32_t, std::set<uint32_t>> layouts; // struct -> the layouts of its matrix members
    std::map<uint32_t, std::string> names;
    for (size_t i = 0; i < module.size(); ++i) {
        const auto& instruction = module.instruction(i);
        const auto& operands = instruction.operands;
        if (instruction.opcode == spv::OpDecorate && operands.size() > 1 &&
            (operands[1] == spv::DecorationBlock || operands[1] == spv::DecorationBufferBlock))
            blocks.insert(operands[0]);
        else if (instruction.opcode == spv::OpMemberDecorate && operands.size() > 2 &&
                 (operands[2] == spv::DecorationRowMajor || operands[2] == spv::DecorationColMajor))
            layouts[operands[0]].insert(operands[2]);
        else if (instruction.opcode == spv::OpName && operands.size() > 1)
            names[operands[0]] = literalString(operands, 1);
    }
    for (const auto& [type, kinds] : layouts)
        if (kinds.size() > 1 && !blocks.count(type))
            throw CompileError(sourceName + ": error: " + std::string(form) + " cannot express the shader: struct '" + names[type] +
                               "' in a buffer holds row_major and column_major matrices, and GLSL gives a struct's "
                               "matrices one layout: declare them all alike (or write the msl or hlsl form)");
}

CrossCompiled toOpenGl(std::vector<uint32_t> spirv, const ShaderReflection& reflection, bool es,
                       const std::string& sourceName) {
    requireOneMatrixLayoutPerStruct(spirv, sourceName, es ? "essl" : "glsl");
    const auto adaptedFrom = es ? esslStandIns(spirv, reflection, sourceName) : std::map<std::string, StandIn>{};
    spirv_cross::CompilerGLSL compiler(std::move(spirv));
    if (es) requireEsslImageAccess(compiler, reflection, sourceName, false);
    auto options = compiler.get_common_options();
    options.version = es ? 310 : 450;
    options.es = es;
    options.vulkan_semantics = false;
    compiler.set_common_options(options);

    CrossCompiled out;
    const auto ids = variablesByName(compiler);
    std::map<std::string, uint32_t> next;
    for (const auto& resource : reflection.resources) {
        std::string space;
        std::string format;
        switch (resource.kind) {
        case ResourceKind::ConstantBuffer: space = "uniform_block"; break;
        case ResourceKind::StorageBuffer: space = "storage_buffer"; break;
        case ResourceKind::StorageImage:
        case ResourceKind::StorageTexelBuffer:
            space = "image_unit";
            format = adaptedFrom.count(resource.name) ? adaptedFrom.at(resource.name).declared : resource.format;
            break;
        default: continue; // textures and samplers become combined samplers below
        }
        const auto id = ids.at(resource.name);
        compiler.unset_decoration(id, spv::DecorationDescriptorSet);
        compiler.set_decoration(id, spv::DecorationBinding, next[space]);
        const auto adapted = adaptedFrom.find(resource.name);
        out.bindings.push_back({resource.name, space, next[space]++, "", format,
                                adapted == adaptedFrom.end() ? "" : adapted->second.original});
    }

    // OpenGL has no push constants: SPIRV-Cross writes the block as a uniform struct, which
    // SPIR-V for OpenGL (ARB_gl_spirv) accepts only with a location. Its members take the
    // locations from 0 on.
    for (const auto& pushConstants : compiler.get_shader_resources().push_constant_buffers) {
        compiler.set_decoration(pushConstants.id, spv::DecorationLocation, 0);
        out.bindings.push_back({reflection.pushConstantBlock, "uniform_location", 0, "", "", ""});
    }

    const spirv_cross::VariableID dummySampler = compiler.build_dummy_sampler_for_combined_images();
    compiler.build_combined_image_samplers();
    auto combined = compiler.get_combined_image_samplers();
    const auto registerOf = [&](spirv_cross::VariableID id) -> std::tuple<uint32_t, uint32_t, uint32_t> {
        const auto* resource = reflection.find(compiler.get_name(id));
        if (!resource) return {~0u, 0, 0};
        return {resource->location.space, resource->location.registerIndex, 0};
    };
    std::sort(combined.begin(), combined.end(), [&](const auto& a, const auto& b) {
        return std::tuple(registerOf(a.image_id), registerOf(a.sampler_id)) <
               std::tuple(registerOf(b.image_id), registerOf(b.sampler_id));
    });
    for (const auto& pair : combined) {
        const std::string texture = compiler.get_name(pair.image_id);
        const bool withSampler = pair.sampler_id != dummySampler;
        const std::string sampler = withSampler ? compiler.get_name(pair.sampler_id) : "";
        const std::string declared = withSampler ? texture + "_" + sampler : texture;
        compiler.set_name(pair.combined_id, declared);
        compiler.unset_decoration(pair.combined_id, spv::DecorationDescriptorSet);
        compiler.set_decoration(pair.combined_id, spv::DecorationBinding, next["texture_unit"]);
        out.bindings.push_back(
            {withSampler ? texture + "+" + sampler : texture, "texture_unit", next["texture_unit"]++, declared, "", ""});
    }
    auto readable = readableGlsl(compiler, reflection.stage, es, false, es ? "essl" : "glsl", sourceName);
    out.source = std::move(readable.source);
    out.version = readable.version;
    out.extensions = std::move(readable.extensions);
    return out;
}

bool declaresAny(const spirv_cross::Compiler& compiler, spv::Capability first, spv::Capability last) {
    const auto& capabilities = compiler.get_declared_capabilities();
    return std::any_of(capabilities.begin(), capabilities.end(),
                       [&](spv::Capability capability) { return capability >= first && capability <= last; });
}

bool declares(const spirv_cross::Compiler& compiler, spv::Capability capability) {
    return declaresAny(compiler, capability, capability);
}

bool usesWaveOperations(const spirv_cross::Compiler& compiler) {
    return declaresAny(compiler, spv::CapabilityGroupNonUniform, spv::CapabilityGroupNonUniformQuad);
}

bool usesSixteenBitTypes(const spirv_cross::Compiler& compiler) {
    return declares(compiler, spv::CapabilityFloat16) || declares(compiler, spv::CapabilityInt16);
}

// The lowest shader model that has what the module uses: 16-bit types need 6.2, SV_ViewID 6.1,
// wave operations and 64-bit integers 6.0, register spaces and bindless resources 5.1.
uint32_t lowestShaderModel(const spirv_cross::Compiler& compiler, bool usesSpaces) {
    if (usesSixteenBitTypes(compiler)) return 62;
    if (declares(compiler, spv::CapabilityMultiView)) return 61;
    if (usesWaveOperations(compiler) || declares(compiler, spv::CapabilityInt64)) return 60;
    // NonUniformResourceIndex and unbounded arrays of resources are 5.1's.
    const bool bindless = declares(compiler, spv::CapabilityShaderNonUniform) || declares(compiler, spv::CapabilityRuntimeDescriptorArray);
    return usesSpaces || bindless ? 51 : 50;
}

CrossCompiled toVulkanGlsl(std::vector<uint32_t> spirv, const ShaderReflection& reflection, bool es,
                           const std::string& sourceName) {
    requireOneMatrixLayoutPerStruct(spirv, sourceName, es ? "vulkan-essl" : "vulkan-glsl");
    const auto adaptedFrom = es ? esslStandIns(spirv, reflection, sourceName) : std::map<std::string, StandIn>{};
    spirv_cross::CompilerGLSL compiler(std::move(spirv));
    if (es) requireEsslImageAccess(compiler, reflection, sourceName, true);
    auto options = compiler.get_common_options();
    options.version = es ? 310 : 450;
    options.es = es;
    options.vulkan_semantics = true;
    compiler.set_common_options(options);
    CrossCompiled out;
    for (const auto& resource : reflection.resources) {
        const auto adapted = adaptedFrom.find(resource.name);
        const bool standsIn = adapted != adaptedFrom.end();
        out.bindings.push_back({resource.name, "set" + std::to_string(resource.location.set), resource.location.binding, "",
                                standsIn ? adapted->second.declared : "", standsIn ? adapted->second.original : ""});
    }
    auto readable = readableGlsl(compiler, reflection.stage, es, true, es ? "vulkan-essl" : "vulkan-glsl", sourceName);
    out.source = std::move(readable.source);
    out.version = readable.version;
    out.extensions = std::move(readable.extensions);
    return out;
}

CrossCompiled toMsl(const std::vector<uint32_t>& spirv, const ShaderReflection& reflection) {
    spirv_cross::CompilerMSL compiler(spirv);
    auto options = compiler.get_msl_options();
    // 64-bit integers and SIMD-group functions in fragment shaders came with MSL 2.2; everything
    // else the kit's shaders use is in 2.1.
    const bool fragmentWaves = reflection.stage == ShaderStage::Fragment && usesWaveOperations(compiler);
    options.set_msl_version(2, declares(compiler, spv::CapabilityInt64) || fragmentWaves ? 2 : 1);
    compiler.set_msl_options(options);

    CrossCompiled out;
    uint32_t buffer = 0, texture = 0, sampler = 0;
    for (const auto& resource : reflection.resources) {
        spirv_cross::MSLResourceBinding binding;
        binding.stage = executionModelOf(reflection.stage);
        binding.desc_set = resource.location.set;
        binding.binding = resource.location.binding;
        binding.count = resource.location.count;
        switch (resource.kind) {
        case ResourceKind::ConstantBuffer:
        case ResourceKind::StorageBuffer:
            out.bindings.push_back({resource.name, "buffer", binding.msl_buffer = buffer++, "", "", ""});
            break;
        case ResourceKind::Sampler:
            out.bindings.push_back({resource.name, "sampler", binding.msl_sampler = sampler++, "", "", ""});
            break;
        default:
            out.bindings.push_back({resource.name, "texture", binding.msl_texture = texture++, "", "", ""});
            break;
        }
        compiler.add_msl_resource_binding(binding);
    }
    out.source = compiler.compile();
    return out;
}

// SPIRV-Cross always names the HLSL entry point `main` (and the function it wraps `<stage>_main`):
// the round trip keeps the entry point's own name, so the host code that names it still works.
std::string withEntryName(std::string source, const std::string& entry) {
    if (entry == "main") return source;
    for (const std::string returned : {"void ", "SPIRV_Cross_Output "}) {
        const std::string wrapper = "\n" + returned + "main(";
        if (const auto at = source.find(wrapper); at != std::string::npos) {
            source.replace(at + 1 + returned.size(), 4, entry);
            return source;
        }
    }
    return source;
}

CrossCompiled toHlsl(const std::vector<uint32_t>& spirv, const ShaderReflection& reflection) {
    spirv_cross::CompilerHLSL compiler(spirv);
    const auto registers = hlslFormRegisters(reflection);
    const bool usesSpaces = std::any_of(registers.begin(), registers.end(),
                                        [](const auto& named) { return named.second.space != 0; });
    auto options = compiler.get_hlsl_options();
    options.shader_model = lowestShaderModel(compiler, usesSpaces);
    options.enable_16bit_types = usesSixteenBitTypes(compiler); // half and int16_t, not min16*
    compiler.set_hlsl_options(options);

    CrossCompiled out;
    for (const auto& resource : reflection.resources) {
        spirv_cross::HLSLResourceBinding binding;
        binding.stage = executionModelOf(reflection.stage);
        binding.desc_set = resource.location.set;
        binding.binding = resource.location.binding;
        const auto& hlslRegister = registers.at(resource.name);
        binding.cbv = binding.srv = binding.uav = binding.sampler = {hlslRegister.space, hlslRegister.index};
        compiler.add_hlsl_resource_binding(binding);
        out.bindings.push_back({resource.name, std::string(1, registerLetter(resource.location.registerClass)),
                                hlslRegister.index, "", "", ""});
    }
    out.source = withEntryName(withFloatMatrixLoads(compiler.compile()), reflection.entryPoint);
    return out;
}

// SPIRV-Cross's reason, with the construct named in HLSL's terms and the form that can
// express it.
std::string explained(CrossTarget target, const std::string& reason) {
    const bool openGl = target == CrossTarget::Glsl || target == CrossTarget::Essl;
    if (openGl && reason.find("only supported in Vulkan semantics") != std::string::npos)
        return "wave operations (Wave*, Quad*) exist in GLSL only with Vulkan semantics (GL_KHR_shader_subgroup): "
               "write that form with --vulkan-" + std::string(crossTargetName(target)) + " FILE (" + reason + ")";
    return reason;
}

} // namespace

std::string_view crossTargetName(CrossTarget target) {
    switch (target) {
    case CrossTarget::Glsl: return "glsl";
    case CrossTarget::Essl: return "essl";
    case CrossTarget::Msl: return "msl";
    case CrossTarget::Hlsl: return "hlsl";
    case CrossTarget::VulkanGlsl: return "vulkan-glsl";
    case CrossTarget::VulkanEssl: return "vulkan-essl";
    }
    return "unknown";
}

CrossCompiled crossCompile(const std::vector<uint32_t>& spirv, const ShaderReflection& reflection, CrossTarget target,
                           const std::string& sourceName) {
    try {
        switch (target) {
        case CrossTarget::Glsl: return toOpenGl(spirv, reflection, false, sourceName);
        case CrossTarget::Essl: return toOpenGl(spirv, reflection, true, sourceName);
        case CrossTarget::Msl: return toMsl(spirv, reflection);
        case CrossTarget::Hlsl: return toHlsl(spirv, reflection);
        case CrossTarget::VulkanGlsl: return toVulkanGlsl(spirv, reflection, false, sourceName);
        case CrossTarget::VulkanEssl: return toVulkanGlsl(spirv, reflection, true, sourceName);
        }
    } catch (const spirv_cross::CompilerError& error) {
        throw CompileError(sourceName + ": error: " + std::string(crossTargetName(target)) +
                           " cannot express the shader: " + explained(target, error.what()));
    }
    return {};
}

} // namespace iblkit::compiler
