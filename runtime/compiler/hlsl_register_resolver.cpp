#include "hlsl_register_resolver.hpp"

#include "compile_error.hpp"

namespace iblkit::compiler {
namespace {

std::optional<RegisterClass> registerClassOf(const glslang::TType& type) {
    const auto& qualifier = type.getQualifier();
    if (qualifier.isPushConstant()) return std::nullopt;
    if (type.getBasicType() == glslang::EbtSampler) {
        const auto& sampler = type.getSampler();
        if (sampler.isPureSampler()) return RegisterClass::Sampler;
        if (sampler.isImage()) return qualifier.isReadOnly() ? RegisterClass::ShaderResource : RegisterClass::UnorderedAccess;
        return RegisterClass::ShaderResource;
    }
    if (qualifier.storage == glslang::EvqBuffer)
        return qualifier.isReadOnly() ? RegisterClass::ShaderResource : RegisterClass::UnorderedAccess;
    if (qualifier.storage == glslang::EvqUniform) return RegisterClass::ConstantBuffer;
    return std::nullopt;
}

uint32_t registerCount(const glslang::TType& type) {
    if (!type.isArray() || type.getBasicType() == glslang::EbtBlock) return 1;
    return type.isSizedArray() ? static_cast<uint32_t>(type.getCumulativeArraySize()) : 1;
}

// cbuffers are blocks whose variable is anonymous: the HLSL name is the block's.
std::string hlslNameOf(const glslang::TIntermSymbol& symbol) {
    const auto& type = symbol.getType();
    if (type.getBasicType() == glslang::EbtBlock && type.getTypeName().size() > 0)
        return type.getTypeName().c_str();
    return symbol.getName().c_str();
}

} // namespace

HlslRegisterResolver::HlslRegisterResolver(const glslang::TIntermediate& intermediate, BindingShifts shifts,
                                           std::map<std::string, ExplicitBinding> vulkanBindings, std::string sourceName)
    : TDefaultIoResolverBase(intermediate), shifts_(shifts), vulkanBindings_(std::move(vulkanBindings)),
      sourceName_(std::move(sourceName)) {}

bool HlslRegisterResolver::validateBinding(EShLanguage, glslang::TVarEntryInfo&) { return true; }

glslang::TResourceType HlslRegisterResolver::getResourceType(const glslang::TType& type) {
    switch (registerClassOf(type).value_or(RegisterClass::ConstantBuffer)) {
    case RegisterClass::ConstantBuffer: return glslang::EResUbo;
    case RegisterClass::ShaderResource: return glslang::EResTexture;
    case RegisterClass::Sampler: return glslang::EResSampler;
    case RegisterClass::UnorderedAccess: return glslang::EResUav;
    }
    return glslang::EResCount;
}

void HlslRegisterResolver::notifyBinding(EShLanguage, glslang::TVarEntryInfo& entry) {
    const auto& type = entry.symbol->getType();
    const auto registerClass = registerClassOf(type);
    if (!registerClass || !entry.live) return;
    const auto& qualifier = type.getQualifier();
    DeclaredResource resource{hlslNameOf(*entry.symbol), *registerClass, std::nullopt,
                              qualifier.hasSet() ? static_cast<uint32_t>(qualifier.layoutSet) : 0u,
                              registerCount(type)};
    // glslang keeps [[vk::binding]] in the same place as a register: the attribute is told apart by name.
    if (const auto vulkan = vulkanBindings_.find(resource.name); vulkan != vulkanBindings_.end()) resource.vulkanBinding = vulkan->second;
    else if (qualifier.hasBinding()) resource.explicitRegister = static_cast<uint32_t>(qualifier.layoutBinding);
    declared_.emplace(entry.id, std::move(resource));
}

void HlslRegisterResolver::endNotifications(EShLanguage) {
    std::vector<DeclaredResource> inDeclarationOrder;
    for (const auto& [id, resource] : declared_) inDeclarationOrder.push_back(resource);
    try {
        shifts_ = grownToFit(inDeclarationOrder, shifts_);
        registers_ = assignRegisters(inDeclarationOrder, shifts_, sourceName_);
    } catch (const CompileError& error) {
        error_ = error.what();
    }
}

const ResourceRegister* HlslRegisterResolver::find(const glslang::TVarEntryInfo& entry) const {
    const auto name = hlslNameOf(*entry.symbol);
    for (const auto& assigned : registers_)
        if (assigned.name == name) return &assigned;
    return nullptr;
}

int HlslRegisterResolver::resolveBinding(EShLanguage, glslang::TVarEntryInfo& entry) {
    const auto* assigned = find(entry);
    return entry.newBinding = assigned ? static_cast<int>(assigned->binding) : -1;
}

int HlslRegisterResolver::resolveSet(EShLanguage, glslang::TVarEntryInfo& entry) {
    const auto* assigned = find(entry);
    return entry.newSet = assigned ? static_cast<int>(assigned->set) : -1;
}

} // namespace iblkit::compiler
