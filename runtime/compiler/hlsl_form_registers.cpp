#include "hlsl_form_registers.hpp"

#include <set>
#include <tuple>

namespace iblkit::compiler {

std::map<std::string, HlslFormRegister> hlslFormRegisters(const ShaderReflection& reflection) {
    std::set<std::tuple<RegisterClass, uint32_t, uint32_t>> taken; // class, space, register
    std::map<std::string, HlslFormRegister> registers;
    for (const auto& resource : reflection.resources) {
        const auto& location = resource.location;
        if (location.vulkanBinding) continue;
        registers[resource.name] = {location.space, location.registerIndex};
        for (uint32_t i = 0; i < location.count; ++i)
            taken.emplace(location.registerClass, location.space, location.registerIndex + i);
    }
    for (const auto& resource : reflection.resources) {
        const auto& location = resource.location;
        if (!location.vulkanBinding) continue;
        const auto isFree = [&](uint32_t first) {
            for (uint32_t i = 0; i < location.count; ++i)
                if (taken.contains({location.registerClass, location.set, first + i})) return false;
            return true;
        };
        uint32_t first = 0;
        while (!isFree(first)) ++first;
        for (uint32_t i = 0; i < location.count; ++i) taken.emplace(location.registerClass, location.set, first + i);
        registers[resource.name] = {location.set, first};
    }
    return registers;
}

} // namespace iblkit::compiler
