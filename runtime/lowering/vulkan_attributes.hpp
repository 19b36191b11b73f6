#pragma once

#include "hlsl_tokens.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace iblkit::lowering {

struct VulkanBinding {
    uint32_t binding = 0;
    uint32_t set = 0;
    SourcePlace place;
};

// What the `[[vk::...]]` attributes of a shader ask of the kit, by resource name.
struct VulkanAttributes {
    std::map<std::string, VulkanBinding> bindings;     // [[vk::binding(b, s)]]: wins over the register rule
    std::map<std::string, std::string> imageFormats;   // [[vk::image_format("rgba8")]], as written
    std::vector<std::string> warnings;                 // attributes the kit does not honour
    bool pushConstantStructs = false;                  // a `[[vk::push_constant]] S pc;` became a ConstantBuffer<S>
};

// Reads every [[vk::...]] attribute and the declaration it stands before. glslang honours
// binding, location, constant_id and push_constant on a constant buffer itself; the kit
// honours image_format (dropped here, as glslang does not know it) and push_constant on a
// plain struct variable (`[[vk::push_constant]] S pc;` becomes `ConstantBuffer<S> pc;`).
std::vector<Token> readVulkanAttributes(const std::vector<Token>& tokens, VulkanAttributes& attributes);

} // namespace iblkit::lowering
