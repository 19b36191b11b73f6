#include "spirv_image_format.hpp"

#include "compile_error.hpp"
#include "image_formats.hpp"
#include "spirv_module.hpp"

#include <spirv/unified1/spirv.hpp>


namespace iblkit::compiler {
namespace {

enum class Component { Float, Int, Uint };

Component componentOfFormat(std::string_view name) {
    if (name.ends_with("ui")) return Component::Uint;
    if (name.ends_with("i")) return Component::Int;
    return Component::Float;
}

const char* componentName(Component component) {
    return component == Component::Float ? "float" : component == Component::Int ? "int" : "uint";
}

class FormatApplier {
public:
    FormatApplier(SpirvModule& module, std::string sourceName) : module_(module), sourceName_(std::move(sourceName)) {}

    void apply(const std::string& name, const std::string& formatName) {
        const auto* format = findImageFormatByGlslName(formatName);
        if (!format) fail("unknown image format '" + formatName + "' (known: " + knownFormats() + ")");
        const uint32_t variable = storageImageVariable(name);
        const uint32_t imageType = imageTypeOf(variable);
        check(name, imageType, formatName);
        auto* image = module_.definition(imageType);
        if (image->operands[kImageFormat] == format->spirvFormat) return;
        retarget(variable, imageType, format->spirvFormat);
        if (format->esslStandIn != format->glslName) module_.requireCapability(spv::CapabilityStorageImageExtendedFormats);
    }

private:
    [[noreturn]] void fail(const std::string& message) const { throw CompileError(sourceName_ + ": error: " + message); }

    static std::string knownFormats() {
        std::string names;
        for (unsigned format = 0; format < 64; ++format)
            if (const auto* info = findImageFormat(format)) names += (names.empty() ? "" : ", ") + std::string(info->glslName);
        return names;
    }

    uint32_t storageImageVariable(const std::string& name) const {
        for (uint32_t id : module_.idsNamed(name)) {
            const auto* variable = module_.definition(id);
            if (!variable || variable->opcode != spv::OpVariable) continue;
            if (module_.storageImageTypeOf(id)) return id;
            fail("--image-format names '" + name + "', which is not a storage image (RWTexture*)");
        }
        fail("--image-format names '" + name + "', which the entry point does not use as a storage image");
    }

    uint32_t imageTypeOf(uint32_t variable) const {
        return module_.pointeeOf(module_.definition(variable)->operands[0]);
    }

    // The component type must match; the channel counts need not: a write narrower than the
    // format is widened later (spirv_texel_widening.hpp), a wider one's extra channels dropped.
    void check(const std::string& name, uint32_t imageType, const std::string& formatName) const {
        const auto* sampled = module_.definition(module_.definition(imageType)->operands[kImageSampledType]);
        const Component component = sampled->opcode == spv::OpTypeFloat ? Component::Float
                                    : sampled->operands[2] ? Component::Int
                                                           : Component::Uint;
        if (component != componentOfFormat(formatName))
            fail("image format " + formatName + " of '" + name + "' does not match the component type of its element (" +
                 componentName(component) + ")");
    }

    // Gives the variable an image type of the wanted format: its own type changed in place when
    // nothing else uses it, else an identical type already declared, else a new one (SPIR-V
    // forbids two identical declarations).
    void retarget(uint32_t variable, uint32_t imageType, uint32_t spirvFormat) {
        const uint32_t pointerType = module_.definition(variable)->operands[0];
        SpirvInstruction wanted = *module_.definition(imageType);
        wanted.operands[kImageFormat] = spirvFormat;
        uint32_t target = module_.findTypeLike(wanted);
        const size_t ownUses = 1 + module_.loadsOf(variable).size(); // its pointer type and its loads
        const bool owned = module_.usesOf(imageType) == ownUses && module_.usesOf(pointerType) == 1;
        if (!target && owned) {
            module_.definition(imageType)->operands[kImageFormat] = spirvFormat;
            return;
        }
        if (!target) {
            target = module_.cloneTypeAfter(imageType, pointerType);
            module_.definition(target)->operands[kImageFormat] = spirvFormat;
        }
        uint32_t pointer = module_.findUniformConstantPointer(target);
        if (!pointer) {
            pointer = module_.cloneTypeAfter(pointerType, target);
            module_.definition(pointer)->operands[2] = target;
        }
        module_.retypeVariable(variable, pointer, imageType, target);
    }

    SpirvModule& module_;
    std::string sourceName_;
};

} // namespace

void applyImageFormats(SpirvModule& module, const std::map<std::string, std::string>& formats,
                       const std::string& sourceName) {
    FormatApplier applier(module, sourceName);
    for (const auto& [name, format] : formats) applier.apply(name, format);
}

} // namespace iblkit::compiler
