#include "block_writer.hpp"

#include "vulkan_error.hpp"

#include <cstring>

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

void writeComponent(const std::string& scalar, double value, std::byte* at) {
    if (scalar == "float") {
        const float f = static_cast<float>(value);
        std::memcpy(at, &f, 4);
    } else if (scalar == "int") {
        const auto i = static_cast<int32_t>(value);
        std::memcpy(at, &i, 4);
    } else {
        const auto u = static_cast<uint32_t>(value);
        std::memcpy(at, &u, 4);
    }
}

} // namespace

std::vector<std::byte> packBlock(const std::string& blockName, const std::vector<compiler::BlockMember>& members,
                                 uint32_t size, const std::map<std::string, std::vector<double>>& values) {
    std::vector<std::byte> bytes(size);
    for (const auto& [name, components] : values) {
        const auto member = std::find_if(members.begin(), members.end(), [&](const auto& m) { return m.name == name; });
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
            writeComponent(type.scalar, components[i], bytes.data() + member->offset + 4 * i);
    }
    return bytes;
}

} // namespace iblkit::vulkan
