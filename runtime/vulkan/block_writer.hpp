#pragma once

#include "reflection.hpp"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace iblkit::vulkan {

// The bytes of a cbuffer or push-constant block with the named members set at their
// reflected offsets (zero elsewhere). A value has as many components as the member's type
// (float, float2, ..., uint4, int, ...). Throws VulkanError for an unknown member or a wrong
// component count; matrices and arrays are refused by name.
// One 32-bit scalar ("float", "int", "uint") written at `at`; a value the type cannot hold
// (-1 or 1e20 for a uint, 1.5 for an int, NaN) is a VulkanError naming `where`.
void writeScalar(const std::string& scalar, double value, std::byte* at, const std::string& where);

std::vector<std::byte> packBlock(const std::string& blockName, const std::vector<compiler::BlockMember>& members,
                                 uint32_t size, const std::map<std::string, std::vector<double>>& values);

} // namespace iblkit::vulkan
