#pragma once

#include "register_binding.hpp"

#include <glslang/MachineIndependent/iomapper.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::compiler {

// Plugs the kit's register rule (register_binding.hpp) into glslang's I/O mapper: glslang
// notifies every resource first (collected here with its declaration order), then asks for
// each one's set and binding.
class HlslRegisterResolver : public glslang::TDefaultIoResolverBase {
public:
    HlslRegisterResolver(const glslang::TIntermediate& intermediate, BindingShifts shifts,
                         std::map<std::string, ExplicitBinding> vulkanBindings, std::string sourceName);

    bool validateBinding(EShLanguage stage, glslang::TVarEntryInfo& entry) override;
    glslang::TResourceType getResourceType(const glslang::TType& type) override;
    void notifyBinding(EShLanguage stage, glslang::TVarEntryInfo& entry) override;
    void endNotifications(EShLanguage stage) override;
    int resolveBinding(EShLanguage stage, glslang::TVarEntryInfo& entry) override;
    int resolveSet(EShLanguage stage, glslang::TVarEntryInfo& entry) override;

    const std::vector<ResourceRegister>& registers() const { return registers_; }
    const BindingShifts& shifts() const { return shifts_; }
    // Set when the registers could not be assigned; glslang must not see an exception.
    const std::optional<std::string>& error() const { return error_; }

private:
    const ResourceRegister* find(const glslang::TVarEntryInfo& entry) const;

    BindingShifts shifts_; // grown to fit when they are the defaults (grownToFit)
    std::map<std::string, ExplicitBinding> vulkanBindings_; // by HLSL name
    std::string sourceName_;
    std::map<long long, DeclaredResource> declared_; // by symbol id: declaration order
    std::vector<ResourceRegister> registers_;
    std::optional<std::string> error_;
};

} // namespace iblkit::compiler
