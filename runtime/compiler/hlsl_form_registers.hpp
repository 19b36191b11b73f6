#pragma once

#include "reflection.hpp"

#include <cstdint>
#include <map>
#include <string>

namespace iblkit::compiler {

// A register of the HLSL form: its class letter comes from the resource's kind.
struct HlslFormRegister {
    uint32_t space = 0;
    uint32_t index = 0;
};

// The register each resource takes in the HLSL form, by name. A resource with a register keeps
// it. One bound by [[vk::binding(b, s)]] has none, so it takes space s and the lowest free
// registers of its class there (an array of N takes N, as in D3D), in reflection order, after
// every written register: two such resources never share a register.
std::map<std::string, HlslFormRegister> hlslFormRegisters(const ShaderReflection& reflection);

} // namespace iblkit::compiler
