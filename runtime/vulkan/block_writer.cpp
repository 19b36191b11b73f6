#include "block_writer.hpp"

#include "vulkan_error.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace iblkit::vulkan {
namespace {

struct MemberType {
    std::string scalar;
    uint32_t components;
};

MemberType parseType(const std::string& block, const compiler::BlockMember& member) {
    const auto fail = [&] {
        throw VulkanError("cannot set " + block + "." + member.name + " of type " + member.type +
                          ": only scalars and vectors of float, int and uint are supported");
    };
    for (const char* scalar : {"float", "uint", "int"}) {
        const std::string prefix = scalar;
        if (member.type.rfind(prefix, 0) != 0) continue;
        const std::string rest = member.type.substr(prefix.size());
        if (rest.empty()) return {prefix, 1};
        if (rest.size() == 1 && rest[0] >= '2' && rest[0] <= '4') return {prefix, static_cast<uint32_t>(rest[0] - '0')};
        fail();
    }
    fail();
    return {};
}

} // namespace

// A value the type cannot hold is refused: casting -1 or 1e20 to a uint is undefined.
void writeScalar(const std::string& scalar, double value, std::byte* at, const std::string& where) {
    const auto refuse = [&](const char* why) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", value);
        throw VulkanError(where + " is a " + scalar + ": " + text + " " + why);
    };
    if (scalar == "float") {
        if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max())) refuse("is beyond float's range");
        const float f = static_cast<float>(value);
        std::memcpy(at, &f, 4);
        return;
    }
    if (value != std::floor(value)) refuse("is not a whole number");
    const bool isInt = scalar == "int";
    const double least = isInt ? double(std::numeric_limits<int32_t>::min()) : 0.0;
    const double most = isInt ? double(std::numeric_limits<int32_t>::max()) : double(std::numeric_limits<uint32_t>::max());
    if (value < least || value > most) refuse(isInt ? "is beyond int's range" : "is beyond uint's range");
    if (isInt) {
        const auto i = static_cast<int32_t>(value);
        std::memcpy(at, &i, 4);
    } else {
        const auto u = static_cast<uint32_t>(value);
        std::memcpy(at, &u, 4);
    }
}


std::vector<std::byte> packBlock(const std::string& blockName, const std::vector<compiler::BlockMember>& members,
                                 uint32_t size, const std::map<std::string, std::vector<double>>& values) {
    std::vector<std::byte> bytes(size);
    for (const auto& [name, components] : values) {
        const auto member = std::find_if(members.begin(), members.end(), [&wanted = name](const auto& m) { return m.name == wanted; });
        if (member == members.end()) {
            std::string known;
            for (const auto& m : members) known += (known.empty() ? "" : ", ") + m.name;
            throw VulkanError(blockName + " has no member '" + name + "' (members: " + known + ")");
        }
        const auto type = parseType(blockName, *member);
        if (components.size() != type.components)
            throw VulkanError(blockName + "." + name + " is a " + member->type + ": it takes " +
                              std::to_string(type.components) + " value(s), not " + std::to_string(components.size()));
        for (uint32_t i = 0; i < type.components; ++i)
            writeScalar(type.scalar, components[i], bytes.data() + member->offset + 4 * i, blockName + "." + name);
    }
    return bytes;
}

} // namespace iblkit::vulkan
